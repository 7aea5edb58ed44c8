// A case file from disk to a TOML table: what load_case and a case's [case] base read the same way.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace granlub {

// A case's file: `dir_or_file` itself, or the case.toml in it when it is a directory.
struct CaseFileText {
    std::filesystem::path file;
    std::string text;
};
// Throws CaseError naming the file when it is missing, not a regular file, too large or unreadable.
CaseFileText read_case_file(const std::filesystem::path& dir_or_file);

// The text as a TOML table, `source` naming it in messages and in every node's source region:
// size, UTF-8 and the screen for what toml++ mishandles (toml_screen.h) first.
toml::table read_toml(std::string_view text, const std::string& source);

// "file:line:column" of a node, for messages: the file the node was read from (a base's, for a
// value merged from a case's base), else `file`.
std::string where(const std::string& file, const toml::source_region& r);

}  // namespace granlub
