// The closure-family registry: one row per family, named as its file (lun84 -> lun84.cpp).
// Adding one = one file here + one row below.
#include "granlub/continuum/closures/family.h"
#include "granlub/registry.h"

namespace granlub::continuum {

std::unique_ptr<ClosureFamily> make_closures_lun84();
std::unique_ptr<ClosureFamily> make_closures_garzo_dufty();

const std::vector<ClosureEntry>& closure_registry() {
    static const std::vector<ClosureEntry> table = {
        {"lun84", "Lun, Savage, Jeffrey & Chepurniy 1984 (default; reproduces Sawyer & Tichy 2001)",
         make_closures_lun84},
        {"garzo_dufty", "Garzo & Dufty 1999 viscosity and conductivity, as extended kinetic theory uses them",
         make_closures_garzo_dufty},
    };
    static const bool checked = (registry_checked(table, "closures"), true);  // once, where it is built
    (void)checked;
    return table;
}

std::vector<std::string> closure_names() { return registry_names(closure_registry()); }

std::shared_ptr<const ClosureFamily> make_closure_family(const std::string& name) {
    return registry_find(closure_registry(), name, "closures").make();
}

}  // namespace granlub::continuum
