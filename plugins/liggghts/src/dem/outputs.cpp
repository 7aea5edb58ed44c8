// Reading LIGGGHTS' wall-force, plate and snapshot files (outputs.h).
#include "outputs.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "deck.h"
#include "granlub/error.h"

namespace granlub::dem {

namespace fs = std::filesystem;

namespace {

// Calls row(values, line number) for each data line of a LIGGGHTS text output (fix ave/time
// style: blank lines and # comments skipped); `what` names the file in the "not written" error.
// Numbers are read with strtod, which also takes the "nan" and "inf" LIGGGHTS prints when a run
// blows up (an istream stops there, silently shortening the row).
template <class Row>
void for_each_data_line(const fs::path& file, const char* what, Row row) {
    std::ifstream in(file);
    if (!in) throw SolverError(fmt::format("{}: LIGGGHTS wrote no {} file", file.string(), what));
    std::string l, token;
    std::vector<double> values;
    std::size_t lineno = 0;
    while (std::getline(in, l)) {
        ++lineno;
        if (l.empty() || l[0] == '#') continue;
        std::istringstream ss(l);
        values.clear();
        while (ss >> token) {
            char* end = nullptr;
            values.push_back(std::strtod(token.c_str(), &end));
            if (end != token.c_str() + token.size())
                throw SolverError(fmt::format("{}:{}: '{}' is not a number", file.string(), lineno, token));
        }
        if (!values.empty()) row(values, lineno);
    }
}

}  // namespace

WallSeries read_wall_series(const fs::path& file) {
    WallSeries w;
    for_each_data_line(file, "wall-force", [&](const std::vector<double>& v, std::size_t lineno) {
        const std::size_t n = v.size() - 1;  // columns after the step
        if (w.columns.empty()) w.columns.resize(n);
        if (n != w.columns.size() || n == 0)
            throw SolverError(fmt::format("{}:{}: expected {} columns after the step", file.string(), lineno,
                                          std::max<std::size_t>(w.columns.size(), 1)));
        for (std::size_t k = 1; k <= n; ++k)
            if (!std::isfinite(v[k]))
                throw SolverError(fmt::format("{}:{}: non-finite wall force (the run blew up; reduce the time step)",
                                              file.string(), lineno));
        w.step.push_back(v[0]);
        for (std::size_t k = 0; k < n; ++k) w.columns[k].push_back(v[k + 1]);
    });
    if (w.step.empty()) throw SolverError(fmt::format("{}: no wall-force samples", file.string()));
    return w;
}

std::size_t for_each_snapshot(const fs::path& file, const std::function<void(const ParticleSet&, double)>& snapshot) {
    std::ifstream in(file);
    if (!in) throw SolverError(fmt::format("{}: LIGGGHTS wrote no particle snapshots", file.string()));
    std::string l;
    std::size_t count = 0;
    ParticleSet p;
    auto bad = [&](const std::string& why) {
        return SolverError(fmt::format("{}: snapshot {}: {}", file.string(), count + 1, why));
    };
    while (std::getline(in, l)) {
        if (l.rfind("ITEM: TIMESTEP", 0) != 0) continue;
        double step = 0;
        std::size_t n = 0;
        if (!(in >> step)) throw bad("no time step");
        std::getline(in, l);
        std::getline(in, l);  // ITEM: NUMBER OF ATOMS
        if (!(in >> n)) throw bad("no atom count");
        std::getline(in, l);
        for (int k = 0; k < 4; ++k) std::getline(in, l);  // box bounds
        std::getline(in, l);                               // ITEM: ATOMS <columns>
        if (l != std::string("ITEM: ATOMS ") + kSnapshotColumns && l != std::string("ITEM: ATOMS ") + kSnapshotColumns + " ")
            throw bad(fmt::format("unexpected columns: '{}' (expected: {})", l, kSnapshotColumns));
        p.clear();
        p.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            double id, x, y, z, vx, vy, vz, r;
            if (!(in >> id >> x >> y >> z >> vx >> vy >> vz >> r)) throw bad("truncated");
            if (id != static_cast<double>(i + 1)) throw bad(fmt::format("atom {} has id {} (sorted ids expected)", i + 1, id));
            p.push_back(x, y, z, vx, vy, vz, r);
        }
        snapshot(p, step);
        ++count;
    }
    return count;
}

PlateSeries read_plate_series(const fs::path& file) {
    PlateSeries p;
    for_each_data_line(file, "plate-position", [&](const std::vector<double>& v, std::size_t lineno) {
        if (v.size() != 2 || !std::isfinite(v[1]))
            throw SolverError(fmt::format("{}:{}: expected: step gap", file.string(), lineno));
        const double step = v[0], gap = v[1];
        if (step <= 0 || (!p.step.empty() && step <= p.step.back())) return;  // initial position, repeats
        p.step.push_back(step);
        p.gap.push_back(gap);
    });
    if (p.step.size() < 2) throw SolverError(fmt::format("{}: fewer than 2 plate positions", file.string()));
    return p;
}

WallForceSeries wall_forces(const WallSeries& w) {
    auto grains_on_wall = [&](std::size_t col) {
        std::vector<double> v(w.columns.at(col));
        for (double& x : v) x = -x;
        return v;
    };
    WallForceSeries f{w.step,
                      grains_on_wall(0), grains_on_wall(1), grains_on_wall(2),
                      grains_on_wall(3), grains_on_wall(4), grains_on_wall(5), {}, {}};
    if (w.columns.size() >= 8) f.fx_side1 = grains_on_wall(6), f.fx_side2 = grains_on_wall(7);
    if (w.columns.size() >= 10) f.fy_side1 = grains_on_wall(8), f.fy_side2 = grains_on_wall(9);
    return f;
}

}  // namespace granlub::dem
