#include "granlub/automaton/ensemble.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <thread>

#include "granlub/automaton/invariants.h"
#include "granlub/error.h"

namespace granlub::automaton {

Lattice make_lattice(const Params& p, int replica) {
    const auto r = static_cast<std::uint64_t>(replica);
    Lattice e(p.lattice.columns, p.lattice.rows, p.rules, Philox(p.run.seed, order_stream(r)),
              Philox(p.run.seed, rules_stream(r)));
    e.fill_random(p.lattice);
    return e;
}

namespace {

// Least-squares line u = a + b eta through rows 1..H-2 (docs/automaton-model.md §4.3); returns {1 - a, a + b}.
std::pair<double, double> fit_slips(const std::vector<double>& u, int rows) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
    for (int r = 1; r <= rows - 2; ++r) {
        const double eta = (r + 0.5) / rows;
        sx += eta; sy += u[r]; sxx += eta * eta; sxy += eta * u[r]; n += 1;
    }
    const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    const double a = (sy - b * sx) / n;
    return {1.0 - a, a + b};
}

struct ReplicaOut {
    std::vector<Block> blocks;
    std::vector<TimePoint> series;
    Counters counters;
};

}  // namespace

SteadyState steady_state(const RunSpec& run, const std::vector<Block>& blocks) {
    SteadyState s;
    const int need = run.steady_pairs;
    int passing = 0;
    for (std::size_t b = 1; b < blocks.size(); ++b) {
        double du = 0, dnu = 0;
        for (std::size_t r = 0; r < blocks[b].up.size(); ++r) {
            dnu = std::max(dnu, std::abs(blocks[b].nu[r] - blocks[b - 1].nu[r]));
            if (blocks[b].has[r] && blocks[b - 1].has[r])
                du = std::max(du, std::abs(blocks[b].up[r] - blocks[b - 1].up[r]));
        }
        passing = (du < run.steady_tol_u && dnu < run.steady_tol_nu) ? passing + 1 : 0;
        if (passing == need) {
            s.step = blocks[b - static_cast<std::size_t>(need)].start;
            break;
        }
    }
    // Drift: slope of a line through <u_p> of the last 5 blocks (§4.4).
    if (blocks.size() >= 5) {
        const std::size_t first = blocks.size() - 5;
        double sy = 0, sxy = 0;
        for (std::size_t k = 0; k < 5; ++k) {
            const double xk = static_cast<double>(k) - 2.0;
            sy += blocks[first + k].mean_up;
            sxy += xk * blocks[first + k].mean_up;
        }
        s.drift = std::abs(sxy / 10.0);
    }
    if (s.step < 0)
        s.note = blocks.size() < static_cast<std::size_t>(need + 1)
                     ? "run too short for the block test (" + std::to_string(blocks.size()) + " blocks, need " +
                           std::to_string(need + 1) + ")"
                 : passing > 0 ? "only the last " + std::to_string(passing) + " block pair(s) agreed (need " +
                                     std::to_string(need) + "): run longer"
                               : "consecutive blocks never agreed within the tolerances";
    else if (s.step > run.t_avg_start)
        s.note = "steady only from step " + std::to_string(s.step) + ", after t_avg_start = " +
                 std::to_string(run.t_avg_start);
    else if (blocks.size() >= 5 && s.drift >= run.drift_tol)
        s.note = "<u_p> drifts by " + std::to_string(s.drift) + " U per block over the last 5 blocks";
    s.reached = s.note.empty();
    return s;
}

