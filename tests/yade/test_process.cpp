// The process runner: exit codes, logs, timeouts, programs that cannot start.
#define BOOST_TEST_MODULE yade_process
#include <boost/test/unit_test.hpp>

#include "granlub/error.h"
#include "granlub/yade/process.h"
#include "yade_test_case.h"

using namespace granlub;
using namespace granlub::yade;
using granlub::yade::test::read_text;
using granlub::yade::test::scratch;

BOOST_AUTO_TEST_CASE(finds_programs_on_the_path) {
    const auto sh = find_executable("sh");
    BOOST_TEST_REQUIRE(sh.has_value());
    BOOST_TEST(sh->is_absolute());
    BOOST_TEST(!find_executable("granlub-no-such-program").has_value());
    BOOST_TEST(!find_executable("/nonexistent/yade").has_value());
    BOOST_TEST(find_executable(sh->string()).has_value());
}

BOOST_AUTO_TEST_CASE(exit_code_and_log) {
    const auto dir = scratch("process-exit");
    const auto log = dir / "run.log";
    const ProcessResult r = run_process({"/bin/sh", "-c", "echo to-stdout; echo to-stderr >&2; pwd; exit 3"}, dir, log, 30);
    BOOST_TEST(r.exit_code == 3);
    BOOST_TEST(!r.timed_out);
    BOOST_TEST(r.signal == 0);
    BOOST_TEST(r.describe() == "exit code 3");
    const std::string text = read_text(log);
    BOOST_TEST(text.find("to-stdout") != std::string::npos);
    BOOST_TEST(text.find("to-stderr") != std::string::npos);
    BOOST_TEST(text.find(dir.filename().string()) != std::string::npos);  // ran in `dir`
    BOOST_TEST(tail_lines(log, 1).find(dir.filename().string()) != std::string::npos);
}

BOOST_AUTO_TEST_CASE(timeout_kills_the_process_group) {
    const auto dir = scratch("process-timeout");
    int polls = 0;
    const ProcessResult r = run_process({"/bin/sh", "-c", "sleep 30 & sleep 30"}, dir, dir / "run.log", 0.6,
                                        [&] { ++polls; });
    BOOST_TEST(r.timed_out);
    BOOST_TEST(r.seconds < 10.0);
    BOOST_TEST(polls > 0);
    BOOST_TEST(r.describe().find("timed out") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(missing_program_is_a_solver_error) {
    const auto dir = scratch("process-missing");
    try {
        run_process({"/nonexistent/yade", "-x"}, dir, dir / "run.log", 5);
        BOOST_FAIL("expected SolverError");
    } catch (const SolverError& e) {
        BOOST_TEST(std::string(e.what()).find("/nonexistent/yade") != std::string::npos);
    }
}
