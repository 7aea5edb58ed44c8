// The g0 registry: one row per form, named as its file (lun_savage -> lun_savage.cpp). Adding a
// form = one file in this folder + one row here.
#include "granlub/continuum/g0/radial_distribution.h"
#include "granlub/registry.h"

namespace granlub::continuum {

std::unique_ptr<RadialDistribution> make_g0_ogawa(double numax);
std::unique_ptr<RadialDistribution> make_g0_lun_savage(double numax);
std::unique_ptr<RadialDistribution> make_g0_carnahan_starling(double numax);
std::unique_ptr<RadialDistribution> make_g0_ma_ahmadi(double numax);
std::unique_ptr<RadialDistribution> make_g0_torquato(double numax);
std::unique_ptr<RadialDistribution> make_g0_chialvo_sundaresan(double numax);

const std::vector<G0Entry>& g0_registry() {
    static const std::vector<G0Entry> table = {
        {"ogawa", "1/(1 - (nu/nu_max)^(1/3)), Ogawa et al. 1980 (the LSJC 1984 form)", make_g0_ogawa},
        {"lun_savage", "(1 - nu/nu_max)^(-2.5 nu_max), Lun & Savage 1986", make_g0_lun_savage, "ls"},
        {"carnahan_starling", "(2 - nu)/(2 (1 - nu)^3), Carnahan & Starling 1969 (no nu_max)",
         make_g0_carnahan_starling, "cs"},
        {"ma_ahmadi", "Ma & Ahmadi 1986", make_g0_ma_ahmadi, "ma"},
        {"torquato", "Carnahan-Starling below 0.49, then (nu_max - 0.49)/(nu_max - nu), Torquato 1995",
         make_g0_torquato},
        {"chialvo_sundaresan", "CS + 0.58 nu^2/(nu_max - nu)^(3/2), Chialvo & Sundaresan 2013 Eq. 31",
         make_g0_chialvo_sundaresan},
    };
    static const bool checked = (registry_checked(table, "g0"), true);  // once, where it is built
    (void)checked;
    return table;
}

std::vector<std::string> g0_names() { return registry_names(g0_registry()); }
std::vector<std::pair<std::string, std::string>> g0_old_names() { return registry_old_names(g0_registry()); }

std::unique_ptr<RadialDistribution> make_g0(const std::string& name, double numax) {
    return registry_find(g0_registry(), name, "g0").make(numax);
}

}  // namespace granlub::continuum
