#include "toml_screen.h"

#include <vector>

namespace granlub {

namespace {

bool ascii_space(char c) { return c == ' ' || c == '\t'; }
bool key_start(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '"' || c == '\'';
}
// First characters of a TOML value: strings, numbers (incl. inf/nan), booleans, dates, arrays,
// inline tables.
bool value_start(char c) {
    return c == '"' || c == '\'' || (c >= '0' && c <= '9') || c == '+' || c == '-' || c == 't' || c == 'f' ||
           c == 'i' || c == 'n' || c == '[' || c == '{';
}

class Screen {
public:
    explicit Screen(std::string_view t) : t_(t) {}

    std::optional<ScreenProblem> run() {
        if (t_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // a UTF-8 byte-order mark, which toml++ skips
        bool line_start = true;  // at the start of a line, outside any value
        char prev = '\n';        // the last character outside strings, blanks and comments
        bool expect_key = true;  // a key may come (line start, after '{' or ','): an '=' is due
        bool in_header = false;  // inside [table] or [[table]]
        while (i_ < t_.size()) {
            const char c = t_[i_];
            if (c == '#') { skip_comment(); continue; }
            if (c == '"' || c == '\'') {
                // A string starts a key or a value, never the middle of one (`8888-"x`): there the
                // screen and toml++ would disagree on what is inside a string.
                const bool dotted_key = prev == '.' && (expect_key || in_header);  // a."b", never 0."b"
                if (prev != '\n' && prev != '=' && prev != '[' && prev != ',' && prev != '{' && !dotted_key)
                    return fail("a quote in the middle of a key or value");
                if (!string()) return problem_;
                prev = '"';
                line_start = false;
                continue;
            }
            const char before = prev;
            if (!ascii_space(c) && c != '\r') prev = c;
            if (static_cast<unsigned char>(c) >= 0x80)
                return fail("a non-ASCII character outside a string or comment (put it in quotes)");
            if (c == '\n') {
                if (stack_.empty()) line_start = expect_key = true, in_header = false;
                ++i_;
                continue;
            }
            if (c == '\r') {  // only as part of CRLF (toml++ asserts on a lone one in a header)
                if (i_ + 1 >= t_.size() || t_[i_ + 1] != '\n') return fail("a carriage return without a line feed");
                ++i_;
                continue;
            }
            if (ascii_space(c)) { ++i_; continue; }
            if (stack_.empty() && line_start && c == '[') {  // table header: [a] or [[a]]
                ++i_;
                if (i_ < t_.size() && t_[i_] == '[') ++i_;
                if (!next_is(key_start, "a table header must start with a key, e.g. [walls.top]")) return problem_;
                line_start = expect_key = false;
                in_header = true;
                continue;
            }
            line_start = false;
            if (c == '=') {
                // One '=' per key: a second one in a value (`a = 1-2=3="x"`) made toml++ read on
                // into text the screen took for a string.
                if (!expect_key) return fail("an '=' where a value or the end of the line was expected");
                expect_key = false;
                ++i_;
                if (!next_is(value_start, "a value must follow '='")) return problem_;
                continue;
            }
            if (c == '[' || c == '{') {  // in value position: an array or an inline table
                // only where a value starts (`a = 8888-["x` made toml++ read on as above)
                if (before != '=' && before != '[' && before != ',')
                    return fail("a bracket in the middle of a key or value");
                stack_.push_back(c);
                expect_key = c == '{';
                ++i_;
                if (!element(c)) return problem_;
                continue;
            }
            if (c == ',' && !stack_.empty()) {
                expect_key = stack_.back() == '{';
                ++i_;
                if (!element(stack_.back())) return problem_;
                continue;
            }
            if ((c == ']' || c == '}') && !stack_.empty()) {
                stack_.pop_back();
                ++i_;
                continue;
            }
            ++i_;
        }
        return std::nullopt;
    }

private:
    std::optional<ScreenProblem> fail(const char* why) {
        problem_ = ScreenProblem{i_, why};
        return problem_;
    }

    void skip_comment() {
        while (i_ < t_.size() && t_[i_] != '\n') ++i_;
    }

    // Skips blanks (and, inside arrays, newlines and comments); true when the next character
    // satisfies `ok` or closes the enclosing bracket.
    bool next_is(bool (*ok)(char), const char* why, char open = 0) {
        while (i_ < t_.size()) {
            const char c = t_[i_];
            if (ascii_space(c)) { ++i_; continue; }
            if (open == '[' && (c == '\n' || (c == '\r' && i_ + 1 < t_.size() && t_[i_ + 1] == '\n'))) {
                ++i_;
                continue;
            }
            if (open == '[' && c == '#') { skip_comment(); continue; }
            break;
        }
        if (i_ >= t_.size()) return true;  // toml++ reports a premature end cleanly
        const char c = t_[i_];
        if (ok(c) || (open == '[' && c == ']') || (open == '{' && c == '}')) return true;
        if (static_cast<unsigned char>(c) >= 0x80) {
            fail("a non-ASCII character outside a string or comment (put it in quotes)");
            return false;
        }
        fail(why);
        return false;
    }

    bool element(char open) {
        return open == '[' ? next_is(value_start, "an array element must be a value", '[')
                           : next_is(key_start, "an inline table must hold key = value pairs", '{');
    }

    // A string from its opening quote; false with problem_ set when it has a toml++ trap.
    bool string() {
        const char q = t_[i_];
        const bool multi = t_.substr(i_, 3) == std::string_view(q == '"' ? "\"\"\"" : "'''");
        i_ += multi ? 3 : 1;
        while (i_ < t_.size()) {
            const char c = t_[i_];
            if (!multi && c == '\n') return true;  // unterminated: toml++ says so
            if (q == '"' && c == '\\') {
                // No escape starts with a non-ASCII character; toml++ 3.3 trips on one after a
                // backslash (and, in multi-line strings, after the blanks it skips there).
                std::size_t k = i_ + 1;
                while (multi && k < t_.size() && ascii_space(t_[k])) ++k;
                if (k < t_.size() && static_cast<unsigned char>(t_[k]) >= 0x80) {
                    i_ = k;
                    fail("a non-ASCII character after a backslash (not a TOML escape)");
                    return false;
                }
                if (multi && line_ending_backslash()) {
                    // toml++ skips the whitespace that follows and trips on a non-ASCII character
                    while (i_ < t_.size() && (ascii_space(t_[i_]) || t_[i_] == '\r' || t_[i_] == '\n')) ++i_;
                    if (i_ < t_.size() && static_cast<unsigned char>(t_[i_]) >= 0x80) {
                        fail("a non-ASCII character right after a line-ending backslash (start the line with an "
                             "ASCII character)");
                        return false;
                    }
                    continue;
                }
                i_ += 2;
                continue;
            }
            if (c == q) {
                if (!multi) { ++i_; return true; }
                if (t_.substr(i_, 3) == std::string_view(q == '"' ? "\"\"\"" : "'''")) {
                    i_ += 3;
                    while (i_ < t_.size() && t_[i_] == q) ++i_;  // up to two quotes may end the content
                    return true;
                }
            }
            ++i_;
        }
        return true;
    }

    // At a backslash: is it followed by blanks up to the end of the line?
    bool line_ending_backslash() {
        std::size_t k = i_ + 1;
        while (k < t_.size() && (ascii_space(t_[k]) || t_[k] == '\r')) ++k;
        if (k < t_.size() && t_[k] == '\n') {
            i_ = k + 1;
            return true;
        }
        return false;
    }

    std::string_view t_;
    std::size_t i_ = 0;
    std::vector<char> stack_;
    std::optional<ScreenProblem> problem_;
};

}  // namespace

std::optional<ScreenProblem> screen_toml(std::string_view text) { return Screen(text).run(); }

}  // namespace granlub
