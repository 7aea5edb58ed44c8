// A valid case as TOML text, and a helper to make variants of it for tests.
#pragma once
#include <stdexcept>
#include <string>

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

}  // namespace granlub::test
