// The small shear cell the `granlub dem` tests run: d = 1 mm grains in an 8 x 6 x 6 mm cell,
// inserted at solid fraction 0.4 (220 grains), gravity and a centripetal force. Each test adds
// its own [operating] keys and [dem] settings. Small enough for a few seconds per run.
#pragma once
#include <filesystem>
#include <regex>
#include <string>

#include "granlub/case/case.h"
#include "granlub/dem/command.h"

namespace granlub::test {

inline std::string tiny_cell(const std::string& name, const std::string& operating, const std::string& dem) {
    return "[case]\nname = \"" + name + R"("
[grains]
diameter = 1.0e-3
density = 2500.0
restitution = 0.9
friction = 0.5
[walls]
restitution = 0.8
roughness = 0.5
[cell]
gap = 6.0e-3
length = 8.0e-3
width = 6.0e-3
annulus_radius = 0.05
[operating]
speed = [1.0]
solid_fraction = 0.4
)" + operating + R"(
[body_forces]
gravity = 9.81
[dem]
)" + dem;
}

inline Schema dem_schema() {
    Schema s = Schema::common();
    s.add(dem::section());
    return s;
}

// `text` with every match of the regular expression `from` replaced by `to`.
inline std::string edit(const std::string& text, const std::string& from, const std::string& to) {
    return std::regex_replace(text, std::regex(from), to);
}

// A fresh, empty folder under the build tree for one test's results.
inline std::filesystem::path scratch(const std::string& suite, const std::string& name) {
    const auto d = std::filesystem::path(GRANLUB_BINARY_DIR) / "tests" / suite / name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

}  // namespace granlub::test
