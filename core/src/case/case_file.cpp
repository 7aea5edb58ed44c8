// A case file from disk to a TOML table (case_file.h).
#include "case_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

#include <fmt/format.h>

#include "granlub/case/case.h"
#include "granlub/error.h"
#include "granlub/text.h"
#include "toml_screen.h"

namespace granlub {

namespace {
// Why `file` cannot be read as a case file, or "" when it is a readable regular file. Checked
// before opening: opening a FIFO would block, a directory reads as empty.
std::string unreadable_case_file(const std::filesystem::path& file, bool from_directory) {
    namespace fs = std::filesystem;
    const std::string hint = "(a case is a directory holding case.toml, e.g. cases/sawyer2001)";
    struct stat lst {};
    if (::lstat(file.c_str(), &lst) != 0) {
        if (errno == ENOENT)
            return from_directory ? fmt::format("{}: no case.toml in this directory {}", file.parent_path().string(), hint)
                                  : fmt::format("{}: no such case directory or file {}", file.string(), hint);
        return fmt::format("{}: cannot be examined: {}", file.string(), std::strerror(errno));
    }
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0) {
        if (errno == ELOOP) return fmt::format("{}: a loop of symbolic links", file.string());
        std::error_code ec;
        const auto target = fs::read_symlink(file, ec);
        return fmt::format("{}: a symbolic link to {}, which {}", file.string(), ec ? "?" : target.string(),
                           errno == ENOENT ? "does not exist" : std::strerror(errno));
    }
    if (S_ISDIR(st.st_mode)) return fmt::format("{}: a directory, not a case file {}", file.string(), hint);
    if (!S_ISREG(st.st_mode))
        return fmt::format("{}: not a regular file (a FIFO, socket or device); a case file is a TOML text file",
                           file.string());
    if (static_cast<std::uintmax_t>(st.st_size) > kMaxCaseFileBytes)
        return fmt::format("{}: {} bytes; a case file may have at most {} bytes", file.string(), st.st_size,
                           kMaxCaseFileBytes);
    return "";
}
}  // namespace

std::string where(const std::string& file, const toml::source_region& r) {
    // A node merged from a case's base keeps its own file (case_base.h).
    const std::string& f = r.path && !r.path->empty() ? *r.path : file;
    if (r.begin.line == 0) return f;
    return fmt::format("{}:{}:{}", f, r.begin.line, r.begin.column);
}

CaseFileText read_case_file(const std::filesystem::path& dir_or_file) {
    std::filesystem::path file = dir_or_file;
    std::error_code ec;
    const bool from_directory = std::filesystem::is_directory(file, ec);
    if (from_directory) file /= "case.toml";
    if (const std::string why = unreadable_case_file(file, from_directory); !why.empty()) throw CaseError(why);
    std::ifstream in(file, std::ios::binary);
    if (!in) throw CaseError(fmt::format("{}: cannot be read: {}", file.string(), std::strerror(errno)));
    std::stringstream ss;
    ss << in.rdbuf();
    return {file, ss.str()};
}

toml::table read_toml(std::string_view text, const std::string& source) {
    if (text.size() > kMaxCaseFileBytes)
        throw CaseError(fmt::format("{}: {} bytes; a case file may have at most {} bytes", source, text.size(),
                                    kMaxCaseFileBytes));
    // A case file is UTF-8 text; and toml++ 3.3 has undefined behaviour on some malformed TOML
    // (toml_screen.h), which is therefore rejected before toml++ sees it.
    if (const auto bad = invalid_utf8_offset(text)) {
        const LineColumn lc = line_column(text, *bad);
        throw CaseError(fmt::format("{}:{}:{}: byte 0x{:02x} is not valid UTF-8 (a case file is UTF-8 text)", source,
                                    lc.line, lc.column, static_cast<unsigned char>(text[*bad])));
    }
    if (const auto bad = screen_toml(text)) {
        const LineColumn lc = line_column(text, bad->offset);
        throw CaseError(fmt::format("{}:{}:{}: TOML syntax error: {}", source, lc.line, lc.column, bad->why));
    }
    try {
        return toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        throw CaseError(fmt::format("{}: TOML syntax error: {}", where(source, e.source()), e.description()));
    }
}

}  // namespace granlub
