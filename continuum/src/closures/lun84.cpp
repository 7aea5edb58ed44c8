// Closure family lun84: Lun, Savage, Jeffrey & Chepurniy 1984 (J. Fluid Mech. 140, 223) as coded in
// MFiX GT_PDE_LUN (docs/continuum-model.md §2.1; closures/lun84.h). The default: it reproduces
// Sawyer & Tichy 2001.
#include "granlub/continuum/closures/lun84.h"

namespace granlub::continuum {
namespace {
class Lun84 final : public ClosureFamily {
public:
    ClosureState<D1> state(const ClosureParams& p, D1 nu, D1 g, D1 dg) const override {
        return lun84_state(p, nu, g, dg);
    }
    bool uses_lsjc_knobs() const override { return true; }
};
}  // namespace

std::unique_ptr<ClosureFamily> make_closures_lun84() { return std::make_unique<Lun84>(); }

}  // namespace granlub::continuum
