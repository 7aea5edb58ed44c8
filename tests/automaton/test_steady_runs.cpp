// JH06's literal steady-state protocol (docs/automaton-model.md §4.5, [automaton] steady_state = "runs"):
// it converges on the JH06 default lattice, its profile agrees with the block protocol's (§4.4)
// within the measured standard errors, and a tight step limit gives a clear failure.
#define BOOST_TEST_MODULE automaton_steady_runs
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "granlub/automaton/ensemble.h"
#include "granlub/error.h"

using namespace granlub::automaton;

namespace {

// The JH06 default lattice (10 x 100, fill 0.85, e_p 0.85, e_w 0.65, R 0.65) by the runs protocol.
Params runs(std::uint64_t seed = 1) {
    Params p;
    p.run.replicas = 4;
    p.run.seed = seed;
    p.run.steady_protocol = SteadyProtocol::Runs;
    return p;
}

// |a - b| within 5 combined standard errors (the suite's convention, test_statistics.cpp).
void agree(const std::string& what, const Stat& a, const Stat& b) {
    const double tol = 5 * std::hypot(a.stderr_, b.stderr_);
    BOOST_TEST_MESSAGE(what << ": runs " << a.mean << " +- " << a.stderr_ << ", blocks " << b.mean << " +- "
                            << b.stderr_);
    BOOST_CHECK_MESSAGE(a.stderr_ > 0 && b.stderr_ > 0 && std::abs(a.mean - b.mean) <= tol,
                        what << ": runs " << a.mean << " +- " << a.stderr_ << " vs blocks " << b.mean << " +- "
                             << b.stderr_ << " (tolerance " << tol << ")");
}

}  // namespace

BOOST_AUTO_TEST_CASE(converges_on_the_jh06_lattice_and_agrees_with_the_block_protocol) {
    const Params p = runs();
    const EnsembleResult r = run_ensemble(p);
    const RunsProtocol& rp = r.runs;
    BOOST_TEST(rp.used);
    BOOST_TEST(rp.converged);
    BOOST_REQUIRE(rp.lengths.size() >= 2u);
    BOOST_TEST(rp.lengths.front() == p.run.runs_start);
    for (std::size_t k = 1; k < rp.lengths.size(); ++k) BOOST_TEST(rp.lengths[k] == 2 * rp.lengths[k - 1]);
    BOOST_TEST(rp.du.size() == rp.lengths.size() - 1);
    BOOST_TEST(rp.du.back() < p.run.runs_tol_u);
    BOOST_TEST(rp.dnu.back() < p.run.runs_tol_nu);
    // §4.5: the transient is ~100 steps; needing more than 2000 steps would indicate a bug.
    BOOST_TEST(rp.lengths.back() <= 2000);
    BOOST_TEST(r.steady.reached);
    BOOST_TEST(r.steady.step == rp.lengths.back() / 2);  // read over the last run's second half
    BOOST_TEST(r.window_blocks == p.run.replicas * (rp.lengths.back() / 2 / p.run.block));

    // The block protocol (§4.4, cheap CI variant of §7.2) on an independent seed.
    Params b;
    b.run.steps = 3000;
    b.run.t_avg_start = 1000;
    b.run.replicas = 4;
    b.run.seed = 2;
    const EnsembleResult rb = run_ensemble(b);
    BOOST_TEST(rb.steady.reached);
    BOOST_REQUIRE(r.rows_.u.size() == rb.rows_.u.size());
    for (std::size_t y = 0; y < r.rows_.u.size(); ++y) {
        agree("u/U row " + std::to_string(y), r.rows_.u[y], rb.rows_.u[y]);
        agree("occupancy row " + std::to_string(y), r.rows_.nu[y], rb.rows_.nu[y]);
    }
    agree("slip bottom", r.slip_bottom, rb.slip_bottom);
    agree("slip top", r.slip_top, rb.slip_top);
}

BOOST_AUTO_TEST_CASE(same_numbers_for_any_thread_count) {
    Params p = runs(7);
    p.run.threads = 1;
    const EnsembleResult a = run_ensemble(p);
    p.run.threads = 3;
    const EnsembleResult b = run_ensemble(p);
    BOOST_TEST(a.runs.lengths == b.runs.lengths);
    BOOST_TEST(a.runs.du == b.runs.du);
    for (std::size_t y = 0; y < a.rows_.u.size(); ++y) BOOST_TEST(a.rows_.u[y].mean == b.rows_.u[y].mean);
}

BOOST_AUTO_TEST_CASE(a_tight_step_limit_fails_clearly) {
    // Runs of 20, 40, 80 steps still read the transient (<u_p> rises for ~60-100 steps, §4.4).
    Params p = runs();
    p.run.block = 10;
    p.run.t_avg_start = 0;
    p.run.runs_start = 20;
    p.run.runs_max_steps = 80;
    const EnsembleResult r = run_ensemble(p);
    const RunsProtocol& rp = r.runs;
    BOOST_TEST(!rp.converged);
    BOOST_TEST(!r.steady.reached);
    BOOST_TEST((rp.lengths == std::vector<std::int64_t>{20, 40, 80}));
    BOOST_REQUIRE(rp.du.size() == 2u);
    BOOST_TEST((rp.du.back() >= p.run.runs_tol_u || rp.dnu.back() >= p.run.runs_tol_nu));
    std::string msg;
    try {
        require_converged("U2.0_R0.65", p, rp);
    } catch (const granlub::SolverError& e) {
        msg = e.what();
    }
    BOOST_TEST_MESSAGE(msg);
    for (const char* part : {"point U2.0_R0.65", "steady_state = \"runs\"", "did not converge", "20, 40, 80",
                             "runs_max_steps = 80", "last max |du| =", "between the runs of 40 and 80 steps",
                             "Try: a larger runs_max_steps"})
        BOOST_TEST(msg.find(part) != std::string::npos, part << " in: " << msg);
    // The differences in the message are the measured ones.
    char du[32];
    std::snprintf(du, sizeof du, "%.4f U", rp.du.back());
    BOOST_TEST(msg.find(du) != std::string::npos, msg);

    // A long enough limit converges from the same start.
    p.run.runs_max_steps = 2000;
    const EnsembleResult ok = run_ensemble(p);
    BOOST_TEST(ok.runs.converged);
    BOOST_TEST(ok.runs.lengths.back() > 80);
    BOOST_CHECK_NO_THROW(require_converged("U2.0_R0.65", p, ok.runs));
}

BOOST_AUTO_TEST_CASE(bad_parameters_are_rejected) {
    auto message = [](const Params& p) {
        try {
            validate(p);
        } catch (const granlub::Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    Params p = runs();
    BOOST_TEST(message(p) == "");
    p.run.runs_start = 700;  // not a multiple of 2 x block = 1000
    std::string m = message(p);
    BOOST_TEST(m.find("runs_start = 700") != std::string::npos, m);
    BOOST_TEST(m.find("multiple of 2 x block = 1000") != std::string::npos, m);
    p = runs();
    p.run.runs_max_steps = 1500;
    m = message(p);
    BOOST_TEST(m.find("runs_max_steps = 1500") != std::string::npos, m);
    BOOST_TEST(m.find("at least 2 x runs_start = 2000") != std::string::npos, m);
    p = runs();
    p.run.runs_tol_nu = 0;
    m = message(p);
    BOOST_TEST(m.find("runs_tol_nu") != std::string::npos, m);
}
