// Shared set-up for the continuum suites: the dimensionless problems of docs/continuum-model.md.
#pragma once
#include <cmath>
#include <memory>
#include <string>

#include "granlub/continuum/problem.h"

namespace granlub::continuum::testing {

struct Spec {
    double d = 0.787e-3, rho = 2550, H = 4e-3, U = 2.0, P = 5.5e3;
    double ep = 0.9, ew = 0.9, R = 0.5, numax = 0.65;
    std::string g0 = "ogawa", wall = "kinetic";
    Mode mode = Mode::Load;
    double nu_mean = 0.595;
    double alpha = 1.0;
    bool dufour = true;
};

inline std::shared_ptr<const Closures> make_closures(const std::string& g0, double ep, double numax = 0.65,
                                                double alpha = 1.0, bool dufour = true) {
    return std::make_shared<Closures>(ClosureParams{ep, alpha, dufour},
                                      std::shared_ptr<const RadialDistribution>(make_g0(g0, numax)));
}

inline Problem problem(const Spec& s) {
    Problem p;
    p.closures = make_closures(s.g0, s.ep, s.numax, s.alpha, s.dufour);
    p.Lambda = s.H / s.d;
    p.Pi = s.rho * s.U * s.U / s.P;
    p.mode = s.mode;
    p.nu_mean = s.nu_mean;
    WallBC w{make_wall_family(s.wall), WallParams{s.ew, s.R, s.R, s.R, s.R, 0.0}};
    p.bottom = w;
    p.top = w;
    return p;
}

// S&T 2001 case (docs/continuum-model.md §1) at speed U and load P.
inline Spec sawyer(double U, double P = 5.5e3) {
    Spec s;
    s.U = U;
    s.P = P;
    return s;
}

// Jasti & Higgs 2006 continuum case (§7.4): H = 4 mm, e_p = 0.85, e_w = 0.65, R = 0.65.
inline Spec jasti(double P = 5.5e3) {
    Spec s;
    s.U = 2.0;
    s.P = P;
    s.ep = 0.85;
    s.ew = 0.65;
    s.R = 0.65;
    return s;
}

// An illustrative contact stress (docs/continuum-model.md §2.9; not fitted): Johnson & Jackson's form with n = 2,
// m = 5, nu_min = 0.5, nu_c = 0.65 (the fixtures' nu_max) and Fr/P = 3e-5, so p_c = P at nu_P ~ 0.60; mu_c = 0.2,
// below the kinetic theory's own mu at nu_P (LSJC with Ogawa's g0: 0.30), so that mu(I) rises from mu_c: with mu_c
// above it mu(I) falls with I (rate weakening) and the gap's core stops shearing.
constexpr double kIllustrativeMuC = 0.2;
inline ContactStress illustrative_contact(double friction = kIllustrativeMuC, double eps = 1e-2) {
    ContactStress c;
    c.coefficient = 3e-5;
    c.onset = 0.5;
    c.jamming = 0.65;
    c.n = 2;
    c.m = 5;
    c.friction = friction;
    c.sign_width = eps;
    return c;
}
inline Problem with_contact(Problem p, const ContactStress& c) {
    p.closures = std::make_shared<Closures>(p.closures->with_contact(c));
    return p;
}

inline double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace granlub::continuum::testing
