// Closure families (docs/continuum-model.md §2): the transport coefficients of one kinetic theory as
// dimensionless functions of nu (p = rho_p T f_p, mu = rho_p d T^{1/2} f_mu, kappa = rho_p d T^{1/2} f_k,
// kappa_phi = rho_p d T^{3/2} f_phi, gamma = rho_p T^{3/2} f_gamma / d). One file per family in src/closures/,
// chosen by the [continuum] closures key through the registry in src/closures/registry.cpp.
// Every family is evaluated in dual numbers (exact d/dnu, §2.4).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "granlub/continuum/dual.h"

namespace granlub::continuum {

enum class CorrelationLength {
    None,         // L* = 1: classical kinetic theory
    Jenkins2007,   // closures/correlation_length.h
    JenkinsBerzi,  // closures/correlation_length.h, with ClosureParams::correlation_constant
};

struct ClosureParams {
    double restitution = 0.9;  // e_p: in f_p, f_mu, f_k (and L*)
    double alpha = 1.0;        // LSJC viscosity factor c_a = (2 + alpha)/3; 1 = original LSJC (lun84 only)
    bool dufour = true;        // include the grad-nu heat-flux term f_phi of LSJC (§2.2; lun84 only)
    // e_eff of the collisional dissipation: friction through an effective restitution
    // (closures/effective_restitution.h); negative = e_p (frictionless)
    double dissipation_restitution = -1.0;
    CorrelationLength correlation_length = CorrelationLength::None;
    double correlation_constant = 1.0;  // c of the Jenkins-Berzi correlation length
    double eta() const { return 0.5 * (1.0 + restitution); }
    double e_eff() const { return dissipation_restitution < 0 ? restitution : dissipation_restitution; }
};

// The closure functions at one solid fraction, and the combinations the Couette problem needs after
// eliminating T with p_yy = P (§3): G = f_k f_p'/f_p - f_phi, M = f_mu f_p^{-1/2}, K = G f_p^{-3/2},
// C = f_gamma f_p^{-3/2}. With a contact stress (contact_stress.h, §2.9) T = (P - p_c)/(rho_p fpk), so fp is
// fpk/(1 - p_c/P) (T = P/(rho_p fp) still) and fpk the kinetic one, which the walls' collision rate sees;
// without one they are equal.
template <class S>
struct ClosureState {
    S nu, g, dg, fp, dfp, fmu, fk, fphi, fgam, G, fpk;
    S M() const { using std::sqrt; return fmu / sqrt(fp); }
    S K() const { using std::sqrt; return G / (fp * sqrt(fp)); }
    S C() const { using std::sqrt; return fgam / (fp * sqrt(fp)); }
};

class ClosureFamily {
public:
    virtual ~ClosureFamily() = default;
    // f_p, f_p', f_mu, f_k, f_phi and the frictionless, L* = 1 dissipation f_gamma at nu with g0 = g,
    // g0' = dg; the Closures class applies e_eff and L* to f_gamma and forms G.
    virtual ClosureState<D1> state(const ClosureParams& p, D1 nu, D1 g, D1 dg) const = 0;
    // Whether the family reads the LSJC-only knobs alpha and dufour.
    virtual bool uses_lsjc_knobs() const { return false; }
};

struct ClosureEntry {
    const char* name;  // the case-file value of [continuum] closures
    const char* doc;   // one line with the source
    std::unique_ptr<ClosureFamily> (*make)();
    const char* old_name = nullptr;
};

const std::vector<ClosureEntry>& closure_registry();
std::vector<std::string> closure_names();
// Shared instance; throws granlub::Error naming the allowed families.
std::shared_ptr<const ClosureFamily> make_closure_family(const std::string& name);

}  // namespace granlub::continuum
