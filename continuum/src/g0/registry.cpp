// The g0 registry: one row per form. Adding a form = one file in this folder + one row here.
#include <algorithm>

#include "granlub/continuum/g0/radial_distribution.h"
#include "granlub/error.h"

namespace granlub::continuum {

std::unique_ptr<RadialDistribution> make_g0_ogawa(double numax);
std::unique_ptr<RadialDistribution> make_g0_lun_savage(double numax);
std::unique_ptr<RadialDistribution> make_g0_carnahan_starling(double numax);
std::unique_ptr<RadialDistribution> make_g0_ma_ahmadi(double numax);
std::unique_ptr<RadialDistribution> make_g0_torquato(double numax);

const std::vector<G0Entry>& g0_registry() {
    static const std::vector<G0Entry> table = {
        {"ogawa", "1/(1 - (nu/nu_max)^(1/3)), Ogawa et al. 1980 (the LSJC 1984 form)", make_g0_ogawa},
        {"ls", "(1 - nu/nu_max)^(-2.5 nu_max), Lun & Savage 1986", make_g0_lun_savage},
        {"cs", "(2 - nu)/(2 (1 - nu)^3), Carnahan & Starling 1969 (no nu_max)", make_g0_carnahan_starling},
        {"ma", "Ma & Ahmadi 1986", make_g0_ma_ahmadi},
        {"torquato", "Carnahan-Starling below 0.49, then (nu_max - 0.49)/(nu_max - nu), Torquato 1995",
         make_g0_torquato},
    };
    return table;
}

std::vector<std::string> g0_names() {
    std::vector<std::string> n;
    for (const auto& e : g0_registry()) n.emplace_back(e.name);
    return n;
}

std::unique_ptr<RadialDistribution> make_g0(const std::string& name, double numax) {
    const auto& t = g0_registry();
    auto it = std::find_if(t.begin(), t.end(), [&](const G0Entry& e) { return name == e.name; });
    if (it == t.end()) {
        std::string allowed;
        for (const auto& e : t) allowed += std::string(allowed.empty() ? "" : ", ") + e.name;
        throw Error("unknown g0 \"" + name + "\" (allowed: " + allowed + ")");
    }
    return it->make(numax);
}

}  // namespace granlub::continuum
