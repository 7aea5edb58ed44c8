// The one particle pipeline of `granlub dem` and `granlub yade` (particle_pipeline.h).
#include "granlub/particles/particle_pipeline.h"
#include "granlub/particles/bulk_rheology.h"

#include <chrono>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "granlub/particles/coarse_grain.h"
#include "granlub/particles/contacts.h"
#include "granlub/particles/cross_section.h"
#include "granlub/error.h"
#include "granlub/statistics/flow_regime.h"
#include "granlub/particles/packing_order.h"
#include "granlub/particles/wall_layer.h"

namespace granlub {

namespace fs = std::filesystem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The profile across the width over the steady snapshots (cross_section.h); the ring's also with
// the radius each slice-frame z stands for (annulus.h).
std::string width_profile_csv(const ParticlePipeline& in, const CrossSection& xs, const ParticleReduction& out) {
    const std::size_t first =
        out.run.at("snapshots").get<std::size_t>() - out.run.at("snapshots_used").get<std::size_t>();
    Profile t = xs.width_profile(in.p.speed, first, in.blocks);
    std::string frame = "z across the width, z/W = -1/2 the outer wall (where the centripetal force pushes)";
    if (in.annulus) {
        const auto& z = t.column("z_over_W");
        std::vector<double> r(z.size());
        const double R = in.annulus->R, W = in.annulus->W;
        for (std::size_t i = 0; i < z.size(); ++i) r[i] = (std::sqrt(R * R + 0.25 * W * W - 2.0 * R * z[i] * W) - R) / W;
        t.add("r_minus_R_over_W", std::move(r));
        frame = "the whole ring in the slice frame: z/W = -1/2 the outer cylinder, equal-area bands, "
                "r_minus_R_over_W the radius of each band's centre";
    }
    return profile_csv(t, {in.what, "solid fraction and u/U across the width, over the gap (the mean plate gap under "
                                    "load) and the snapshots of the steady window; " + frame});
}

// Contact persistence between consecutive persistence snapshots, pooled over the intervals.
struct Persistence {
    std::optional<double> mean;
    std::size_t snapshots = 0;
};

Persistence persistence(const ParticlePipeline& in, const ParticleRecord& rec) {
    std::vector<ContactList> pairs;
    std::vector<double> times;
    rec.persistence.read([&](const ParticleSet& p, double t) {
        pairs.push_back(touching_pairs(p, *in.contact_box));
        times.push_back(t);
    });
    const double dt = static_cast<double>(in.persistence_every) * in.time_step;
    double persisting = 0;
    std::size_t intervals = 0;
    for (std::size_t k = 0; k + 1 < pairs.size(); ++k) {
        if (std::abs(times[k + 1] - times[k] - dt) > 0.5 * in.time_step)
            throw SolverError(fmt::format("{}: snapshots at {:g} s and {:g} s, expected {} steps ({:g} s) apart",
                                          rec.persistence.name, times[k], times[k + 1], in.persistence_every, dt));
        if (const auto f = contact_persistence(pairs[k], pairs[k + 1])) persisting += *f, ++intervals;
    }
    if (pairs.size() < 2)
        throw SolverError(fmt::format("{}: {} persistence snapshots, expected at least 2", rec.persistence.name,
                                      pairs.size()));
    Persistence r;
    r.snapshots = pairs.size();
    if (intervals > 0) r.mean = persisting / static_cast<double>(intervals);
    return r;
}

// run.flow_regime: the inertial numbers from the profile and the mean wall normal stress, the
// coordination number and the overlaps over the steady snapshots, the contact persistence after
// the run; what is not recorded is null and said.
nlohmann::json flow_regime_record(const ParticlePipeline& in, const ParticleRecord& rec, const ParticleReduction& out,
                                  double gap, const std::optional<ContactSeries>& contacts) {
    const auto t0 = std::chrono::steady_clock::now();
    FlowDiagnostics d;
    const double P = 0.5 * (out.outputs.at("normal_stress_bottom").value + out.outputs.at("normal_stress_top").value);
    set_inertial_numbers(d, out.profile, in.p.speed, gap, P, in.c.grains.diameter, in.c.grains.density);
    std::optional<Persistence> pers;
    if (contacts && !contacts->coordination().empty()) {
        double sum = 0;
        for (double v : contacts->coordination()) sum += v;
        d.coordination = sum / static_cast<double>(contacts->coordination().size());
        // its block error over the steady snapshots: a point's Z either side of the verdict's
        // threshold reads "at the transition" (point_verdict.h)
        const BlockEstimate z = block_average(contacts->coordination(), in.blocks);
        if (z.blocks >= 2) d.coordination_stderr = z.stderr_;
    }
    if (contacts && rec.persistence) {
        pers = persistence(in, rec);
        d.persistence = pers->mean;
    }
    nlohmann::json j = flow_regime_json(d);
    j["mean_normal_stress_Pa"] = P;
    if (contacts && contacts->core_coordination().size() >= 2) {  // the core's Z (bulk_rheology.h)
        const auto& zc = contacts->core_coordination();
        const BlockEstimate z = block_average(zc, in.blocks);
        j["coordination_number_core"] = z.mean;
        j["coordination_number_core_stderr"] = z.blocks >= 2 ? nlohmann::json(z.stderr_) : nlohmann::json();
        j["core_band_over_gap"] = {kCoreFrom, kCoreTo};
        j["core_coordination_snapshots"] = zc.size();
    }
    if (contacts) {
        j["coordination_snapshots"] = contacts->coordination().size();
        j["contact_gap_tolerance"] = kContactGapTolerance;
        j["wall_contacts_in_coordination"] = false;
        // rigid grains should not interpenetrate: overlap / (r_i + r_j) of grain pairs, steady snapshots
        j["max_overlap"] = contacts->max_overlap();
        j["mean_overlap"] = contacts->mean_overlap();
    } else {
        j["contacts_not_measured"] = "the snapshots hold no positions along the flow";
    }
    if (pers) {
        j["persistence_interval_steps"] = in.persistence_every;
        j["persistence_interval_s"] = static_cast<double>(in.persistence_every) * in.time_step;
        j["persistence_snapshots"] = pers->snapshots;
    }
    j["analysis_wall_clock_s"] = (contacts ? contacts->seconds() : 0.0) + seconds_since(t0);
    return j;
}

// How far a wall's bumps reach from its plane (0 for a plane).
double protrusion(const std::optional<BumpLayer>* b) { return b && *b ? 0.5 * (*b)->diameter : 0.0; }
// A wall's bumps, or null for a plane.
const BumpLayer* bumps_of(const std::optional<BumpLayer>* b) { return b && *b ? &**b : nullptr; }

// run.order and the outputs "layering" and "q6" (packing_order.h): layering from the profile,
// q6 over the steady snapshots when their positions are recorded.
nlohmann::json order_record(const ParticlePipeline& in, ParticleReduction& out, double gap,
                            const std::optional<OrderSeries>& order) {
    nlohmann::json j = {{"neighbour_cutoff", kOrderNeighbourCutoff}, {"min_neighbours", kOrderMinNeighbours}};
    const std::optional<double> layering = layering_amplitude(out.profile, gap, in.c.grains.diameter);
    j["layering"] = layering ? nlohmann::json(*layering) : nlohmann::json();
    if (layering) out.outputs["layering"] = Scalar{*layering, std::nullopt, ""};
    if (!order || order->q6().empty()) {
        j["q6"] = j["Q6"] = j["layer_order"] = nullptr;
        j["q6_not_measured"] = order ? "no steady snapshot" : "the snapshots hold no positions along the flow";
        return j;
    }
    const BlockEstimate q6 = block_average(order->q6(), in.blocks), Q6 = block_average(order->Q6(), in.blocks);
    const BlockEstimate layers = block_average(order->layer_order(), in.blocks);
    out.outputs["q6"] = Scalar{q6.mean, q6.stderr_, ""};
    out.outputs["layer_order"] = Scalar{layers.mean, layers.stderr_, ""};
    j.update(nlohmann::json{{"q6", q6.mean},
                            {"q6_stderr", q6.stderr_},
                            {"Q6", Q6.mean},
                            {"Q6_stderr", Q6.stderr_},
                            {"layer_order", layers.mean},
                            {"layer_order_stderr", layers.stderr_},
                            {"layer_spacing_over_d", order->mean_layer_spacing() / in.c.grains.diameter},
                            {"mean_neighbours", order->mean_neighbours()},
                            {"snapshots", order->q6().size()}});
    return j;
}

}  // namespace

