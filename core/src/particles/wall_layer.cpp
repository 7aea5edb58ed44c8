// The wall layer's kinematics (wall_layer.h).
#include "granlub/particles/wall_layer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "granlub/statistics/block_average.h"

namespace granlub {

namespace {

using Vec = std::array<double, 3>;

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// d to its nearest periodic image (period 0: not periodic)
double nearest_image(double d, double period) { return period > 0 ? d - period * std::round(d / period) : d; }

// The contacts' samples of one wall, over U (wall_layer.h's definitions).
struct Samples {
    std::vector<double> slip, tangential, rolling, contact;
    std::size_t rolls = 0;
};

}  // namespace

WallLayer wall_layer(const ParticleSet& p, const ParticleBox& box, const WallLayerWall& w, double U) {
    const double s_w = w.side == WallSide::Bottom ? 1.0 : -1.0;  // also n_w's y
    const Vec n_w{0.0, s_w, 0.0};
    const bool spin = p.has_spin();
    const double tol = 1.0 + kWallContactTolerance;
    const double half_bump = w.bumps ? 0.5 * w.bumps->diameter : 0.0;
    WallLayer r;
    Samples s;
    auto contact = [&](std::size_t i, const Vec& n) {
        const double a = p.radius[i];
        const Vec u{p.vx[i] - w.speed, p.vy[i], p.vz[i]};  // the grain's velocity relative to the wall
        const double un = dot(u, n);
        const Vec ut{u[0] - un * n[0], u[1] - un * n[1], u[2] - un * n[2]};
        const Vec wn = spin ? cross({p.wx[i], p.wy[i], p.wz[i]}, n) : Vec{0, 0, 0};
        const Vec gt{ut[0] - a * wn[0], ut[1] - a * wn[1], ut[2] - a * wn[2]};  // g_t = u_t + w x (-a n)
        s.slip.push_back(-s_w * u[0] / U);
        s.tangential.push_back(-s_w * ut[0] / U);
        s.rolling.push_back(-s_w * a * wn[0] / U);
        s.contact.push_back(-s_w * gt[0] / U);
        if (std::sqrt(dot(gt, gt)) < kRollingSlip * U) ++s.rolls;
    };
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double a = p.radius[i], h = s_w * (p.y[i] - w.plane);  // height above the wall's plane
        const std::size_t before = s.slip.size();
        if (h < tol * a) contact(i, n_w);
        if (w.bumps && h < tol * (a + half_bump)) {
            const double touching = a + half_bump;
            for (std::size_t b = 0; b < w.bumps->size(); ++b) {
                const Vec d{nearest_image(p.x[i] - w.bumps->x[b] - w.bump_shift, box.length), p.y[i] - w.plane,
                            nearest_image(p.z[i] - w.bumps->across[b], box.periodic_z ? box.width : 0.0)};
                const double dist = std::sqrt(dot(d, d));
                if (dist >= tol * touching || dist == 0) continue;
                r.max_bump_overlap = std::max(r.max_bump_overlap, (touching - dist) / a);
                contact(i, {d[0] / dist, d[1] / dist, d[2] / dist});
                ++r.bump_contacts;
            }
        }
        if (s.slip.size() > before) ++r.grains;
    }
    r.contacts = s.slip.size();
    if (r.contacts == 0) return r;
    // the contacts as independent samples (wall_layer.h)
    const BlockEstimate slip = mean_and_stderr(s.slip), tangential = mean_and_stderr(s.tangential),
                        rolling = mean_and_stderr(s.rolling), cs = mean_and_stderr(s.contact);
    r.slip = slip.mean, r.slip_stderr = slip.stderr_;
    r.tangential_slip = tangential.mean, r.tangential_slip_stderr = tangential.stderr_;
    r.rolling = rolling.mean, r.rolling_stderr = rolling.stderr_;
    r.contact_slip = cs.mean, r.contact_slip_stderr = cs.stderr_;
    if (r.slip != 0) r.rolling_share = 1.0 - r.contact_slip / r.slip;
    r.rolling_fraction = static_cast<double>(s.rolls) / static_cast<double>(r.contacts);
    return r;
}

namespace {

nlohmann::json wall_json(const WallLayer& r, const WallLayerWall& w, double U, double time) {
    nlohmann::json j = {{"surface", w.bumps ? "bumps" : "plane"}, {"wall_speed_over_U", w.speed / U},
                        {"grains", r.grains}, {"contacts", r.contacts}};
    if (w.bumps) j["max_bump_overlap_over_radius"] = r.max_bump_overlap;
    if (w.bumps && r.max_bump_overlap > kBumpOverlapLimit) {
        j["not_measured"] = fmt::format("the grains overlap the bumps placed where they were at t = {:g} s by up to "
                                        "{:.3g} of a radius, more than {:g}: not where the engine had them",
                                        time, r.max_bump_overlap, kBumpOverlapLimit);
        return j;
    }
    if (r.contacts == 0) {
        j["not_measured"] = "no grain touches the wall";
        return j;
    }
    j.update(nlohmann::json{{"slip_over_U", r.slip},
                            {"slip_over_U_stderr", r.slip_stderr},
                            {"rolling_over_U", r.rolling},
                            {"rolling_over_U_stderr", r.rolling_stderr},
                            {"contact_slip_over_U", r.contact_slip},
                            {"contact_slip_over_U_stderr", r.contact_slip_stderr},
                            {"rolling_share", r.rolling_share ? nlohmann::json(*r.rolling_share) : nlohmann::json()},
                            {"rolling_fraction", r.rolling_fraction}});
    if (w.bumps) {
        j["bump_contacts"] = r.bump_contacts;
        j["tangential_slip_over_U"] = r.tangential_slip;
        j["tangential_slip_over_U_stderr"] = r.tangential_slip_stderr;
    }
    return j;
}

}  // namespace

nlohmann::json wall_layer_record(const std::optional<ParticleState>& state, const ParticleBox& box, double U,
                                 const BumpLayer* bottom, const BumpLayer* top, bool ring) {
    nlohmann::json j = {{"contact_tolerance", kWallContactTolerance}, {"rolling_slip_over_U", kRollingSlip}};
    const char* why = ring                           ? "the ring's walls turn about its axis: measured in a slice only"
                      : !state                       ? "the run left no final state"
                      : !state->particles.has_spin() ? "the final state holds no spins"
                      : !(U > 0)                     ? "the floor does not move (U = 0)"
                                                     : nullptr;
    if (why) {
        j["not_measured"] = why;
        return j;
    }
    j["source"] = "the run's final state (final_state.csv), one snapshot after the run and its contact-persistence "
                  "steps (the steady snapshots hold no spins); standard errors over the contacts";
    j["time_s"] = state->time;
    j["signs"] = "positive when the grains lag their wall: slip (U - v_x)/U at the floor, v_x/U at the top; rolling "
                 "a w_z/U on a plane, the part the spin carries back; contact_slip = slip - rolling on a plane";
    const WallLayerWall b{.side = WallSide::Bottom, .plane = 0.0, .speed = U, .bumps = bottom,
                          .bump_shift = U * state->time};
    const WallLayerWall t{.side = WallSide::Top, .plane = state->gap, .speed = 0.0, .bumps = top};
    j["bottom"] = wall_json(wall_layer(state->particles, box, b, U), b, U, state->time);
    j["top"] = wall_json(wall_layer(state->particles, box, t, U), t, U, state->time);
    if (!box.periodic_z) j["sides"] = "not measured (the floor's and the top's grains touching a side wall count)";
    return j;
}

}  // namespace granlub
