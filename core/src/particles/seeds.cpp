// A particle point's set of seeds and the sweep over its members (seeds.h).
#include "granlub/particles/seeds.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "granlub/error.h"
#include "granlub/particles/seed_pool.h"

namespace granlub {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSeedsAllowed =
    "a whole number of seeds from 1 to 1000, or a comma-separated list of distinct whole numbers, e.g. --seeds 6 or "
    "--seeds 1,2,7";

// A whole number written with digits only (no sign, no spaces, no exponent).
std::optional<std::uint64_t> whole(std::string_view t) {
    std::uint64_t v = 0;
    const char* end = t.data() + t.size();
    const auto [ptr, ec] = std::from_chars(t.data(), end, v);
    if (t.empty() || ec != std::errc() || ptr != end || v > static_cast<std::uint64_t>(INT64_MAX)) return std::nullopt;
    return v;
}

[[noreturn]] void bad_flag(const std::string& text, const std::string& why) {
    throw CaseError(fmt::format("--seeds {}: {} (allowed: {})", text, why, kSeedsAllowed));
}

// --seeds N|LIST: a count (no comma) or the seeds themselves.
struct Given {
    std::optional<std::uint64_t> count;
    std::vector<std::uint64_t> list;
};

Given parse_flag(const std::string& text) {
    Given g;
    if (text.find(',') == std::string::npos) {
        const auto n = whole(text);
        if (!n) bad_flag(text, "not a whole number");
        if (*n < 1 || *n > kMaxIntegerList) bad_flag(text, "out of range");
        g.count = *n;
        return g;
    }
    std::size_t from = 0;
    while (from <= text.size()) {
        const std::size_t comma = std::min(text.find(',', from), text.size());
        const std::string item = text.substr(from, comma - from);
        const auto v = whole(item);
        if (!v) bad_flag(text, fmt::format("'{}' is not a whole number", item));
        if (std::find(g.list.begin(), g.list.end(), *v) != g.list.end())
            bad_flag(text, fmt::format("{} appears twice", *v));
        g.list.push_back(*v);
        if (g.list.size() > kMaxIntegerList) bad_flag(text, fmt::format("more than {} seeds", kMaxIntegerList));
        from = comma + 1;
    }
    return g;
}

Given from_case(const Section& s) {
    Given g;
    if (const auto* l = s.integers("seeds"))
        for (const std::int64_t v : *l) g.list.push_back(static_cast<std::uint64_t>(v));
    else
        g.count = static_cast<std::uint64_t>(s.integer("seeds"));
    return g;
}

}  // namespace

SeedSet seed_set(const Case& c, const RunOptions& o) {
    const Section& s = c.section(kParticlesSection);
    const Given g = o.seeds.empty() ? from_case(s) : parse_flag(o.seeds);
    const auto base = static_cast<std::uint64_t>(s.integer("seed"));
    SeedSet set;
    if (g.count) {
        if (*g.count == 1) {  // one run, as always: --seed is its seed
            set.seeds = {o.seed.value_or(base)};
            set.run = set.seeds;
            return set;
        }
        if (base > static_cast<std::uint64_t>(INT64_MAX) - *g.count)
            throw CaseError(fmt::format("{}: [particles] seed = {} with {} seeds passes 2^63 - 1", c.file.string(), base,
                                        *g.count));
        for (std::uint64_t k = 0; k < *g.count; ++k) set.seeds.push_back(base + k);
    } else {
        set.seeds = g.list;
        std::sort(set.seeds.begin(), set.seeds.end());
    }
    const std::string origin = o.seeds.empty() ? fmt::format("{}: [particles] seeds", c.file.string()) : "--seeds";
    if (!o.seed) {
        set.run = set.seeds;
    } else if (std::binary_search(set.seeds.begin(), set.seeds.end(), *o.seed)) {
        set.run = {*o.seed};
    } else {
        throw CaseError(fmt::format("--seed {}: not one of the seeds {} ({}; allowed: one of them, or no --seed to run "
                                    "every one)",
                                    *o.seed, fmt::format("[{}]", fmt::join(set.seeds, ", ")), origin));
    }
    return set;
}

fs::path point_result_dir(const Case& c, const RunOptions& o, const std::string& solver, const std::string& point) {
    const fs::path dir = result_dir(results_root(c, o), solver, point);
    return seed_set(c, o).pooled() ? dir / realisation_folder(o.seed.value()) : dir;
}

fs::path initial_subfolder(const Case& c, const RunOptions& o) {
    return seed_set(c, o).pooled() ? fs::path(realisation_folder(o.seed.value())) : fs::path();
}

std::string point_label(const std::string& point, const fs::path& dir) {
    for (const fs::path& d : {dir, dir.parent_path()})
        if (const std::string f = d.filename().string(); f.starts_with("seed-")) return point + "/" + f;
    return point;
}

int run_particle_sweep(const Case& c, const std::string& solver, const RunOptions& o, const SeedSolver& solve,
                       const std::vector<std::string>& reads) {
    const SeedSet set = seed_set(c, o);
    const auto points = static_cast<int>(c.select(o.point).size());
    // each point (member) is its own engine process: as many side by side as cores allow
    if (!set.pooled()) {
        // one seed: o as it is (the bytes of every earlier run), unless a list of one names another seed
        RunOptions one = o;
        if (set.seeds.front() != o.seed.value_or(static_cast<std::uint64_t>(
                                      c.section(kParticlesSection).integer("seed"))))
            one.seed = set.seeds.front();
        return run_sweep(
            c, solver, one, [&](const OperatingPoint& p, const fs::path& dir) { return solve(p, one, dir); },
            points_at_once(o, points), reads);
    }
    const Realisations r{.run = set.run,
                         .solve = solve,
                         .pool = [&](const OperatingPoint&, const fs::path& dir) {
                             pool_seeds(dir, set.seeds, result_key(c, solver));
                         }};
    return run_sweep(c, solver, o, r, points_at_once(o, points * static_cast<int>(set.run.size())), reads);
}

}  // namespace granlub
