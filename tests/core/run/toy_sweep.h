// What the sweep tests share: a fresh results folder and a toy solver's point result.
#pragma once
#include <filesystem>
#include <string>

#include "granlub/case/case.h"
#include "granlub/results/results.h"
#include "granlub/run/sweep.h"

namespace granlub::test {

// Options that write into a fresh results folder of this name in the temporary directory.
inline RunOptions fresh_results(const std::string& name) {
    RunOptions o;
    o.results_root = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(o.results_root);
    return o;
}

// A complete result of `solver` at point p: a two-row profile and every standard output = U.
inline PointResult toy_result(const Case& c, const OperatingPoint& p, const std::string& solver = "toy") {
    PointResult r;
    r.profile.add("y_over_H", {0, 1}).add("u_over_U", {1, 0}).add("solid_fraction", {0.5, 0.5}).add(
        "temperature_over_U2", {0.01, 0.01});
    r.summary = make_summary(c, p, solver);
    for (const char* name : kStandardOutputs) r.summary.set(name, p.speed, "");
    r.line = "ok";
    return r;
}

}  // namespace granlub::test
