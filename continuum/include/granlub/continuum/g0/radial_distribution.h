// Radial distribution function at contact g0(nu), one unit per form (docs/continuum-model.md §2.3), chosen by the
// [continuum] g0 key through a registry table (src/g0/registry.cpp). Adding a form is one file in
// src/g0/ plus one registry row.
//
// Every form supplies the analytic g0 and g0'. Both are evaluated in dual numbers, so d/dnu of
// g0' (needed for the exact Jacobian of the conduction term) is exact too (§2.4).
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "granlub/continuum/dual.h"

namespace granlub::continuum {

class RadialDistribution {
public:
    explicit RadialDistribution(double numax) : numax_(numax) {}
    virtual ~RadialDistribution() = default;
    virtual D1 g0(D1 nu) const = 0;
    virtual D1 dg0(D1 nu) const = 0;  // analytic dg0/dnu
    // Upper bound of nu for the logit map: nu_max when g0 diverges there, else a safe cap
    // (§6.1: 0.95 for Carnahan-Starling, with nu > nu_max flagged as unphysical).
    virtual double cap() const { return numax_; }
    double numax() const { return numax_; }
    double g0(double nu) const { return g0(D1(nu)).v; }
    double dg0(double nu) const { return dg0(D1(nu)).v; }

protected:
    double numax_;
};

// Adapter: a form written as static templates `g(S nu, double numax)` and `dg(S nu, double numax)`.
template <class Form>
class RadialDistributionOf final : public RadialDistribution {
public:
    using RadialDistribution::RadialDistribution;
    using RadialDistribution::dg0;
    using RadialDistribution::g0;
    D1 g0(D1 nu) const override { return Form::g(nu, numax_); }
    D1 dg0(D1 nu) const override { return Form::dg(nu, numax_); }
    double cap() const override { return Form::cap(numax_); }
};

struct G0Entry {
    const char* name;  // the case-file value of [continuum] g0
    const char* doc;   // one line with the source
    std::unique_ptr<RadialDistribution> (*make)(double numax);
    const char* old_name = nullptr;  // its spelling before it was named as its file: still read
};

const std::vector<G0Entry>& g0_registry();
std::vector<std::string> g0_names();
// {old, new} for each renamed row, for SectionSpec::old_spellings.
std::vector<std::pair<std::string, std::string>> g0_old_names();
// Throws granlub::Error naming the allowed forms when `name` is unknown.
std::unique_ptr<RadialDistribution> make_g0(const std::string& name, double numax);

}  // namespace granlub::continuum
