// The small shear cell the `granlub dem` tests run (tiny_cell_text.h), with the dem section's
// schema and the tests' helpers.
#pragma once
#include <filesystem>
#include <regex>
#include <string>

#include "granlub/case/case.h"
#include "granlub/dem/command.h"
#include "tiny_cell_text.h"

namespace granlub::test {

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
