#include "granlub/text.h"

#include <fmt/format.h>

namespace granlub {

namespace {
// Length of the well-formed UTF-8 sequence starting at `i` (RFC 3629, Table 3-7 of the Unicode
// standard), or 0 when it is not well formed.
std::size_t utf8_sequence(std::string_view t, std::size_t i) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(t[k]); };
    const unsigned char c = b(i);
    if (c < 0x80) return 1;
    std::size_t n;
    unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
    if (c >= 0xC2 && c <= 0xDF) n = 2;
    else if (c == 0xE0) n = 3, lo = 0xA0;  // no overlong 3-byte forms
    else if (c == 0xED) n = 3, hi = 0x9F;  // no UTF-16 surrogates
    else if (c >= 0xE1 && c <= 0xEF) n = 3;
    else if (c == 0xF0) n = 4, lo = 0x90;  // no overlong 4-byte forms
    else if (c == 0xF4) n = 4, hi = 0x8F;  // nothing above U+10FFFF
    else if (c >= 0xF1 && c <= 0xF3) n = 4;
    else return 0;
    if (i + n > t.size()) return 0;
    if (b(i + 1) < lo || b(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
    return n;
}

bool name_char(char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '.' ||
           ch == '_' || ch == '-' || ch == '+';
}
}  // namespace

std::optional<std::size_t> invalid_utf8_offset(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8_sequence(text, i);
        if (n == 0) return i;
        i += n;
    }
    return std::nullopt;
}

LineColumn line_column(std::string_view text, std::size_t offset) {
    LineColumn lc;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') ++lc.line, lc.column = 1;
        else ++lc.column;
    }
    return lc;
}

std::string name_problem(std::string_view name) {
    if (name.empty()) return "empty";
    if (name.size() > kMaxNameLength) return fmt::format("longer than {} characters", kMaxNameLength);
    for (char ch : name)
        if (!name_char(ch))
            return static_cast<unsigned char>(ch) >= 0x80 ? std::string("holds a non-ASCII character")
                                                          : fmt::format("holds '{}'", one_line(std::string(1, ch)));
    if (name.front() == '.' || name.front() == '-') return "starts with '.' or '-'";
    return "";
}

std::string sanitized_name(std::string_view name) {
    std::string out;
    for (char ch : name.substr(0, kMaxNameLength)) out += name_char(ch) ? ch : '_';
    if (!out.empty() && (out.front() == '.' || out.front() == '-')) out.front() = '_';
    return out;
}

std::optional<std::size_t> control_character_offset(std::string_view text) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c == 0x7F) return i;
        if (c == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
            static_cast<unsigned char>(text[i + 1]) <= 0x9F)
            return i;  // C1 controls U+0080..U+009F
        if (c == 0xE2 && i + 2 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0x80 &&
            (static_cast<unsigned char>(text[i + 2]) == 0xA8 || static_cast<unsigned char>(text[i + 2]) == 0xA9))
            return i;  // U+2028 LINE SEPARATOR, U+2029 PARAGRAPH SEPARATOR
    }
    return std::nullopt;
}

std::string one_line(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (ch == '\n') out += "\\n";
        else if (ch == '\r') out += "\\r";
        else if (ch == '\t') out += "\\t";
        else if (c < 0x20 || c == 0x7F) out += fmt::format("\\x{:02x}", c);
        else out += ch;
    }
    return out;
}

std::string clipped(std::string_view text, std::size_t max) {
    if (text.size() <= max) return std::string(text);
    std::size_t cut = max;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a sequence
    return fmt::format("{}... ({} bytes)", text.substr(0, cut), text.size());
}

}  // namespace granlub
