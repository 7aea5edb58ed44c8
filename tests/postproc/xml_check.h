// XML well-formedness with expat: empty string when well-formed, else "line N: message".
#pragma once
#include <string>

namespace granlub::test {
std::string xml_error(const std::string& text);
}
