// Whole-file reads and atomic writes (file_io.h).
#include "granlub/results/file_io.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

namespace {

// This machine's name as a file name part ("host" when it has none; a '/' would name a folder).
std::string host_name() {
    char buf[HOST_NAME_MAX + 1] = {};
    std::string h = ::gethostname(buf, sizeof buf - 1) == 0 ? std::string(buf) : std::string();
    std::replace(h.begin(), h.end(), '/', '_');
    return h.empty() ? "host" : h;
}

// A temp file of its own beside `path`, created with O_EXCL: the host, the process and a
// process-wide count name it, so that no two writers (threads of one process, processes on two
// nodes sharing the filesystem) ever write into one temp file. A name already taken (left by a
// killed writer whose pid came round again) is passed over for the next count.
int open_temp(const std::filesystem::path& path, std::string& tmp) {
    static const std::string host = host_name();
    static std::atomic<std::uint64_t> count{0};
    for (int attempt = 0;; ++attempt) {
        tmp = fmt::format("{}.tmp.{}.{}.{}", path.string(), host, ::getpid(), count.fetch_add(1));
        const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
        if (fd >= 0 || errno != EEXIST || attempt == 99) return fd;
    }
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::string_view bytes) {
    std::error_code ec;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
    std::string tmp;
    int fd = open_temp(path, tmp);
    if (fd < 0) throw Error(fmt::format("{}: cannot write: {}", path.string(), std::strerror(errno)));
    std::size_t off = 0;
    while (off < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + off, bytes.size() - off);
        if (n < 0) {
            if (errno == EINTR) continue;
            int e = errno;
            ::close(fd);
            ::unlink(tmp.c_str());
            throw Error(fmt::format("{}: write failed: {}", path.string(), std::strerror(e)));
        }
        off += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        ::unlink(tmp.c_str());
        throw Error(fmt::format("{}: write failed: {}", path.string(), std::strerror(errno)));
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        int e = errno;
        ::unlink(tmp.c_str());
        throw Error(fmt::format("{}: cannot rename into place: {}", path.string(), std::strerror(e)));
    }
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(fmt::format("{}: cannot be read", path.string()));
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace granlub
