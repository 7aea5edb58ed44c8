// failure.json: why a point has no result (failure_record.h).
#include "granlub/results/failure_record.h"


#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "granlub/error.h"
#include "granlub/results/results.h"

namespace granlub {

void write_failure(const std::filesystem::path& dir, const std::string& solver, const std::string& point,
                   const std::string& message, bool no_answer) {
    const nlohmann::json j = {{"format", "granlub-failure-1"}, {"solver", solver},       {"point", point},
                              {"message", message},            {"utc_time", utc_now()}, {"granlub_version", version()},
                              {"kind", no_answer ? "no answer" : "failed"}};
    write_file_atomic(dir / kFailureFile, j.dump(2) + "\n");
}

std::optional<FailureRecord> read_failure(const std::filesystem::path& dir) {
    const auto path = dir / kFailureFile;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return std::nullopt;
    try {
        const auto j = nlohmann::json::parse(read_file(path));
        if (!j.is_object() || j.value("format", "") != "granlub-failure-1")
            throw Error(fmt::format("{}: not a granlub failure record (format is not granlub-failure-1)", path.string()));
        const std::string kind = j.value("kind", "failed");
        if (kind != "failed" && kind != "no answer")
            throw Error(fmt::format("{}: kind = \"{}\" (allowed: \"failed\", \"no answer\")", path.string(), kind));
        return FailureRecord{j.at("solver").get<std::string>(), j.at("point").get<std::string>(),
                             j.at("message").get<std::string>(), j.value("utc_time", ""),
                             j.value("granlub_version", ""), kind == "no answer"};
    } catch (const nlohmann::json::exception& e) {
        throw Error(fmt::format("{}: malformed failure record: {}", path.string(), e.what()));
    }
}

void remove_failure(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::remove(dir / kFailureFile, ec);
}

}  // namespace granlub
