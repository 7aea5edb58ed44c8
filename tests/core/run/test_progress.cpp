// Progress in a log (stderr not a terminal): plain lines at the log interval, no terminal control
// codes, none before the interval has passed, none with GRANLUB_PROGRESS=0.
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include "granlub/run/progress.h"

namespace fs = std::filesystem;
using granlub::Progress;
using namespace std::chrono_literals;

namespace {

// What `body` writes to stderr, with stderr pointed at a file (so it is not a terminal).
template <class F>
std::string stderr_of(F body) {
    const fs::path file = fs::temp_directory_path() / ("granlub-progress-" + std::to_string(::getpid()) + ".log");
    std::fflush(stderr);
    const int saved = ::dup(STDERR_FILENO);
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    BOOST_REQUIRE(saved >= 0 && fd >= 0);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
    body();
    std::fflush(stderr);
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    std::stringstream text;
    text << std::ifstream(file).rdbuf();
    fs::remove(file);
    return text.str();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(progress_in_a_log)

BOOST_AUTO_TEST_CASE(writes_plain_lines_at_the_interval) {
    ::unsetenv("GRANLUB_PROGRESS");
    const std::string out = stderr_of([] {
        Progress p("dem U2.0", 10, 0ms);
        BOOST_TEST(p.due());
        p.update(3, "LIGGGHTS");
        p.update(10, "LIGGGHTS");
    });
    // one line per update (the ETA of the first depends on the clock), each ended by a newline
    static const std::regex lines(R"(dem U2\.0  30\.0% \(3/10\)  ETA \S+  LIGGGHTS\n)"
                                  R"(dem U2\.0 100\.0% \(10/10\)  ETA --  LIGGGHTS\n)");
    BOOST_TEST(std::regex_match(out, lines), out);
    BOOST_TEST(out.find('\r') == std::string::npos);
    BOOST_TEST(out.find('\033') == std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_short_run_leaves_no_line) {
    ::unsetenv("GRANLUB_PROGRESS");
    const std::string out = stderr_of([] {
        Progress p("yade U2.0", 100);  // the default interval, a minute
        BOOST_TEST(!p.due());
        for (std::uint64_t i = 0; i <= 100; ++i) p.update(i);
    });
    BOOST_TEST(out.empty());
}

BOOST_AUTO_TEST_CASE(granlub_progress_0_silences_it) {
    ::setenv("GRANLUB_PROGRESS", "0", 1);
    const std::string out = stderr_of([] {
        Progress p("automaton U2.0", 10, 0ms);
        BOOST_TEST(!p.due());
        p.update(5);
    });
    ::unsetenv("GRANLUB_PROGRESS");
    BOOST_TEST(out.empty());
}

BOOST_AUTO_TEST_SUITE_END()
