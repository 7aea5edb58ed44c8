// The keys both particle engines' sections (`[dem]`, `[yade]`) add the same way.
#pragma once
#include "granlub/case/bound_keys.h"
#include "granlub/case/case.h"
#include "granlub/particles/particle_section.h"
#include "granlub/particles/servo.h"

namespace granlub {

// The sampling keys (particle_section.h) and the servo's (servo.h), sample_every, stations and
// blocks bound to the engine's Settings fields of those names, and [particles] among the sections
// its results depend on (the initial grains both engines share).
template <class Settings>
void add_engine_keys(BoundKeys<Settings>& k) {
    add_sampling_keys(k.spec);
    add_servo_keys(k.spec);
    k.bind("sample_every", &Settings::sample_every).bind("stations", &Settings::stations).bind("blocks", &Settings::blocks);
    k.spec.uses = {kParticlesSection};
}

}  // namespace granlub
