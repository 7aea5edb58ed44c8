#include "formats/format.h"

#include <cmath>

#include <fmt/format.h>

namespace granlub::postproc {

std::string xml_escape(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (char ch : s) {
        switch (ch) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += ch;
        }
    }
    return out;
}

std::string num(double v, int digits) {
    if (!std::isfinite(v)) return "";
    if (v == 0.0) return "0";
    return fmt::format("{:.{}g}", v, digits);
}

std::string num(const std::optional<double>& v, int digits) { return v ? num(*v, digits) : std::string(); }

std::string csv_field(std::string_view s) {
    if (s.find_first_of(",\"\n") == std::string_view::npos) return std::string(s);
    std::string out = "\"";
    for (char ch : s) {
        if (ch == '"') out += '"';
        out += ch;
    }
    return out + "\"";
}

std::string value_pm(const std::optional<double>& v, const std::optional<double>& se, int digits) {
    if (!v) return "";
    if (se && *se > 0) return fmt::format("{} ± {}", num(*v, digits), num(*se, 2));
    return num(*v, digits);
}

std::string z_text(double z) { return std::abs(z) < 10 ? fmt::format("z = {:.1f}", z) : fmt::format("z = {:.0f}", z); }

std::string list_text(const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
    return s;
}

}  // namespace granlub::postproc
