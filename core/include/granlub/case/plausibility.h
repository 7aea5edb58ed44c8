// Values that are allowed but probably a slip of units (a gap of 5 m is 6 000 grain diameters):
// `granlub check` warns about them, it does not refuse them.
#pragma once
#include <string>
#include <vector>

namespace granlub {

struct Case;

// One line per implausible value, naming the key, the value and why it looks wrong.
std::vector<std::string> plausibility_warnings(const Case& c);

}  // namespace granlub
