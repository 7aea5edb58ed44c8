#include "granlub/automaton/sampler.h"

#include <algorithm>

namespace granlub::automaton {

Sampler::Sampler(int rows, int columns, const RunSpec& run)
    : rows_(rows), columns_(columns), run_(run),
      n_(rows, 0), s_(rows, 0), s2_(rows, 0), x_(rows, 0), x2_(rows, 0), kin_(rows, 0) {
    blocks_.reserve(static_cast<std::size_t>(run.steps / run.block) + 1);
    if (run.timeseries_every > 0)
        series_.reserve(static_cast<std::size_t>(run.steps / run.timeseries_every) + 1);
}

void Sampler::close_block(std::int64_t start, const Counters& now, std::size_t grains) {
    Block b;
    b.start = start;
    b.up.assign(rows_, 0);
    b.ux.assign(rows_, 0);
    b.ukin.assign(rows_, 0);
    b.var_up.assign(rows_, 0);
    b.var_ux.assign(rows_, 0);
    b.nu.assign(rows_, 0);
    b.has.assign(rows_, false);
    double total = 0, count = 0;
    for (int r = 0; r < rows_; ++r) {
        const double n = n_[r];
        total += s_[r];
        count += n;
        b.nu[r] = samples_ > 0 ? n / (static_cast<double>(columns_) * static_cast<double>(samples_)) : 0;
        if (n <= 0) continue;
        b.has[r] = true;
        b.up[r] = s_[r] / n;
        b.ux[r] = x_[r] / n;
        b.ukin[r] = kin_[r] / n;
        b.var_up[r] = std::max(s2_[r] / n - b.up[r] * b.up[r], 0.0);
        b.var_ux[r] = std::max(x2_[r] / n - b.ux[r] * b.ux[r], 0.0);
    }
    b.mean_up = count > 0 ? total / count : 0;
    const double per = 1.0 / (static_cast<double>(run_.block) * columns_);  // per step per column
    b.tangential_bottom = (now.tangential_bottom - at_block_start_.tangential_bottom) * per;
    b.tangential_top = (now.tangential_top - at_block_start_.tangential_top) * per;
    b.normal_bottom = (now.normal_bottom - at_block_start_.normal_bottom) * per;
    b.normal_top = (now.normal_top - at_block_start_.normal_top) * per;
    const double grain_steps = static_cast<double>(run_.block) * static_cast<double>(std::max<std::size_t>(grains, 1));
    b.moves = static_cast<double>(now.moves - at_block_start_.moves) / grain_steps;
    b.pp = static_cast<double>(now.pp - at_block_start_.pp) / grain_steps;
    b.wall_bottom = static_cast<double>(now.wall_bottom - at_block_start_.wall_bottom) / grain_steps;
    b.wall_top = static_cast<double>(now.wall_top - at_block_start_.wall_top) / grain_steps;
    b.exhausted = static_cast<double>(now.exhausted - at_block_start_.exhausted) / grain_steps;
    blocks_.push_back(std::move(b));
    at_block_start_ = now;
    std::fill(n_.begin(), n_.end(), 0);
    std::fill(s_.begin(), s_.end(), 0);
    std::fill(s2_.begin(), s2_.end(), 0);
    std::fill(x_.begin(), x_.end(), 0);
    std::fill(x2_.begin(), x2_.end(), 0);
    std::fill(kin_.begin(), kin_.end(), 0);
    samples_ = 0;
}

}  // namespace granlub::automaton
