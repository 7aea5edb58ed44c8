// Whole files: read at once, written atomically. Every result file and page goes through these.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

namespace granlub {

// Atomic writes: a temp file of the writer's own in the same directory (<file>.tmp.<host>.<pid>.<count>,
// created exclusively: unique across the hosts sharing a filesystem, the processes and the threads),
// flushed, then renamed over the target. Concurrent writers of one file leave one of their writes whole.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);
// The whole file's bytes; Error "<file>: cannot be read" when it cannot be opened.
std::string read_file(const std::filesystem::path& path);

}  // namespace granlub
