// Small text helpers shared by the report writers.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace granlub::postproc {

std::string xml_escape(std::string_view s);       // & < > " '
std::string num(double v, int digits = 4);         // compact: "%.{digits}g"
std::string num(const std::optional<double>& v, int digits = 4);  // "" when absent
std::string csv_field(std::string_view s);         // quoted when it holds , " or a newline

}  // namespace granlub::postproc
