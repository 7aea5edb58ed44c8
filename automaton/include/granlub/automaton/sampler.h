// Measurements of one replica (docs/automaton-model.md §4.2-4.4): per-row sums of every sampled step,
// closed into blocks of `block` steps counted from step 0. Blocks serve both the steady-state
// test (all blocks) and the averages with standard errors (blocks inside the sampling window).
#pragma once
#include <cstdint>
#include <vector>

#include "granlub/automaton/engine.h"
#include "granlub/automaton/params.h"

namespace granlub::automaton {

// Averages over one block of steps; per-row vectors have `rows` entries.
struct Block {
    std::int64_t start = 0;              // first step of the block
    std::vector<double> up;              // <u_p>/U per row (JH06's velocity, §4.1)
    std::vector<double> ux;              // <u_p dx>/U per row (directional; vector-mode velocity)
    std::vector<double> ukin;            // streamwise lattice displacement per grain-step, per row
    std::vector<double> var_up;          // variance of u_p per row (temperature analogue)
    std::vector<double> var_ux;          // variance of u_p dx per row
    std::vector<double> nu;              // occupancy per row
    std::vector<bool> has;               // row held a grain in this block
    double mean_up = 0;                  // <u_p> over all grains
    // Wall momentum per step per lattice column, lattice units (grain mass x U per step per cell).
    double tangential_bottom = 0, tangential_top = 0, normal_bottom = 0, normal_top = 0;
    double moves = 0, pp = 0, wall_bottom = 0, wall_top = 0, exhausted = 0;  // per grain-step
};

struct TimePoint {
    std::int64_t step = 0;
    double mean_up = 0, u_bottom_row = 0, u_top_row = 0;  // <u_p>/U overall, row 0, row H-1
};

class Sampler {
public:
    Sampler(int rows, int columns, const RunSpec& run);
    // Call after every step t (0-based) with the engine state after that step.
    template <class Rng>
    void after_step(std::int64_t t, Engine<Rng>& e);
    const std::vector<Block>& blocks() const { return blocks_; }
    const std::vector<TimePoint>& timeseries() const { return series_; }

private:
    void close_block(std::int64_t start, const Counters& now, std::size_t grains);
    int rows_, columns_;
    RunSpec run_;
    std::vector<double> n_, s_, s2_, x_, x2_, kin_;
    std::int64_t samples_ = 0;
    Counters at_block_start_;
    std::vector<Block> blocks_;
    std::vector<TimePoint> series_;
};

template <class Rng>
void Sampler::after_step(std::int64_t t, Engine<Rng>& e) {
    auto& kin = e.kin();
    const bool sample = t % run_.sample_every == 0;
    const bool series = run_.timeseries_every > 0 && t % run_.timeseries_every == 0;
    if (sample || series) {
        const auto& cells = e.cells();
        const auto& up = e.speeds();
        const auto& dir = e.dirs();
        std::vector<double>& n = n_;
        if (sample) {
            for (std::size_t i = 0; i < cells.size(); ++i) {
                const int r = e.row_of(cells[i]);
                const double u = up[i], ux = u * kDx[dir[i]];
                n[r] += 1;
                s_[r] += u;
                s2_[r] += u * u;
                x_[r] += ux;
                x2_[r] += ux * ux;
            }
            for (int r = 0; r < rows_; ++r) kin_[r] += static_cast<double>(kin[r]);
            ++samples_;
        }
        if (series) {
            double total = 0, b = 0, nb = 0, tp = 0, nt = 0;
            for (std::size_t i = 0; i < cells.size(); ++i) {
                const int r = e.row_of(cells[i]);
                total += up[i];
                if (r == 0) { b += up[i]; nb += 1; }
                if (r == rows_ - 1) { tp += up[i]; nt += 1; }
            }
            series_.push_back({t, cells.empty() ? 0 : total / static_cast<double>(cells.size()),
                               nb > 0 ? b / nb : 0, nt > 0 ? tp / nt : 0});
        }
    }
    std::fill(kin.begin(), kin.end(), 0);
    if ((t + 1) % run_.block == 0) close_block(t + 1 - run_.block, e.counters(), e.size());
}

}  // namespace granlub::automaton
