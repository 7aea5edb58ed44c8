// Value formatting shared by the report writers: numbers, lists, escapes (core's granlub/text.h is the
// case text's guard, another thing).
#pragma once
#include <optional>
#include <string>
#include <vector>
#include <string_view>

namespace granlub::postproc {

std::string xml_escape(std::string_view s);       // & < > " '
std::string num(double v, int digits = 4);         // compact: "%.{digits}g"
std::string num(const std::optional<double>& v, int digits = 4);  // "" when absent
std::string csv_field(std::string_view s);         // quoted when it holds , " or a newline
std::string list_text(const std::vector<std::string>& v);  // "a, b, c"
// "v ± se" (se to 2 digits; just v without a positive se; "" without v)
std::string value_pm(const std::optional<double>& v, const std::optional<double>& se, int digits = 4);
// "z = 2.2": one decimal near the |z| = 2 threshold, to the unit beyond 10, where a decimal says nothing
std::string z_text(double z);

}  // namespace granlub::postproc
