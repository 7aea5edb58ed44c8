// A valid case as TOML text, and a helper to make variants of it for tests.
#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>

#include "granlub/case/case.h"
#include "granlub/error.h"

namespace granlub::test {

inline const std::string kValidCase = R"(# test case
[case]
name = "t"

[grains]
diameter = 1.0e-3
density = 2500.0
restitution = 0.9

[walls]
restitution = 0.8
roughness = 0.5

[cell]
gap = 5.0e-3
length = 20.0e-3
width = 0.0
max_solid_fraction = 0.65

[operating]
speed = [1.0, 2.0]
control = "fill"
solid_fraction = 0.5
normal_stress = 1000.0
)";

// kValidCase with the first occurrence of `from` replaced by `to` (which must exist).
inline std::string with(const std::string& from, const std::string& to, std::string text = kValidCase) {
    auto pos = text.find(from);
    if (pos == std::string::npos) throw std::logic_error("test text lacks: " + from);
    return text.replace(pos, from.size(), to);
}

// The CaseError message of parsing `text` as "bad.toml" with the common schema; "" when it parses.
inline std::string error_of(const std::string& text) {
    try {
        parse_case(text, "bad.toml", Schema::common());
    } catch (const CaseError& e) {
        return e.what();
    }
    return "";
}

// The CaseError message of loading a case directory or file with the common schema; "" when it loads.
inline std::string load_error(const std::filesystem::path& p) {
    try {
        load_case(p, Schema::common());
    } catch (const CaseError& e) {
        return e.what();
    }
    return "";
}

// A fresh folder under the system temp folder, removed at the end of the scope.
struct TmpDir {
    std::filesystem::path path;
    explicit TmpDir(const std::string& name)
        : path(std::filesystem::temp_directory_path() / ("granlub_test_" + name)) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TmpDir() { std::filesystem::remove_all(path); }
};

}  // namespace granlub::test
