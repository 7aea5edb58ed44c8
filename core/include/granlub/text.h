// Text that comes from a case file and ends up somewhere else: in a LIGGGHTS deck, a data file, a
// CSV comment, an error message. Every such string is either checked here at parse time or made
// into one inert line before it is written (a newline in a deck comment would start a command).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace granlub {

// Byte offset of the first byte that does not start a well-formed UTF-8 sequence (overlong
// forms, surrogates and code points above U+10FFFF included); nullopt when the text is valid.
std::optional<std::size_t> invalid_utf8_offset(std::string_view text);

// 1-based line and column (in bytes) of a byte offset, for error messages.
struct LineColumn {
    std::size_t line = 1;
    std::size_t column = 1;
};
LineColumn line_column(std::string_view text, std::size_t offset);

// Characters a case name may hold: it names result folders and is written into decks and files.
inline constexpr const char* kNameCharacters = "letters A-Z a-z, digits, '.', '_', '-', '+'";
inline constexpr std::size_t kMaxNameLength = 64;
// Empty when `name` is a usable case name, else why not.
std::string name_problem(std::string_view name);
// The same name with every character outside kNameCharacters replaced by '_' (and clipped), for
// names derived from a directory.
std::string sanitized_name(std::string_view name);

// Byte offset of the first control character (C0, DEL, C1, U+2028/U+2029): none may stand in a
// one-line text such as a title. Assumes valid UTF-8.
std::optional<std::size_t> control_character_offset(std::string_view text);

// The text as one inert line: control characters written as \n, \t or \xNN, so that it cannot
// end a comment line early in any file format we write.
std::string one_line(std::string_view text);

// At most `max` bytes of `text` (cut on a UTF-8 boundary), with "... (N bytes)" when cut: for
// echoing user input in error messages.
std::string clipped(std::string_view text, std::size_t max = 60);

}  // namespace granlub