EnsembleResult pool(const Params& p, const std::vector<std::vector<Block>>& blocks) {
    const int H = p.lattice.rows;
    EnsembleResult out;
    out.rows = H;
    out.columns = p.lattice.columns;
    out.particles = p.lattice.particles();
    out.replicas = static_cast<int>(blocks.size());
    const bool vec = p.rules.mode == Mode::Vector;

    std::vector<const Block*> win;  // window blocks of every replica, in replica order
    for (const auto& rb : blocks)
        for (const auto& b : rb)
            if (b.start >= p.run.t_avg_start) win.push_back(&b);
    out.window_blocks = static_cast<std::int64_t>(win.size());

    auto row_stat = [&](auto field, int r, bool needs_grains) {
        std::vector<double> v;
        v.reserve(win.size());
        for (const Block* b : win)
            if (!needs_grains || b->has[r]) v.push_back(field(*b)[r]);
        return mean_and_stderr(v);
    };
    auto scalar = [&](auto field) {
        std::vector<double> v;
        v.reserve(win.size());
        for (const Block* b : win) v.push_back(field(*b));
        return mean_and_stderr(v);
    };
    auto& R = out.rows_;
    for (int r = 0; r < H; ++r) {
        R.up.push_back(row_stat([](const Block& b) -> const auto& { return b.up; }, r, true));
        R.ux.push_back(row_stat([](const Block& b) -> const auto& { return b.ux; }, r, true));
        R.ukin.push_back(row_stat([](const Block& b) -> const auto& { return b.ukin; }, r, true));
        R.nu.push_back(row_stat([](const Block& b) -> const auto& { return b.nu; }, r, false));
        R.temp.push_back(vec ? row_stat([](const Block& b) -> const auto& { return b.var_ux; }, r, true)
                             : row_stat([](const Block& b) -> const auto& { return b.var_up; }, r, true));
    }
    R.u = vec ? R.ux : R.up;

    // Slips per block, then mean and standard error (§4.3).
    auto vel = [vec](const Block& b) -> const std::vector<double>& { return vec ? b.ux : b.up; };
    out.slip_bottom = scalar([&](const Block& b) { return 1.0 - vel(b)[0]; });
    out.slip_top = scalar([&](const Block& b) { return vel(b)[static_cast<std::size_t>(H - 1)]; });
    out.has_fit = H >= 4;
    if (out.has_fit) {
        out.slip_bottom_fit = scalar([&](const Block& b) { return fit_slips(vel(b), H).first; });
        out.slip_top_fit = scalar([&](const Block& b) { return fit_slips(vel(b), H).second; });
    }
    out.tangential_bottom = scalar([](const Block& b) { return b.tangential_bottom; });
    out.tangential_top = scalar([](const Block& b) { return b.tangential_top; });
    out.normal_bottom = scalar([](const Block& b) { return b.normal_bottom; });
    out.normal_top = scalar([](const Block& b) { return b.normal_top; });
    out.mean_up = scalar([](const Block& b) { return b.mean_up; });
    out.moves = scalar([](const Block& b) { return b.moves; });
    out.pp = scalar([](const Block& b) { return b.pp; });
    out.wall_bottom = scalar([](const Block& b) { return b.wall_bottom; });
    out.wall_top = scalar([](const Block& b) { return b.wall_top; });
    out.exhausted = scalar([](const Block& b) { return b.exhausted; });

    // Steady state: every replica must pass (§4.4); report the latest onset and largest drift.
    out.steady.reached = !blocks.empty();
    bool all_onsets = true;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        const SteadyState s = steady_state(p.run, blocks[k]);
        all_onsets = all_onsets && s.step >= 0;
        out.steady.step = all_onsets ? std::max(out.steady.step, s.step) : -1;
        out.steady.drift = std::max(out.steady.drift, s.drift);
        if (!s.reached && out.steady.reached) {
            out.steady.reached = false;
            out.steady.note = "replica " + std::to_string(k) + ": " + s.note;
        }
    }
    return out;
}

