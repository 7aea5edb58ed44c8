// Flow-regime evidence of one LIGGGHTS run (diagnostics.h).
#include "diagnostics.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "granlub/contacts.h"
#include "granlub/error.h"
#include "granlub/flow_regime.h"

namespace granlub::dem {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

void CoordinationSeries::add(const ParticleSet& p, double time) {
    if (time < t_start_ - 1e-12) return;
    const auto t0 = std::chrono::steady_clock::now();
    const ContactList pairs = touching_pairs(p, box_);
    z_.push_back(coordination_number(pairs, p.size()));
    const OverlapStats o = overlaps(p, box_, pairs);
    max_overlap_ = std::max(max_overlap_, o.max);
    overlap_sum_ += o.mean * static_cast<double>(o.overlapping);
    overlapping_ += o.overlapping;
    seconds_ += seconds_since(t0);
}

nlohmann::json flow_regime_record(const Case& c, const OperatingPoint& pt, const Settings& s, const DemOutputs& out,
                                  const SliceCoarseGrainer& cg, const CoordinationSeries& z,
                                  const std::filesystem::path& contacts_file) {
    const auto t0 = std::chrono::steady_clock::now();
    // persistence between consecutive snapshots persistence_every steps apart, pooled
    std::vector<ContactList> pairs;
    std::vector<double> steps;
    for_each_snapshot(contacts_file, [&](const ParticleSet& p, double step) {
        pairs.push_back(touching_pairs(p, s.contact_box));
        steps.push_back(step);
    });
    double persisting = 0;
    std::size_t intervals = 0;
    for (std::size_t k = 0; k + 1 < pairs.size(); ++k) {
        if (std::abs(steps[k + 1] - steps[k] - static_cast<double>(s.persistence_every)) > 0.5)
            throw SolverError(fmt::format("{}: snapshots at steps {} and {}, expected {} steps apart",
                                          contacts_file.string(), steps[k], steps[k + 1], s.persistence_every));
        if (const auto f = contact_persistence(pairs[k], pairs[k + 1])) persisting += *f, ++intervals;
    }
    if (pairs.size() < 2)
        throw SolverError(fmt::format("{}: {} persistence snapshots, expected {}", contacts_file.string(),
                                      pairs.size(), s.persistence_intervals + 1));

    FlowDiagnostics d;
    const double U = pt.speed, H = cg.stations().hi;  // H: the gap the profile spans (mean plate gap under load)
    const double P = 0.5 * (out.outputs.at("normal_stress_bottom").value + out.outputs.at("normal_stress_top").value);
    set_inertial_numbers(d, out.profile, U, H, P, c.grains.diameter, c.grains.density);
    const auto& zs = z.values();
    if (!zs.empty()) {
        double sum = 0;
        for (double v : zs) sum += v;
        d.coordination = sum / static_cast<double>(zs.size());
    }
    if (intervals > 0) d.persistence = persisting / static_cast<double>(intervals);  // mean over the intervals

    nlohmann::json j = flow_regime_json(d);
    j["mean_normal_stress_Pa"] = P;
    j["coordination_snapshots"] = zs.size();
    j["contact_gap_tolerance"] = kContactGapTolerance;
    j["wall_contacts_in_coordination"] = false;
    // rigid grains should not interpenetrate: overlap / (r_i + r_j) of grain pairs, steady snapshots
    j["max_overlap"] = z.max_overlap();
    j["mean_overlap"] = z.mean_overlap();
    j["persistence_interval_steps"] = s.persistence_every;
    j["persistence_interval_s"] = static_cast<double>(s.persistence_every) * s.time_step;
    j["persistence_snapshots"] = pairs.size();
    j["persistence_extra_steps"] = s.persistence_run_steps();
    j["analysis_wall_clock_s"] = z.seconds() + seconds_since(t0);
    return j;
}

}  // namespace granlub::dem
