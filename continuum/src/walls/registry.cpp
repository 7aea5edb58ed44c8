// The wall-family registry: one row per family. Adding one = one file here + one row below.
#include <algorithm>

#include "granlub/continuum/walls/wall_family.h"
#include "granlub/error.h"

namespace granlub::continuum {

std::unique_ptr<WallFamily> make_wall_kinetic();
std::unique_ptr<WallFamily> make_wall_johnson_jackson();

const std::vector<WallEntry>& wall_registry() {
    static const std::vector<WallEntry> table = {
        {"k", "kinetic, P-based, Jenkins-Richman-structured (default)", make_wall_kinetic},
        {"jj", "Johnson & Jackson 1987 in GKL form", make_wall_johnson_jackson},
    };
    return table;
}

std::vector<std::string> wall_names() {
    std::vector<std::string> n;
    for (const auto& e : wall_registry()) n.emplace_back(e.name);
    return n;
}

std::shared_ptr<const WallFamily> make_wall_family(const std::string& name) {
    const auto& t = wall_registry();
    auto it = std::find_if(t.begin(), t.end(), [&](const WallEntry& e) { return name == e.name; });
    if (it == t.end()) {
        std::string allowed;
        for (const auto& e : t) allowed += std::string(allowed.empty() ? "" : ", ") + e.name;
        throw Error("unknown wall_model \"" + name + "\" (allowed: " + allowed + ")");
    }
    return it->make();
}

}  // namespace granlub::continuum
