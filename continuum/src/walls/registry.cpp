// The wall-family registry: one row per family, named as its file (kinetic -> kinetic.cpp).
// Adding one = one file here + one row below.
#include "granlub/continuum/walls/wall_family.h"
#include "granlub/registry.h"

namespace granlub::continuum {

std::unique_ptr<WallFamily> make_wall_kinetic();
std::unique_ptr<WallFamily> make_wall_johnson_jackson();

const std::vector<WallEntry>& wall_registry() {
    static const std::vector<WallEntry> table = {
        {"kinetic", "kinetic, P-based, Jenkins-Richman-structured (default)", make_wall_kinetic, "k"},
        {"johnson_jackson", "Johnson & Jackson 1987 in GKL form", make_wall_johnson_jackson, "jj"},
    };
    static const bool checked = (registry_checked(table, "wall_model"), true);  // once, where it is built
    (void)checked;
    return table;
}

std::vector<std::string> wall_names() { return registry_names(wall_registry()); }
std::vector<std::pair<std::string, std::string>> wall_old_names() { return registry_old_names(wall_registry()); }

std::shared_ptr<const WallFamily> make_wall_family(const std::string& name) {
    return registry_find(wall_registry(), name, "wall_model").make();
}

}  // namespace granlub::continuum
