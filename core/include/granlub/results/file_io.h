// Whole files: read at once, written atomically. Every result file and page goes through these.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

namespace granlub {

// Atomic writes: temp file in the same directory, flushed, then renamed over the target.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);
// The whole file's bytes; Error "<file>: cannot be read" when it cannot be opened.
std::string read_file(const std::filesystem::path& path);

}  // namespace granlub
