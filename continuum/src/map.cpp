// The continuum's (U, P) map of a case (map.h).
#include "granlub/continuum/map.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include <fmt/format.h>

#include "granlub/continuum/case_setup.h"
#include "granlub/continuum/command.h"
#include "granlub/error.h"
#include "granlub/results/file_io.h"
#include "granlub/results/results.h"
#include "granlub/run/run_lock.h"

namespace granlub::continuum {

std::string continuum_map_csv(const Case& c, const MapGrid& g, MapStats* stats) {
    if (c.points.empty()) throw CaseError(fmt::format("{}: no operating point to take the walls from", c.file.string()));
    if (!(g.speeds >= 1 && g.loads >= 1 && g.speed_min > 0 && g.load_min > 0 && g.speed_max >= g.speed_min &&
          g.load_max >= g.load_min))
        throw Error("continuum map: the grid needs >= 1 speed and load, positive and ordered bounds");
    const Settings s = resolve_settings(c);
    if (s.cross_section)  // the map is the 1-D gap's; a cross-section point costs ~0.25 s, a 100 x 100 map 40 min
        c.section(kSolver.name).fail("geometry", "the (U, P) map solves the 1-D gap; geometry = \"cross_section\" has "
                                                "no map (allowed: \"gap\" for --map)");
    const auto t0 = std::chrono::steady_clock::now();
    MapStats st;
    std::string out = fmt::format(
        "# granlub continuum map of {} ({}): {} speeds x {} loads, each point solved from scratch\n"
        "# case_hash {}, version {}, closures {}, g0 {}, wall_model {}, wall_energy {}, gap {}\n"
        "speed_m_s,normal_stress_Pa,status,mean_solid_fraction,gap_m,stress_ratio_bottom,stress_ratio_top,"
        "inertial_number,slip_bottom_m_s,slip_top_m_s,max_solid_fraction_node,lubrication\n",
        c.name, c.file.string(), g.speeds, g.loads, c.file_hash, version(), s.closures_name, s.g0_name, s.wall_name,
        s.wall_energy == WallEnergy::GklR8 ? "gkl_r8" : "slip_work", s.gap_from_inventory ? "inventory" : "fixed");
    for (int j = 0; j < g.loads; ++j) {
        const double P = g.loads == 1 ? g.load_min
                                      : g.load_min * std::pow(g.load_max / g.load_min, double(j) / (g.loads - 1));
        for (int i = 0; i < g.speeds; ++i) {
            const double U =
                g.speeds == 1 ? g.speed_min : g.speed_min + (g.speed_max - g.speed_min) * double(i) / (g.speeds - 1);
            OperatingPoint p = c.points.front();
            p.speed = U;
            p.normal_stress = P;
            p.control = Control::Load;
            ++st.points;
            try {
                const PointResult r = solve_point(c, p, s);
                const Summary& m = r.summary;
                const std::string status = m.run.at("status").get<std::string>();
                st.ordered += status == "ordered";
                const double gap = m.outputs.count("gap") ? m.value("gap") : c.cell.gap;
                const double nu_max = *std::max_element(r.profile.column("solid_fraction").begin(),
                                                        r.profile.column("solid_fraction").end());
                const std::string verdict = m.run.at("lubrication").at("verdict").get<std::string>();
                out += fmt::format("{:.6g},{:.6g},{},{:.6f},{:.6e},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{}\n", U, P,
                                   status, m.value("mean_solid_fraction"), gap, m.value("shear_stress_bottom") / P,
                                   m.value("shear_stress_top") / P, m.value("inertial_number"), m.value("slip_bottom"),
                                   m.value("slip_top"), nu_max, verdict.substr(0, verdict.find(' ')));
            } catch (const CaseError&) {
                throw;
            } catch (const Error&) {
                ++st.failed;
                out += fmt::format("{:.6g},{:.6g},failed,,,,,,,,,\n", U, P);
            }
        }
    }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (stats) *stats = st;
    return out;
}

std::filesystem::path write_continuum_map(const Case& c, const MapGrid& g, const std::filesystem::path& results_root,
                                          MapStats* stats) {
    const std::string csv = continuum_map_csv(c, g, stats);
    const auto path = results_root / kSolver.name / kMapFile;
    std::filesystem::create_directories(path.parent_path());
    write_file_atomic(path, csv);
    return path;
}

int run_map(const Case& c, const RunOptions& o, int speeds, int loads) {
    MapGrid g;
    g.speeds = speeds;
    g.loads = loads;
    const std::filesystem::path root = results_root(c, o);
    const ResultsLock held({{root, fmt::format("{}/{}", kSolver.name, kMapFile), LockMode::Exclusive}}, o.wait);
    MapStats st;
    const std::clock_t c0 = std::clock();
    const auto path = write_continuum_map(c, g, root, &st);
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    fmt::print("continuum map: {}: {} points ({} failed, {} ordered) in {:.2f} s wall, {:.2f} s CPU ({:.3f} ms CPU a "
               "point)\n",
               path.string(), st.points, st.failed, st.ordered, st.seconds, cpu, 1e3 * cpu / double(st.points));
    return st.failed == st.points ? 1 : 0;
}

}  // namespace granlub::continuum
