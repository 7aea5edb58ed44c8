// The flow-regime evidence of one run (flow_regime.h): the inertial number from U/H and from the
// measured mid-gap shear rate, the coordination number over the steady snapshots and the contact
// persistence from the snapshots the deck writes after the run (kContactsFile).
#pragma once
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "granlub/case.h"
#include "granlub/coarse_grain.h"
#include "granlub/particles.h"
#include "outputs.h"
#include "settings.h"

namespace granlub::dem {

// Collects the coordination number of each coarse-graining snapshot as it is read.
class CoordinationSeries {
public:
    explicit CoordinationSeries(const ParticleBox& box) : box_(box) {}
    void add(const ParticleSet& p);
    const std::vector<double>& values() const { return z_; }
    double seconds() const { return seconds_; }  // time spent finding contacts

private:
    ParticleBox box_;
    std::vector<double> z_;
    double seconds_ = 0;
};

// run.flow_regime: flow_regime_json() plus how it was measured and what it cost.
nlohmann::json flow_regime_record(const Case& c, const OperatingPoint& p, const Settings& s, const DemOutputs& out,
                                  const SliceCoarseGrainer& cg, const CoordinationSeries& z,
                                  const std::filesystem::path& contacts_file);

}  // namespace granlub::dem