namespace {

// One replica's lattice and sampler, kept between the runs of the §4.5 protocol.
struct Replica {
    Lattice lattice;
    Sampler sampler;
};

// Advances every replica from step `from` to step `to` in `threads` threads (replica r only
// depends on (seed, r), so the thread count never changes the numbers). Reports progress as
// `done_before` + steps done here, out of `total`.
void advance(const Params& p, const RunSpec& sampler_run, std::vector<std::unique_ptr<Replica>>& reps,
             std::int64_t from, std::int64_t to, int threads, const Observer& observer,
             std::uint64_t done_before, std::uint64_t total) {
    const int replicas = static_cast<int>(reps.size());
    std::atomic<int> next{0};
    std::atomic<std::uint64_t> steps_done{0};
    std::atomic<int> finished{0};
    std::exception_ptr error;
    std::atomic<bool> failed{false};

    auto work = [&] {
        for (int r = next++; r < replicas && !failed; r = next++) {
            try {
                auto& slot = reps[static_cast<std::size_t>(r)];
                if (!slot) slot.reset(new Replica{make_lattice(p, r), Sampler(p.lattice.rows, p.lattice.columns, sampler_run)});
                Lattice& e = slot->lattice;
                Sampler& s = slot->sampler;
                const bool snap = r == 0 && observer.snapshot && p.run.snapshot_every > 0;
                if (snap && from == 0) observer.snapshot(0, e);
                std::uint64_t pending = 0;
                for (std::int64_t t = from; t < to; ++t) {
                    e.step();
                    s.after_step(t, e);
#ifndef NDEBUG
                    if (t % 100 == 0) {
                        const std::string bad = check_invariants(e);
                        if (!bad.empty()) throw Error("automaton invariant broken at step " + std::to_string(t) + ": " + bad);
                    }
#endif
                    if (snap && (t + 1) % p.run.snapshot_every == 0) observer.snapshot(t + 1, e);
                    if (++pending == 64) {
                        steps_done += pending;
                        pending = 0;
                    }
                    if (failed) return;
                }
                steps_done += pending;
            } catch (...) {
                if (!failed.exchange(true)) error = std::current_exception();
            }
        }
        ++finished;
    };

    std::vector<std::thread> pool_threads;
    for (int k = 0; k < threads; ++k) pool_threads.emplace_back(work);
    if (observer.progress) {
        while (finished.load() < threads) {
            observer.progress(done_before + steps_done.load(), total);
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
    }
    for (auto& t : pool_threads) t.join();
    if (error) std::rethrow_exception(error);
}

std::vector<std::vector<Block>> blocks_of(const std::vector<std::unique_ptr<Replica>>& reps) {
    std::vector<std::vector<Block>> blocks;
    for (const auto& r : reps) blocks.push_back(r->sampler.blocks());
    return blocks;
}

// The parameters of run T of the §4.5 protocol: T steps, read over their second half [ASSUMPTION].
Params run_of_length(const Params& p, std::int64_t T) {
    Params q = p;
    q.run.steps = T;
    q.run.t_avg_start = T / 2;
    return q;
}

// max_y |a - b| and its row.
std::pair<double, int> max_diff(const std::vector<Stat>& a, const std::vector<Stat>& b) {
    std::pair<double, int> m{0.0, -1};
    for (std::size_t r = 0; r < a.size(); ++r) {
        const double d = std::abs(a[r].mean - b[r].mean);
        if (m.second < 0 || d > m.first) m = {d, static_cast<int>(r)};
    }
    return m;
}

}  // namespace

EnsembleResult run_ensemble(const Params& p, const Observer& observer) {
    validate(p);
    const int replicas = p.run.replicas;
    const int hw = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    const int threads = std::clamp(p.run.threads > 0 ? p.run.threads : hw, 1, replicas);
    const bool by_runs = p.run.steady_protocol == SteadyProtocol::Runs;
    RunSpec sampler_run = p.run;  // sizes the sampler's reservations
    if (by_runs) sampler_run.steps = p.run.runs_max_steps;
    std::vector<std::unique_ptr<Replica>> reps(static_cast<std::size_t>(replicas));
    const std::uint64_t total = static_cast<std::uint64_t>(sampler_run.steps) * static_cast<std::uint64_t>(replicas);
    const auto t0 = std::chrono::steady_clock::now();

    EnsembleResult res;
    if (!by_runs) {
        advance(p, sampler_run, reps, 0, p.run.steps, threads, observer, 0, total);
        res = pool(p, blocks_of(reps));
    } else {
        // JH06 (§4.5): run T_1 < T_2 < ... and stop when consecutive readings match. A run of T
        // steps is the first T steps of a longer run with the same seed, so run T_k continues run
        // T_(k-1) instead of restarting: same numbers, half the cost.
        RunsProtocol rp;
        rp.used = true;
        std::int64_t T = p.run.runs_start;
        advance(p, sampler_run, reps, 0, T, threads, observer, 0, total);
        rp.lengths.push_back(T);
        EnsembleResult prev = pool(run_of_length(p, T), blocks_of(reps));
        while (true) {
            if (2 * T > p.run.runs_max_steps) {
                rp.note = "no two consecutive runs agreed within runs_max_steps = " + std::to_string(p.run.runs_max_steps);
                break;
            }
            advance(p, sampler_run, reps, T, 2 * T, threads, observer,
                    static_cast<std::uint64_t>(T) * static_cast<std::uint64_t>(replicas), total);
            T *= 2;
            rp.lengths.push_back(T);
            EnsembleResult cur = pool(run_of_length(p, T), blocks_of(reps));
            const auto [du, du_row] = max_diff(cur.rows_.u, prev.rows_.u);
            const auto [dnu, dnu_row] = max_diff(cur.rows_.nu, prev.rows_.nu);
            rp.du.push_back(du);
            rp.dnu.push_back(dnu);
            rp.du_row = du_row;
            rp.dnu_row = dnu_row;
            prev = std::move(cur);
            if (du < p.run.runs_tol_u && dnu < p.run.runs_tol_nu) {
                rp.converged = true;
                break;
            }
        }
        res = std::move(prev);
        res.steady.reached = rp.converged;
        res.steady.step = rp.converged ? T / 2 : -1;
        res.steady.note = rp.note;
        res.runs = std::move(rp);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    res.threads = threads;
    std::vector<ReplicaOut> outs;
    for (const auto& r : reps) outs.push_back({{}, r->sampler.timeseries(), r->lattice.counters()});
    for (const auto& o : outs) {
        const Counters& c = o.counters;
        res.totals.visits += c.visits; res.totals.moves += c.moves; res.totals.pp += c.pp;
        res.totals.wall_bottom += c.wall_bottom; res.totals.wall_top += c.wall_top;
        res.totals.exhausted += c.exhausted;
        res.totals.tangential_bottom += c.tangential_bottom; res.totals.tangential_top += c.tangential_top;
        res.totals.normal_bottom += c.normal_bottom; res.totals.normal_top += c.normal_top;
    }
    if (!outs.empty()) {  // ensemble-mean time series
        res.timeseries = outs[0].series;
        for (std::size_t k = 0; k < res.timeseries.size(); ++k) {
            TimePoint& tp = res.timeseries[k];
            tp.mean_up = tp.u_bottom_row = tp.u_top_row = 0;
            for (const auto& o : outs) {
                tp.mean_up += o.series[k].mean_up;
                tp.u_bottom_row += o.series[k].u_bottom_row;
                tp.u_top_row += o.series[k].u_top_row;
            }
            const double n = static_cast<double>(outs.size());
            tp.mean_up /= n; tp.u_bottom_row /= n; tp.u_top_row /= n;
        }
    }
    res.wall_seconds = seconds;
    res.updates_per_second = seconds > 0 ? static_cast<double>(res.totals.visits) / seconds : 0;
    return res;
}

}  // namespace granlub::automaton
