// Reading LIGGGHTS' wall-force, plate and snapshot files (outputs.h).
#include "outputs.h"

#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "deck.h"
#include "ring_deck.h"
#include "granlub/error.h"
#include "granlub/results/table.h"

namespace granlub::dem {

namespace fs = std::filesystem;

namespace {

// LIGGGHTS' `fix ave/time` / `fix print` text: whitespace-separated numbers, '#' comments. strtod
// (in the table reader) also takes the "nan" and "inf" LIGGGHTS prints when a run blows up, which
// an istream would silently stop at.
TableFormat liggghts_text(std::vector<std::string> names = {}) {
    TableFormat f;
    f.separator = TableFormat::Separator::whitespace;
    f.header = false;
    f.names = std::move(names);
    f.finite = true;
    f.nonfinite_hint = "the run blew up; reduce the time step";
    return f;
}

}  // namespace

WallSeries read_wall_series(const fs::path& file) {
    Table t = read_solver_output(file, liggghts_text(), "LIGGGHTS wrote no wall-force file");
    if (t.rows() == 0) throw SolverError(fmt::format("{}: no wall-force samples", file.string()));
    if (t.columns.size() < 2)
        throw SolverError(fmt::format("{}:{}: expected the step and at least one wall force", file.string(), t.line[0]));
    WallSeries w;
    w.step = std::move(t.columns[0]);
    w.columns.assign(std::make_move_iterator(t.columns.begin() + 1), std::make_move_iterator(t.columns.end()));
    return w;
}

std::size_t for_each_snapshot(const fs::path& file, const std::function<void(const ParticleSet&, double)>& snapshot,
                              bool spins) {
    const std::string columns = spins ? kFinalColumns : kSnapshotColumns;
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
        if (l != "ITEM: ATOMS " + columns && l != "ITEM: ATOMS " + columns + " ")
            throw bad(fmt::format("unexpected columns: '{}' (expected: {})", l, columns));
        p.clear();
        p.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            double id, x, y, z, vx, vy, vz, r;
            if (!(in >> id >> x >> y >> z >> vx >> vy >> vz >> r)) throw bad("truncated");
            if (id != static_cast<double>(i + 1)) throw bad(fmt::format("atom {} has id {} (sorted ids expected)", i + 1, id));
            p.push_back(x, y, z, vx, vy, vz, r);
            if (spins) {
                double wx, wy, wz;
                if (!(in >> wx >> wy >> wz)) throw bad("truncated");
                p.wx.push_back(wx), p.wy.push_back(wy), p.wz.push_back(wz);
            }
        }
        snapshot(p, step);
        ++count;
    }
    return count;
}

PlateSeries read_plate_series(const fs::path& file) {
    const Table t = read_solver_output(file, liggghts_text({"step", "gap"}), "LIGGGHTS wrote no plate-position file");
    PlateSeries p;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        const double step = t.columns[0][r], gap = t.columns[1][r];
        if (step <= 0 || (!p.step.empty() && step <= p.step.back())) continue;  // initial position, repeats
        p.step.push_back(step);
        p.gap.push_back(gap);
    }
    if (p.step.size() < 2) throw SolverError(fmt::format("{}: fewer than 2 plate positions", file.string()));
    return p;
}

double read_final_plate(const fs::path& file) {
    const Table t = read_solver_output(file, liggghts_text({"gap"}), "LIGGGHTS wrote no final plate position");
    if (t.rows() != 1 || !(t.columns[0][0] > 0))
        throw SolverError(fmt::format("{}: expected one positive plate position", file.string()));
    return t.columns[0][0];
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

RingWallLoads ring_wall_loads(const WallSeries& w, const fs::path& file) {
    if (w.columns.size() != kRingWallColumns)
        throw SolverError(fmt::format("{}: {} columns after the step, expected the ring's {} (force along the axis "
                                      "and torque about it of floor, top, outer and inner wall)",
                                      file.string(), w.columns.size(), kRingWallColumns));
    return {w.step,         w.columns[0], w.columns[1], w.columns[2], w.columns[3],
            w.columns[4],   w.columns[5], w.columns[6], w.columns[7]};
}

}  // namespace granlub::dem
