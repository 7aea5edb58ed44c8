// A point's answer pooled over its seeds (seed_pool.h).
#include "granlub/particles/seed_pool.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "granlub/case/case.h"
#include "granlub/error.h"
#include "granlub/particles/seed_mean.h"
#include "granlub/results/failure_record.h"
#include "granlub/results/run_status.h"
#include "granlub/run/sweep.h"
#include "granlub/statistics/flow_regime.h"

namespace granlub {

namespace fs = std::filesystem;

namespace {

struct Member {
    std::uint64_t seed = 0;
    Summary summary;
    Profile profile;
    Regime regime;
};

// Why a member of the set is not pooled.
std::string missing_reason(const fs::path& dir, const ResultStatus& st) {
    std::optional<FailureRecord> f;
    try {
        f = read_failure(dir);
    } catch (const Error&) {
    }
    if (f) return fmt::format("{}: {}", f->no_answer ? "no answer" : "failed", f->message);
    switch (st.state) {
        case ResultState::Missing: return "not run yet";
        case ResultState::Stale: return "stale: " + st.reason;
        case ResultState::Corrupt: return "corrupt: " + st.reason;
        case ResultState::Complete: break;
    }
    return "not complete";
}

Profile pooled_profile(const std::vector<Member>& m) {
    const Profile& first = m.front().profile;
    for (const Member& x : m) {
        if (x.profile.names != first.names || x.profile.rows() != first.rows())
            throw Error(fmt::format("seed {}: profile.csv has other columns or stations than seed {}'s: not pooled",
                                    x.seed, m.front().seed));
        const auto& y = x.profile.column("y_over_H");
        for (std::size_t i = 0; i < y.size(); ++i)
            if (std::abs(y[i] - first.column("y_over_H")[i]) > 1e-9)
                throw Error(fmt::format("seed {}: profile.csv row {} at y_over_H = {}, seed {}'s at {}: not pooled",
                                        x.seed, i + 1, y[i], m.front().seed, first.column("y_over_H")[i]));
    }
    Profile out;
    std::vector<std::pair<std::string, std::vector<double>>> extra;  // appended after the members' columns
    for (const std::string& name : first.names) {
        if (name == "y_over_H") {
            out.add(name, first.column(name));
            continue;
        }
        if (name.ends_with("_stderr") && first.has(name.substr(0, name.size() - 7))) continue;  // with its column
        const std::string se_name = name + "_stderr";
        const bool has_se = first.has(se_name);
        std::vector<double> mean(first.rows()), seed_se(first.rows()), block(first.rows());
        for (std::size_t i = 0; i < first.rows(); ++i) {
            std::vector<double> v;
            std::vector<std::optional<double>> se;
            for (const Member& x : m) {
                v.push_back(x.profile.column(name)[i]);
                se.push_back(has_se ? std::optional<double>(x.profile.column(se_name)[i]) : std::nullopt);
            }
            const SeedMean p = seed_mean(v, se);
            mean[i] = p.mean;
            seed_se[i] = m.size() > 1 ? p.seed_stderr : (has_se ? *se.front() : 0.0);
            block[i] = p.block_stderr.value_or(0);
        }
        out.add(name, std::move(mean));
        if (has_se) {
            out.add(se_name, std::move(seed_se));
            extra.emplace_back(name + "_block_stderr", std::move(block));
        } else if (m.size() > 1) {
            extra.emplace_back(se_name, std::move(seed_se));
        }
    }
    // the members' column order: every column where it was, its stderr after it as before
    Profile ordered;
    for (const std::string& name : first.names)
        if (out.has(name)) ordered.add(name, out.column(name));
    for (auto& [name, v] : extra) ordered.add(name, std::move(v));
    return ordered;
}

// One quantity over the members, pooled as every output is: the mean; stderr the seeds' standard
// error (one member: its own error; the same value in every member without an error: none);
// block_stderr the members' own errors combined.
Scalar pooled_scalar(const std::vector<double>& v, const std::vector<std::optional<double>>& se) {
    const SeedMean p = seed_mean(v, se);
    Scalar s;
    s.value = p.mean;
    const bool constant = std::all_of(v.begin(), v.end(), [&](double x) { return x == v.front(); });
    const bool any_se = std::any_of(se.begin(), se.end(), [](const auto& e) { return e.has_value(); });
    if (v.size() == 1) s.stderr_ = se.front();
    else if (any_se || !constant) s.stderr_ = p.seed_stderr;
    if (v.size() > 1 && p.block_stderr) s.block_stderr = p.block_stderr;
    return s;
}

std::map<std::string, Scalar> pooled_outputs(const std::vector<Member>& m, std::vector<std::string>& not_everywhere) {
    std::set<std::string> names;
    for (const Member& x : m)
        for (const auto& [name, v] : x.summary.outputs) names.insert(name);
    std::map<std::string, Scalar> out;
    for (const std::string& name : names) {
        std::vector<double> v, dt;
        std::vector<std::optional<double>> se;
        for (const Member& x : m)
            if (const auto it = x.summary.outputs.find(name); it != x.summary.outputs.end()) {
                v.push_back(it->second.value);
                se.push_back(it->second.stderr_);
                if (it->second.dt_error) dt.push_back(*it->second.dt_error);
            }
        if (v.size() < m.size()) {
            not_everywhere.push_back(name);
            continue;
        }
        Scalar s = pooled_scalar(v, se);
        s.unit = m.front().summary.outputs.at(name).unit;
        if (dt.size() == m.size()) {
            double sum = 0;
            for (double e : dt) sum += e;
            s.dt_error = sum / static_cast<double>(dt.size());
        }
        out[name] = s;
    }
    return out;
}

// The run blocks whose measured facts are pooled, and in each the measured means that carry no
// error of their own (the rest of a block's numbers without a <name>_stderr partner are counts and
// settings, the lowest seed's). A fact with a <name>_stderr partner is pooled wherever it stands.
const std::map<std::string, std::vector<std::string>> kPooledRunBlocks = {
    {"flow_regime",
     {"contact_persistence", "inertial_number_nominal", "inertial_number_mid_gap", "mean_normal_stress_Pa",
      "mean_overlap"}},
    {"order", {"layering", "layer_spacing_over_d", "mean_neighbours"}}};

// What became of the run facts: pooled, recomputed from the pooled ones, missing in some seed
// (null), and the lowest seed's.
struct RunFacts {
    std::vector<std::string> pooled, recomputed, not_in_every_seed;
};

// run.<block>'s facts pooled over the members (at least two) into `out` (the lowest member's block).
void pool_block(const std::vector<Member>& m, const std::string& block, const std::vector<std::string>& measured,
                nlohmann::json& out, RunFacts& facts) {
    std::set<std::string> names(measured.begin(), measured.end());
    for (const Member& x : m)
        for (const auto& [name, v] : x.summary.run.at(block).items())
            if (v.is_number() && x.summary.run.at(block).contains(name + "_stderr")) names.insert(name);
    for (const std::string& name : names) {
        const std::string se_name = name + "_stderr";
        std::vector<double> v;
        std::vector<std::optional<double>> se;
        for (const Member& x : m) {
            const nlohmann::json& b = x.summary.run.at(block);
            if (!b.contains(name) || !b.at(name).is_number()) continue;
            v.push_back(b.at(name).get<double>());
            se.push_back(b.contains(se_name) && b.at(se_name).is_number() ? std::optional(b.at(se_name).get<double>())
                                                                          : std::nullopt);
        }
        if (v.empty()) continue;  // measured in no seed (or not a fact of this block): as it stands
        const std::string fact = block + "." + name;
        if (v.size() < m.size()) {
            out[name] = nullptr;
            if (out.contains(se_name)) out[se_name] = nullptr;
            facts.not_in_every_seed.push_back(fact);
            continue;
        }
        const Scalar s = pooled_scalar(v, se);
        out[name] = s.value;
        if (s.stderr_) out[se_name] = *s.stderr_;
        if (s.block_stderr) out[name + "_block_stderr"] = *s.block_stderr;
        facts.pooled.push_back(fact);
    }
}

// The flow-regime verdict of the pooled numbers, by the function that writes every run's
// (flow_regime.h): a verdict of one seed's Z beside the pooled Z would contradict it.
void recompute_flow_verdict(nlohmann::json& fr, RunFacts& facts) {
    if (!fr.is_object() || !fr.contains("verdict_version")) return;
    const std::set<std::string> pooled(facts.pooled.begin(), facts.pooled.end());
    const nlohmann::json verdict = flow_regime_json(read_flow_diagnostics(fr));
    for (const auto& [name, v] : verdict.items()) {
        const std::string fact = "flow_regime." + name;
        if (!pooled.contains(fact) && !(name.ends_with("_stderr") && pooled.contains(fact.substr(0, fact.size() - 7))))
            facts.recomputed.push_back(fact);
        fr[name] = v;
    }
}

// The pooled run facts (run.flow_regime, run.order) of two or more members, in `run` (the lowest
// member's run block); every other fact stays the lowest member's.
RunFacts pool_run_facts(const std::vector<Member>& m, nlohmann::json& run) {
    RunFacts facts;
    for (const auto& [block, measured] : kPooledRunBlocks) {
        const bool everywhere = std::all_of(m.begin(), m.end(), [&](const Member& x) {
            return x.summary.run.contains(block) && x.summary.run.at(block).is_object();
        });
        if (!everywhere) continue;
        pool_block(m, block, measured, run[block], facts);
        if (block == "flow_regime") recompute_flow_verdict(run[block], facts);
    }
    return facts;
}

nlohmann::json member_record(const Member& x) {
    nlohmann::json outputs = nlohmann::json::object();
    for (const auto& [name, v] : x.summary.outputs)
        outputs[name] = {{"value", v.value}, {"stderr", v.stderr_ ? nlohmann::json(*v.stderr_) : nlohmann::json()}};
    return {{"seed", x.seed},
            {"folder", realisation_folder(x.seed)},
            {"status", to_string(x.regime.status)},
            {"status_reason", x.regime.reason},
            {"run_id", x.summary.provenance.run_id},
            {"outputs", outputs}};
}

// run.seeds.run_facts_from: which run facts pool the seeds, which are recomputed from them, and
// which are the lowest seed's (every fact of `run`, the pooled run block, named).
nlohmann::json run_facts_record(const RunFacts& f, const nlohmann::json& run, std::uint64_t lowest) {
    std::set<std::string> done(f.pooled.begin(), f.pooled.end());
    done.insert(f.recomputed.begin(), f.recomputed.end());
    done.insert(f.not_in_every_seed.begin(), f.not_in_every_seed.end());
    for (const std::string& x : f.pooled) done.insert({x + "_stderr", x + "_block_stderr"});
    for (const std::string& x : f.not_in_every_seed) done.insert(x + "_stderr");
    std::vector<std::string> from_lowest;
    for (const auto& [key, v] : run.items()) {
        if (key == "seeds" || key == "wall_clock_s" || key == "status" || key == "status_reason") continue;
        if (!kPooledRunBlocks.contains(key) || !v.is_object() || f.pooled.empty()) {
            from_lowest.push_back(key);
            continue;
        }
        for (const auto& [name, x] : v.items())
            if (!done.contains(key + "." + name)) from_lowest.push_back(key + "." + name);
    }
    return {{"pooled", f.pooled},
            {"pooled_as", "the mean over the pooled seeds; <name>_stderr the seeds' standard error, "
                          "<name>_block_stderr the seeds' own block errors combined (as the outputs)"},
            {"recomputed", f.recomputed},
            {"recomputed_by", "flow_regime_json (granlub/statistics/flow_regime.h), from the pooled numbers"},
            {"not_in_every_seed", f.not_in_every_seed},
            {"lowest_seed", realisation_folder(lowest)},
            {"from_lowest_seed", from_lowest}};
}

}  // namespace

void pool_seeds(const fs::path& point_dir, const std::vector<std::uint64_t>& seeds_in, const ResultKey& key) {
    std::vector<std::uint64_t> seeds = seeds_in;
    std::sort(seeds.begin(), seeds.end());
    std::vector<Member> members;
    nlohmann::json missing = nlohmann::json::array();
    for (const std::uint64_t s : seeds) {
        const fs::path dir = point_dir / realisation_folder(s);
        LoadedResult r = load_result(dir, key);
        if (r.status.state != ResultState::Complete) {
            missing.push_back({{"seed", s}, {"why", missing_reason(dir, r.status)}});
            continue;
        }
        members.push_back({s, std::move(*r.summary), std::move(*r.profile), {}});
        members.back().regime = read_regime(members.back().summary.run);
    }
    // only the pool may stand at the point: a single run's tables there would name another run
    std::error_code ec;
    fs::remove(point_dir / "summary.json", ec);
    remove_point_tables(point_dir);
    if (members.empty()) {
        fs::remove(point_dir / "profile.csv", ec);
        return;
    }

    const Member& base = members.front();
    Summary s;
    s.solver = base.summary.solver;
    s.case_name = base.summary.case_name;
    s.point = base.summary.point;
    s.inputs = base.summary.inputs;
    std::vector<std::string> not_everywhere;
    s.outputs = pooled_outputs(members, not_everywhere);
    s.run = base.summary.run;
    const RunFacts facts = members.size() > 1 ? pool_run_facts(members, s.run) : RunFacts{};  // one: its own

    nlohmann::json pooled = nlohmann::json::array(), records = nlohmann::json::array();
    std::string ids, utc;
    double wall = 0;
    for (const Member& x : members) {
        pooled.push_back(x.seed);
        records.push_back(member_record(x));
        ids += fmt::format("{}={};", x.seed, x.summary.provenance.run_id);
        utc = std::max(utc, x.summary.provenance.utc_time);
        wall += x.summary.run.value("wall_clock_s", 0.0);
    }
    const std::size_t n = members.size();
    s.run["seeds"] = {
        {"set", seeds},
        {"pooled", pooled},
        {"missing", missing},
        {"error", n > 1 ? "stderr: the seeds' standard error, the sample standard deviation over the pooled seeds / "
                          "sqrt(their number); block_stderr: the seeds' own block errors combined, sqrt(sum se_i^2) / n"
                        : "one seed: stderr is its own block error (no seeds' standard error yet)"},
        {"run_facts_from", run_facts_record(facts, s.run, base.seed)},
        {"members", records}};
    if (!not_everywhere.empty()) s.run["seeds"]["outputs_not_in_every_seed"] = not_everywhere;
    s.run["wall_clock_s"] = wall;

    // the point's status: steady only if every seed is; incomplete while one is missing
    std::string reasons;
    std::optional<RegimeStatus> worst;
    for (const Member& x : members)
        if (!x.regime.steady()) {
            if (!worst) worst = x.regime.status;
            reasons += fmt::format("{}seed {} {}{}", reasons.empty() ? "" : "; ", x.seed, to_string(x.regime.status),
                                   x.regime.reason.empty() ? "" : ": " + x.regime.reason);
        }
    if (!missing.empty()) {
        std::vector<std::string> gone;
        for (const auto& m : missing) gone.push_back(fmt::format("seed {} ({})", m.at("seed").get<std::uint64_t>(),
                                                                 m.at("why").get<std::string>()));
        set_regime(s.run, RegimeStatus::Incomplete,
                   fmt::format("incomplete: {} of {} seeds; missing {}{}", n, seeds.size(), fmt::join(gone, ", "),
                               reasons.empty() ? "" : "; and " + reasons));
    } else if (worst) {
        set_regime(s.run, *worst == RegimeStatus::Unknown ? RegimeStatus::Transient : *worst,
                   fmt::format("{} of {} seeds not steady: {}", std::count_if(members.begin(), members.end(),
                                                                             [](const Member& x) { return !x.regime.steady(); }),
                               n, reasons));
    } else {
        set_regime(s.run, RegimeStatus::Steady, "");
    }

    s.provenance = base.summary.provenance;
    s.provenance.seed = std::nullopt;
    s.provenance.utc_time = utc;
    s.provenance.run_id = "seeds-" + hash_hex(ids);
    write_result(point_dir, pooled_profile(members), s);
}

}  // namespace granlub
