// Until steady, with a cap (granlub/particles/until_steady.h): the run doubles until a piece is steady or
// the next piece would pass the cap, and the record says what was continued, counts the steady
// start from the run's start and names the cap in a transient's hint.
#include <vector>

#include <boost/test/unit_test.hpp>

#include "granlub/results/run_status.h"
#include "granlub/particles/until_steady.h"

using namespace granlub;

BOOST_AUTO_TEST_SUITE(until_steady)

BOOST_AUTO_TEST_CASE(the_run_doubles_until_steady_or_the_cap) {
    BOOST_TEST(next_piece(true, 1, 8) == 0);    // steady: done
    BOOST_TEST(next_piece(false, 1, 0) == 0);   // no cap: one run
    BOOST_TEST(next_piece(false, 1, 1) == 0);   // a cap of one run length leaves no room
    BOOST_TEST(next_piece(false, 1, 2) == 1);   // 1 + 1
    BOOST_TEST(next_piece(false, 2, 8) == 2);   // 2 + 2
    BOOST_TEST(next_piece(false, 4, 8) == 4);   // 4 + 4 = the cap
    BOOST_TEST(next_piece(false, 8, 8) == 0);   // at the cap
    BOOST_TEST(next_piece(false, 4, 7) == 0);   // 4 + 4 would pass 7: no shorter last piece
    // the pieces of a run that never becomes steady under a cap of 8 lengths: 1, 1, 2, 4
    std::int64_t done = 1, pieces = 1;
    while (const std::int64_t next = next_piece(false, done, 8)) done += next, ++pieces;
    BOOST_TEST(done == 8);
    BOOST_TEST(pieces == 4);
}

// The loop both engines run, with pieces that report what a fake engine decides.
BOOST_AUTO_TEST_CASE(the_loop_runs_doubling_pieces_until_steady) {
    const UntilSteadyCap cap{.time_max = 0.8, .key = "[dem] time_max"};
    std::vector<std::int64_t> asked;
    std::vector<int> indices;
    const Continuation k = continue_until_steady(cap, 0.1, "test", [&](std::int64_t times, int index) {
        asked.push_back(times), indices.push_back(index);
        return PieceRun{index == 2, 0.1 * static_cast<double>(times)};  // steady in the third piece
    });
    BOOST_TEST(asked == (std::vector<std::int64_t>{1, 1, 2}), boost::test_tools::per_element());
    BOOST_TEST(indices == (std::vector<int>{0, 1, 2}), boost::test_tools::per_element());
    BOOST_TEST(k.pieces == 3);
    BOOST_TEST(k.earlier_s == 0.2, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(k.last_s == 0.2, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(k.cap_key == "[dem] time_max");
    // never steady: stops at the cap (1 + 1 + 2 + 4 = 8 lengths), and without a cap after one run
    const Continuation capped = continue_until_steady(cap, 0.1, "test", [](std::int64_t times, int) {
        return PieceRun{false, 0.1 * static_cast<double>(times)};
    });
    BOOST_TEST(capped.pieces == 4);
    BOOST_TEST(capped.earlier_s + capped.last_s == 0.8, boost::test_tools::tolerance(1e-12));
    int runs = 0;
    const Continuation off = continue_until_steady({}, 0.1, "test", [&](std::int64_t, int) {
        ++runs;
        return PieceRun{false, 0.1};
    });
    BOOST_TEST(runs == 1);
    BOOST_TEST(off.pieces == 1);
}

BOOST_AUTO_TEST_CASE(a_steady_last_piece_keeps_its_status_and_counts_from_the_run_start) {
    nlohmann::json run = {{"steady_state_detected", true}, {"steady_state_start_s", 0.02}};
    set_regime(run, RegimeStatus::Steady);
    record_continuation(run, {.pieces = 2, .earlier_s = 0.1, .last_s = 0.1, .time_max_s = 0.8});
    BOOST_TEST(run.at("steady_state_start_s").get<double>() == 0.12, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(run.at("continuation").at("simulated_s").get<double>() == 0.2, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(run.at("continuation").at("pieces").get<int>() == 2);
    BOOST_TEST(read_regime(run).steady());
    const std::string note = continuation_note({.pieces = 2, .earlier_s = 0.1, .last_s = 0.1});
    BOOST_TEST(note.find("the last 0.1 s of 0.2 s") != std::string::npos, note);
    BOOST_TEST(continuation_note({}).empty());  // one piece: nothing to add
}

BOOST_AUTO_TEST_CASE(a_capped_transient_names_the_cap) {
    nlohmann::json run = {{"steady_state_detected", false}, {"steady_state_start_s", 0.0}};
    set_regime(run, RegimeStatus::Transient, "no steady state detected: run longer");
    record_continuation(run, {.pieces = 4, .earlier_s = 0.4, .last_s = 0.4, .time_max_s = 0.8,
                              .cap_key = "[dem] time_max_full"});
    const Regime r = read_regime(run);
    BOOST_TEST((r.status == RegimeStatus::Transient));
    BOOST_TEST(r.reason.find("0.8 s of simulated time") != std::string::npos, r.reason);
    BOOST_TEST(r.reason.find("raise [dem] time_max_full") != std::string::npos, r.reason);
}

BOOST_AUTO_TEST_SUITE_END()
