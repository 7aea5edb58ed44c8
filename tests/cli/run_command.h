// Run a command through the shell, capturing stdout+stderr and the exit code.
#pragma once
#include <array>
#include <cstdio>
#include <string>

#include <sys/wait.h>

namespace granlub::test {

struct Output {
    int rc = -1;
    std::string text;
};

inline Output run(const std::string& cmd) {
    Output o;
    FILE* p = ::popen((cmd + " 2>&1").c_str(), "r");
    if (!p) return o;
    std::array<char, 4096> buf{};
    std::size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) o.text.append(buf.data(), n);
    const int status = ::pclose(p);
    o.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return o;
}

}  // namespace granlub::test
