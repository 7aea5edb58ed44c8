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

// Collects the coordination number of each coarse-graining snapshot from the steady-state start
// on (earlier ones are skipped: they are not averaged) as the snapshots are read.
class CoordinationSeries {
public:
    CoordinationSeries(const ParticleBox& box, double t_start) : box_(box), t_start_(t_start) {}
    void add(const ParticleSet& p, double time);
    const std::vector<double>& values() const { return z_; }
    double seconds() const { return seconds_; }  // time spent finding contacts
    // over the same snapshots: the deepest overlap and the mean of the overlapping pairs' overlaps
    double max_overlap() const { return max_overlap_; }
    double mean_overlap() const { return overlapping_ ? overlap_sum_ / static_cast<double>(overlapping_) : 0.0; }

private:
    ParticleBox box_;
    double t_start_;
    std::vector<double> z_;
    double seconds_ = 0;
    double max_overlap_ = 0, overlap_sum_ = 0;
    std::size_t overlapping_ = 0;
};

// run.flow_regime: flow_regime_json() plus how it was measured and what it cost.
nlohmann::json flow_regime_record(const Case& c, const OperatingPoint& p, const Settings& s, const DemOutputs& out,
                                  const SliceCoarseGrainer& cg, const CoordinationSeries& z,
                                  const std::filesystem::path& contacts_file);

}  // namespace granlub::dem
