#define BOOST_TEST_MODULE granlub command
#include <filesystem>
#include <fstream>

#include <boost/test/unit_test.hpp>

#include "run_command.h"

using granlub::test::run;
namespace fs = std::filesystem;

namespace {
const std::string exe = GRANLUB_EXE;
const std::string src = GRANLUB_SOURCE_DIR;
}  // namespace

BOOST_AUTO_TEST_CASE(check_prints_the_resolved_default_case) {
    auto o = run(exe + " check " + src + "/cases/sawyer2001");
    BOOST_TEST(o.rc == 0, o.text);
    BOOST_TEST(o.text.find("# 3 operating point(s)") != std::string::npos, o.text);
    BOOST_TEST(o.text.find("U2.8") != std::string::npos);
    BOOST_TEST(o.text.find("(default)") != std::string::npos);
    // cases/jasti2006 has an [automaton] section, which exists when that module is built in.
    if (run(exe + " --help").text.find("\n  automaton") != std::string::npos) {
        auto j = run(exe + " check " + src + "/cases/jasti2006");
        BOOST_TEST(j.rc == 0, j.text);
        BOOST_TEST(j.text.find("U2.0_R0.75") != std::string::npos, j.text);
    }
}

BOOST_AUTO_TEST_CASE(bad_input_exits_2_with_the_place_named) {
    auto missing = run(exe + " check /nonexistent/case");
    BOOST_TEST(missing.rc == 2);
    BOOST_TEST(missing.text.find("no such case directory or file") != std::string::npos, missing.text);

    const fs::path dir = fs::temp_directory_path() / "granlub_test_cli_bad";
    fs::create_directories(dir);
    {
        std::ifstream in(src + "/cases/sawyer2001/case.toml");
        std::string text((std::istreambuf_iterator<char>(in)), {});
        text.replace(text.find("restitution = 0.9 "), 18, "restitution = 1.9 ");
        std::ofstream(dir / "case.toml") << text;
    }
    auto bad = run(exe + " check " + dir.string());
    BOOST_TEST(bad.rc == 2);
    BOOST_TEST(bad.text.find("case.toml:12:15: [grains] restitution = 1.9: out of range (allowed: a number (0, 1])") !=
                   std::string::npos,
               bad.text);
    fs::remove_all(dir);

    auto usage = run(exe + " check");
    BOOST_TEST(usage.rc == 2);
    BOOST_TEST(usage.text.find("CASE is required") != std::string::npos, usage.text);
}

BOOST_AUTO_TEST_CASE(version_and_help) {
    auto v = run(exe + " --version");
    BOOST_TEST(v.rc == 0);
    BOOST_TEST(v.text.find('.') != std::string::npos, v.text);
    auto h = run(exe + " --help");
    BOOST_TEST(h.rc == 0);
    BOOST_TEST(h.text.find("check") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(keys_are_printed_from_their_declarations) {
    auto o = run(exe + " keys grains");
    BOOST_TEST(o.rc == 0, o.text);
    BOOST_TEST(o.text.find("| `diameter` | required | > 0 | m | grain diameter d |") != std::string::npos, o.text);
    BOOST_TEST(o.text.find("| `friction` | 0.5 | >= 0 |") != std::string::npos, o.text);
    auto bad = run(exe + " keys nosuchsection");
    BOOST_TEST(bad.rc == 2);
    BOOST_TEST(bad.text.find("no section [nosuchsection]") != std::string::npos, bad.text);
}
