// The continuum's diagnostics, reproducible (docs/measurements/continuum.md "Extended kinetic theory against the DEM"):
//   continuum_rheology CASE            every point: top-wall mu, mid-gap I and nu, the homogeneous-shear mu of the
//                                      same closures at that I (simple_shear.h), their ratio, the regime label
//   continuum_rheology CASE I [I ...]  the homogeneous-shear nu, mu and T/(d gamma_dot)^2 of the case's closures at
//                                      each I (e.g. the DEM's mid-gap I from the case README)
// The case is read with the common sections and [continuum] only (the other solvers' sections are dropped:
// the continuum reads nothing else).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include <toml++/toml.h>

#include "granlub/case/case.h"
#include "granlub/continuum/case_setup.h"
#include "granlub/continuum/command.h"
#include "granlub/continuum/simple_shear.h"
#include "granlub/error.h"

using namespace granlub;

namespace {
Case load_for_continuum(std::filesystem::path path, const Schema& schema) {
    if (std::filesystem::is_directory(path)) path /= "case.toml";
    toml::table t = toml::parse_file(path.string());
    std::vector<std::string> drop;
    for (const auto& [key, node] : t) {
        const std::string name(key.str());
        bool known = false;
        for (const auto& s : schema.sections()) known = known || s.name == name;
        if (!known) drop.push_back(name);
    }
    for (const auto& k : drop) t.erase(k);
    std::ostringstream text;
    text << t;
    return parse_case(text.str(), path.string(), schema);
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s CASE [I ...]\n", argv[0]);
        return 2;
    }
    try {
        Schema schema = Schema::common();
        schema.add(continuum::section());
        const Case c = load_for_continuum(argv[1], schema);
        const continuum::Settings s = continuum::resolve_settings(c);
        if (argc > 2) {
            std::printf("I, nu, mu, T/(d gamma_dot)^2   (homogeneous shear, closures of %s)\n", argv[1]);
            for (int i = 2; i < argc; ++i) {
                const auto h = continuum::simple_shear_at_inertial(*s.closures, std::atof(argv[i]));
                std::printf("%.4f %.4f %.4f %.4f\n", h.inertial, h.nu, h.stress_ratio, h.temperature);
            }
            return 0;
        }
        std::printf("point, mu_top, slip_bottom/U, slip_top/U, mean_nu, gap_mm, I_mid, nu_mid, I/nu_mid, label, "
                    "mu_hom(I_mid), mu_top/mu_hom, wall_energy, wall_sink/work\n");
        for (const OperatingPoint& p : c.points) {
            const Summary m = continuum::solve_point(c, p, s).summary;
            const auto& l = m.run.at("lubrication");
            const auto& h = m.run.at("homogeneous_shear");
            const auto& e = m.run.at("energy_budget");
            const double P = m.value("normal_stress_top");
            std::printf("%s %.3f %.3f %.3f %.4f %.3f %.4f %.4f %.4f %s %.3f %.3f %s %.3f\n", p.id.c_str(),
                        m.value("shear_stress_top") / P, m.value("slip_bottom") / p.speed, m.value("slip_top") / p.speed,
                        m.value("mean_solid_fraction"), m.outputs.count("gap") ? 1e3 * m.value("gap") : 0.0,
                        l.at("inertial_number").get<double>(), l.at("solid_fraction").get<double>(),
                        l.at("inertial_number_over_solid_fraction").get<double>(),
                        l.at("verdict").get<std::string>().substr(0, l.at("verdict").get<std::string>().find(' ')).c_str(),
                        h.value("stress_ratio", 0.0), h.value("top_over_homogeneous", 0.0),
                        m.run.at("wall_energy").at("convention").get<std::string>().c_str(),
                        e.at("wall_dissipation_W_m2").get<double>() / e.at("wall_work_W_m2").get<double>());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
