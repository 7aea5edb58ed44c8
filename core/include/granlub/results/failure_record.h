// Why a point has no result: results/<solver>/<point>/failure.json, written when a solver fails
// on the point and removed when it later succeeds, so the report can say "failed: <message>"
// instead of just "missing".
//
//   {"format": "granlub-failure-1", "solver", "point", "message", "utc_time", "granlub_version",
//    "kind": "failed" | "no answer"}
// "no answer": the solver's model cannot answer the point's question (error.h, NoAnswer); absent
// in older records, read as "failed".
#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace granlub {

struct FailureRecord {
    std::string solver;
    std::string point;
    std::string message;   // the solver's error message, as printed
    std::string utc_time;  // ISO 8601
    std::string version;   // granlub version
    bool no_answer = false;  // the model has no answer for the point (error.h, NoAnswer), not a failure
};

inline constexpr const char* kFailureFile = "failure.json";

// Writes dir/failure.json atomically (creating dir), with the current UTC time and version.
void write_failure(const std::filesystem::path& dir, const std::string& solver, const std::string& point,
                   const std::string& message, bool no_answer = false);
// Nothing when dir has no failure.json; throws Error naming the file when it cannot be read.
std::optional<FailureRecord> read_failure(const std::filesystem::path& dir);
// Removes dir/failure.json if present (a point that now succeeded has not failed).
void remove_failure(const std::filesystem::path& dir);

}  // namespace granlub
