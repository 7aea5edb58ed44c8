// The closures of one case: a closure family (family.h), a g0 form, and the dissipation modifiers
// friction (effective_restitution.h) and correlation length (correlation_length.h), which act on f_gamma
// alone (docs/continuum-model.md §2.6-2.7):
//   f_gamma = f_gamma(e_p) (1 - e_eff^2)/(1 - e_p^2) / L*(nu)
#pragma once
#include <algorithm>
#include <memory>

#include "granlub/continuum/closures/contact_stress.h"
#include "granlub/continuum/closures/correlation_length.h"
#include "granlub/continuum/closures/family.h"
#include "granlub/continuum/g0/radial_distribution.h"

namespace granlub::continuum {

class Closures {
public:
    // Without a family: lun84 (the default of every case).
    Closures(ClosureParams p, std::shared_ptr<const RadialDistribution> g0,
             std::shared_ptr<const ClosureFamily> family = make_closure_family("lun84"))
        : p_(p), g0_(std::move(g0)), family_(std::move(family)) {
        const double e = p_.restitution, ee = p_.e_eff();
        friction_factor_ = ee == e ? 1.0 : (1.0 - ee * ee) / (1.0 - e * e);
    }
    // All functions at nu, with exact d/dnu in the dual parts, under the pressure p^ = p/P_y: 1 but for the
    // cross-section's body forces (their local p), where only the contact pressure's share pi_c = p_c/p sees it.
    ClosureState<D1> state(D1 nu, double pressure = 1.0) const {
        ClosureState<D1> s = family_->state(p_, nu, g0_->g0(nu), g0_->dg0(nu));
        s.fpk = s.fp;
        if (contact_.active()) {  // fp -> fp/(1 - pi_c), with its exact derivative at fixed p (§2.9, §2.9a)
            const D1 q = 1.0 - contact_.ratio(nu) / pressure, dq = -contact_.dratio(nu) / pressure;
            s.dfp = (s.dfp * q - s.fpk * dq) / (q * q);
            s.fp = s.fpk / q;
        }
        if (friction_factor_ != 1.0) s.fgam = s.fgam * friction_factor_;
        if (p_.correlation_length == CorrelationLength::Jenkins2007)
            s.fgam = s.fgam / closures::correlation_length_jenkins2007(s.nu, s.g, p_.restitution);
        if (p_.correlation_length == CorrelationLength::JenkinsBerzi)
            s.fgam = s.fgam / closures::correlation_length_jenkins_berzi(s.nu, s.g, p_.correlation_constant,
                                                                        friction_factor_);
        s.G = s.fk * s.dfp / s.fp - s.fphi;
        return s;
    }
    ClosureState<D1> state(double nu, double pressure = 1.0) const { return state(D1::variable(nu, 0), pressure); }
    const ClosureParams& params() const { return p_; }
    const RadialDistribution& g0() const { return *g0_; }
    const ClosureFamily& family() const { return *family_; }
    double numax() const { return g0_->numax(); }
    // Upper bound of nu for the logit map: g0's, or below it where the contact pressure alone carries p = p^ P_y
    // (T = 0).
    double cap(double pressure = 1.0) const {
        if (!contact_.active()) return g0_->cap();
        return std::min(g0_->cap(), pressure == 1.0 ? contact_limit_ : contact_.limit(pressure));
    }
    // The same closures with a contact stress at one point's P_y (ContactStress::coefficient = Fr/P_y).
    Closures with_contact(const ContactStress& c) const {
        Closures r = *this;
        r.contact_ = c;
        r.contact_limit_ = c.active() ? c.limit() : 0.0;
        return r;
    }
    const ContactStress& contact() const { return contact_; }

private:
    ClosureParams p_;
    std::shared_ptr<const RadialDistribution> g0_;
    std::shared_ptr<const ClosureFamily> family_;
    double friction_factor_ = 1.0;
    ContactStress contact_;  // inactive by default
    double contact_limit_ = 0;
};

}  // namespace granlub::continuum
