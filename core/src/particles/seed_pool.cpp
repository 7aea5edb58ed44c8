// A point's answer pooled over its seeds (seed_pool.h).
#include "granlub/particles/seed_pool.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "granlub/case/case.h"
#include "granlub/error.h"
#include "granlub/results/failure_record.h"
#include "granlub/results/run_status.h"
#include "granlub/run/sweep.h"

namespace granlub {

namespace fs = std::filesystem;

namespace {

struct Member {
    std::uint64_t seed = 0;
    Summary summary;
    Profile profile;
    Regime regime;
};

// The mean, the seeds' standard error and the block errors combined of one quantity over the members.
struct Pooled {
    double mean = 0;
    double seed_stderr = 0;
    std::optional<double> block_stderr;  // when every member has its own
};

Pooled pool(const std::vector<double>& v, const std::vector<std::optional<double>>& se) {
    const auto n = static_cast<double>(v.size());
    Pooled p;
    for (double x : v) p.mean += x;
    p.mean /= n;
    double ss = 0;
    for (double x : v) ss += (x - p.mean) * (x - p.mean);
    if (v.size() > 1) p.seed_stderr = std::sqrt(ss / (n - 1) / n);
    if (std::all_of(se.begin(), se.end(), [](const auto& e) { return e.has_value(); })) {
        double s2 = 0;
        for (const auto& e : se) s2 += *e * *e;
        p.block_stderr = std::sqrt(s2) / n;
    }
    return p;
}

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
            const Pooled p = pool(v, se);
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
        const Pooled p = pool(v, se);
        Scalar s;
        s.value = p.mean;
        s.unit = m.front().summary.outputs.at(name).unit;
        const bool constant = std::all_of(v.begin(), v.end(), [&](double x) { return x == v.front(); });
        const bool any_se = std::any_of(se.begin(), se.end(), [](const auto& e) { return e.has_value(); });
        if (m.size() == 1) s.stderr_ = se.front();
        else if (any_se || !constant) s.stderr_ = p.seed_stderr;
        if (m.size() > 1 && p.block_stderr) s.block_stderr = p.block_stderr;
        if (dt.size() == m.size()) {
            double sum = 0;
            for (double e : dt) sum += e;
            s.dt_error = sum / static_cast<double>(dt.size());
        }
        out[name] = s;
    }
    return out;
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
        {"run_facts_from", fmt::format("{} (the lowest pooled seed): the run facts beside run.seeds are that "
                                       "realisation's; the outputs and the profile pool every pooled seed",
                                       realisation_folder(base.seed))},
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