ParticleReduction run_particle_pipeline(const ParticlePipeline& in, const ParticleRecord& rec, const fs::path& dir) {
    const WallForceSeries walls = rec.ring ? ring_wall_forces(*rec.ring, *in.annulus) : rec.forces;
    const WallStresses stresses = wall_stresses(walls, in.box);
    const PlateSeries* plate = rec.plate ? &*rec.plate : nullptr;
    if (plate)
        write_file_atomic(dir / kGapFile,
                          gap_csv(in.servo, in.time_step, walls.step, stresses.normal_top, *plate, in.what));
    const SteadyWindow window =
        wall_steady_window(stresses, walls, in.sample_every, in.time_step, plate, in.servo.servo_every);

    // profile slabs span the gap: the box's, or the mean plate position under load control
    const double gap = plate ? mean_gap(*plate, window, in.blocks).mean : in.box.gap;
    SliceCoarseGrainer cg({0.0, gap, in.stations}, in.box.length * in.box.width);
    CrossSection xs = CrossSection::for_grains(in.c.grains.diameter, gap, in.box.width, in.box.length);
    std::optional<ContactSeries> contacts;
    std::optional<OrderSeries> order;
    if (in.contact_box) {
        contacts.emplace(*in.contact_box, window.t_start, Band{kCoreFrom * gap, kCoreTo * gap});
        // layers counted a mean diameter clear of the walls (of a rough wall's bumps); the ring's
        // axis is its y too
        const double d = in.c.grains.diameter;
        order.emplace(*in.contact_box, window.t_start, protrusion(in.bumps_bottom) + d, gap - protrusion(in.bumps_top) - d,
                      d);
    }
    ParticleSet mapped;  // the ring's grains in the slice frame (annulus.h)
    double solids = 0;   // the grains' volume, from their radii as the engine ran them
    rec.snapshots.read([&](const ParticleSet& g, double t) {
        if (cg.snapshots() == 0) solids = solids_volume(g);
        if (in.annulus) to_slice(g, *in.annulus, mapped);
        const ParticleSet& sg = in.annulus ? mapped : g;
        cg.add_snapshot(sg, t);
        xs.add_snapshot(sg, t);
        if (contacts) contacts->add(g, t), order->add(g, t);  // in the engine's own frame
    });
    if (cg.snapshots() < 2) throw SolverError(fmt::format("{}: fewer than 2 particle snapshots", rec.snapshots.name));

    ParticleReduction out = reduce_particles({.c = in.c,
                                              .speed = in.p.speed,
                                              .box = in.box,
                                              .forces = walls,
                                              .stresses = stresses,
                                              .cg = cg,
                                              .window = window,
                                              .plate = plate,
                                              .servo = in.servo,
                                              .blocks = in.blocks,
                                              .grains = in.grains,
                                              .solids_volume = solids,
                                              .simulated_s = in.simulated_s,
                                              .time_step = in.time_step,
                                              .cross_section = &xs,
                                              .plate_start = in.plate_start,
                                              .slip_bottom_from = protrusion(in.bumps_bottom),
                                              .slip_top_from = protrusion(in.bumps_top)});
    write_file_atomic(dir / kSectionFile,
                      profile_csv(out.cross_section,
                                  {in.what, "solid fraction and u/U over the cross-section: y across the gap (0 = moving "
                                            "floor), z across the width (z/W = -1/2: the outer wall, where the "
                                            "centripetal force pushes), averaged along the flow and over the snapshots "
                                            "of the steady window"}));
    write_file_atomic(dir / kWidthProfileFile, width_profile_csv(in, xs, out));
    if (rec.ring) {  // the torques about the axis: nothing else turns the grains
        const BlockEstimate e = ring_torque_balance(*rec.ring, window.wall_start, in.blocks);
        out.outputs["torque_balance"] = Scalar{e.mean, e.stderr_, ""};
        out.run["geometry"] = "annulus";
    }
    out.run["flow_regime"] = flow_regime_record(in, rec, out, gap, contacts);
    out.run["order"] = order_record(in, out, gap, order);
    // what the walls were, and where the slip is taken: at the wall's plane (through the bumps'
    // centres on a rough wall), from the slab of stations next to it
    const std::optional<BumpLayer> none;
    out.run["walls"] = {{"bottom", walls_json(in.bumps_bottom ? *in.bumps_bottom : none)},
                        {"top", walls_json(in.bumps_top ? *in.bumps_top : none)},
                        {"sides", in.annulus          ? nlohmann::json("cylinders")
                                  : in.box.periodic_z ? nlohmann::json("periodic")
                                                      : walls_json(in.bumps_side ? *in.bumps_side : none)},
                        {"slip_measured", "wall speed minus the mean velocity of the station next to the wall's "
                                          "plane; on a rough wall, of the first station whose centre is clear of "
                                          "its bumps (half a bump diameter from the plane through their centres)"}};
    out.run["wall_layer"] = wall_layer_record(rec.final_state, in.box, in.p.speed, bumps_of(in.bumps_bottom),
                                              bumps_of(in.bumps_top), in.annulus != nullptr);
    return out;
}

}  // namespace granlub
