// A screen run over a case file before toml++ parses it. toml++ 3.3.0 (Debian 12) has undefined
// behaviour (an "unreachable" or a broken precondition) on some malformed inputs: a non-ASCII
// character where it skips whitespace (its issues 190/295, fixed upstream in PR 305), a table
// header that does not start with a key (PR 301), an array element that cannot start a value
// (`a = [}`). Each is malformed TOML anyway, so the screen rejects it with a clear message; any
// input it passes that is still malformed is left to toml++'s own errors.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace granlub {

struct ScreenProblem {
    std::size_t offset = 0;  // byte offset of the offending character
    std::string why;
};

// Expects valid UTF-8 (checked before). TOML 1.0 allows non-ASCII only inside strings and comments.
std::optional<ScreenProblem> screen_toml(std::string_view text);

}  // namespace granlub
