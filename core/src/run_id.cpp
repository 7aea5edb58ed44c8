// The run id of this process and the '#' comment line that carries it into tables (run_id.h).
#include "granlub/run_id.h"

#include <unistd.h>

#include <cctype>
#include <ctime>
#include <fstream>
#include <random>

#include <fmt/format.h>

namespace granlub {

namespace {

constexpr std::string_view kKey = "run_id ";

// The host name in the id's alphabet (letters, digits, '-'), short: the id stays one token that
// the parser below reads back whole.
std::string host_token() {
    char buf[256] = {};
    if (::gethostname(buf, sizeof buf - 1) != 0) return "host";
    std::string h;
    for (const char* c = buf; *c && *c != '.' && h.size() < 24; ++c)
        h += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '-';
    return h.empty() ? "host" : h;
}

std::string make_run_id() {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char when[32];
    std::strftime(when, sizeof when, "%Y%m%dT%H%M%SZ", &tm);
    std::random_device rd;  // the kernel's entropy: no seed of granlub's is touched
    return fmt::format("{}-{}-{}-{:08x}", when, host_token(), ::getpid(), rd());
}

}  // namespace

const std::string& run_id() {
    static const std::string id = make_run_id();
    return id;
}

std::string run_id_comment(std::string_view id) { return fmt::format("{}{}", kKey, id); }

std::optional<std::string> table_run_id(std::string_view text) {
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t eol = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, eol - start);
        start = eol + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.empty()) continue;
        if (line[0] != '#') break;  // the comments end where the table starts
        line.remove_prefix(line.size() > 1 && line[1] == ' ' ? 2 : 1);
        if (line.substr(0, kKey.size()) == kKey) return std::string(line.substr(kKey.size()));
    }
    return std::nullopt;
}

std::optional<std::string> read_table_run_id(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string head;
    for (std::string line; std::getline(in, line) && (line.empty() || line[0] == '#');) head += line + '\n';
    return table_run_id(head);  // only the comment lines are read: final_state.csv can be large
}

}  // namespace granlub
