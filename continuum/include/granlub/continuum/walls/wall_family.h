// Wall boundary-condition families (docs/continuum-model.md §4). The structure of the GKL wall conditions
// (S&T 2001 Eqs. 13-15) is fixed; a family supplies only the four dimensionless coefficient
// functions b5..b8(nu) of §5. Families live in src/walls/, one file each, and are chosen by
// the [continuum] wall_model key through the registry table in src/walls/registry.cpp.
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "granlub/continuum/closures/closure_set.h"

namespace granlub::continuum {

// What the energy wall condition returns of the slip work (docs/continuum-model.md §4.5, [continuum] wall_energy):
//   GklR8     the fraction R8 (S&T 2001 Eq. 15 as GKL use it): the rest, (1 - R8) of the slip work, is a wall sink
//             whatever e_w; the seed's own model (closures = "lun84"),
//   SlipWork  all of it, as Johnson & Jackson 1987, Jenkins & Richman 1986 and Richman 1988 write the flux into the
//             flow: slip work minus a collisional dissipation that vanishes at e_w = 1.
enum class WallEnergy { GklR8, SlipWork };

class FlatWallImpacts;  // walls/flat_wall_impacts.h

// One wall's parameters: restitution e_w, roughness factors R5..R8, the slip-dissipation
// fraction f_t of the R7 term and the energy convention (R8 is read only with GklR8).
struct WallParams {
    double restitution = 0.9;
    double r5 = 0.5, r6 = 0.5, r7 = 0.5, r8 = 0.5;
    double slip_dissipation = 0.0;  // f_t
    WallEnergy energy = WallEnergy::GklR8;
    // e_w in the collisional dissipation (b6) only: < 0 = restitution; with [continuum] wall_friction_restitution
    // = "as_grains" the wall's friction through the grains' effective restitution (case_setup.cpp). Last, so that
    // the positional initialisations above keep their meaning.
    double dissipation_restitution = -1.0;
    double dissipation_e() const { return dissipation_restitution < 0 ? restitution : dissipation_restitution; }
    // A flat wall's impacts that stick and slide (walls/flat_wall_impacts.h): the traction and the collisional terms
    // scaled by their ratios to the stick limit at the wall's slip (wall_condition.h); null: the linear condition.
    std::shared_ptr<const FlatWallImpacts> impacts{};
    // The share of the grains' slip at which their contact points slip on such a wall ([continuum] flat_wall_spin,
    // walls/flat_wall.h): the law's xi is the contact points' (read with impacts only).
    double contact_slip_share = 1.0;
};

struct WallCoefficients {
    D1 b5, b6, b7, b8;  // values and d/dnu
    D1 xi_per_slip;     // xi/(|s| sqrt(Pi)), xi = u_s/sqrt(T) (wall_condition.h): wall_xi_per_slip()
};

// xi_per_slip at the wall: T = P/(rho_p f_p) there (family.h; P the local one), so u_s/sqrt(T) = |s| sqrt(Pi f_p).
inline D1 wall_xi_per_slip(const ClosureState<D1>& s) { return sqrt(s.fp); }

class WallFamily {
public:
    virtual ~WallFamily() = default;
    virtual WallCoefficients coefficients(const ClosureState<D1>& s, const WallParams& w, double numax) const = 0;
    // Whether the family's source scales its collisional dissipation (b6) with the wall's roughness: a bumpy
    // wall's does (Jenkins & Richman 1986), Johnson & Jackson's does not (their specularity enters the traction
    // only). With WallEnergy::SlipWork the default R6 is the roughness if true, else 1; GKL (GklR8) scales
    // every term by R whatever the family.
    virtual bool dissipation_scales_with_roughness() const { return true; }
};

struct WallEntry {
    const char* name;  // the case-file value of [continuum] wall_model
    const char* doc;
    std::unique_ptr<WallFamily> (*make)();
    const char* old_name = nullptr;  // its spelling before it was named as its file: still read
};

const std::vector<WallEntry>& wall_registry();
std::vector<std::string> wall_names();
// {old, new} for each renamed row, for SectionSpec::old_spellings.
std::vector<std::pair<std::string, std::string>> wall_old_names();
// Shared instance of a registered family; throws granlub::Error naming the allowed families.
std::shared_ptr<const WallFamily> make_wall_family(const std::string& name);

}  // namespace granlub::continuum
