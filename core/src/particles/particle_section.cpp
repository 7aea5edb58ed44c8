// The keys both particle engines share (particle_section.h).
#include "granlub/particles/particle_section.h"

namespace granlub {

void add_sampling_keys(SectionSpec& s) {
    s.integer("sample_every", 100, Range::closed(1, 1e8),
              "wall-force block length in steps (forces are summed every step)");
    s.integer("snapshots", 50, Range::closed(4, 1e5), "particle snapshots over the run for coarse-graining");
    s.integer("stations", 20, Range::closed(2, 1e5), "coarse-graining slabs across the gap");
    s.integer("blocks", 10, Range::closed(2, 1e4),
              "blocks for the standard errors (block averaging); the wall stresses use fewer where blocks would "
              "be shorter than three decorrelation times (run.wall_stress_blocks)");
}

void add_until_steady_keys(SectionSpec& s) {
    s.real("time_max", 0.0, Range::non_negative(), "s",
           "until steady, with a cap: a run not steady at its length is continued from where it ended, at the same "
           "step, by a piece as long as the run so far, until a piece is steady (the answer) or the next would pass "
           "this much simulated time in all; 0 = one run, a transient labelled as one").neutral_default();
    s.real("time_max_full", 0.0, Range::non_negative(), "s", "time_max with --full (the run doubles from the --full length)").neutral_default();
}

ParticleStart particle_start(const Case& c, const OperatingPoint& p, std::optional<std::uint64_t> seed) {
    const Section& s = c.section(kParticlesSection);
    ParticleStart r;
    r.insertion.seed = seed ? *seed : static_cast<std::uint64_t>(s.integer("seed"));
    r.insertion.velocity_noise = s.real("velocity_noise");
    r.insertion.wall_speed = p.speed;
    r.periodic_depth = s.real("periodic_depth");
    return r;
}

}  // namespace granlub
