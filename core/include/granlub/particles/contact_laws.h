// The particle engines' contact laws, one row each (src/particles/contact_laws.cpp): the value a
// case gives to [dem] model or [yade] model, how each engine spells the law, how the law's time
// step follows from the case and what kind of stiffness it has (the servo's plate cap, servo.h).
// `granlub dem`'s section, settings and deck writers, `granlub yade`'s settings and the report read
// this table; besides its row a law is named only in its engine's code: a plugin law in its two
// LIGGGHTS model headers (the normal one lists its combinations), a YADE law as its class in
// granlub_yade.py's LAWS; a new step rule or stiffness in the engine's settings. docs/architecture.md
// lists every file that names a law (the repo_doc_file_lists test keeps that list true).
#pragma once
#include <span>
#include <string>
#include <vector>

#include "granlub/case/schema.h"

namespace granlub {

// How a law's time step follows from the case (the engine's settings apply the rule).
enum class StepRule {
    Travel,       // rigid contacts found only by overlap: a fraction of the smallest diameter travelled per step
    Rayleigh,     // Hertz springs: a fraction of the grains' Rayleigh time (particle_section.h)
    ContactTime,  // a linear spring-dashpot of given contact duration t_c: a fraction of t_c
};

// What a grain-plate contact does under the load (servo.h's plate cap).
enum class Stiffness {
    Rigid,   // no overlap scale: the plate's gain is not capped
    Hertz,   // hertz_plate_overlap
    Linear,  // linear_plate_overlap, stiffness from the contact time
};

enum class ParticleEngine { Liggghts, Yade };

struct ContactLaw {
    const char* name;      // the case's value ([dem] model, [yade] model) and the summaries' "model"
    const char* title;     // one line: what it is and where it comes from (the decks' comment, the key's doc)
    const char* liggghts;  // the pair style's model words in granlub dem's decks; nullptr: not in granlub dem
    const char* yade;      // the law granlub_yade.py builds; nullptr: not in granlub yade
    // the report's line on what made a solver's numbers; nullptr: the report words it itself (the
    // impulse operator's depends on contact_solve)
    const char* contacts;
    StepRule step;
    Stiffness stiffness;
    // the impulse operator's options ([dem] beta0, separate_overlaps, bounce_speed, contact_solve,
    // impact_time, speculative, boundary_pairs): written on the model's line, refused with any other law
    bool impulse_options = false;
};

std::span<const ContactLaw> contact_laws();

// The engine's laws' names, in the table's order.
std::vector<std::string> contact_law_names(ParticleEngine e);

// "name = title; ..." of the engine's laws (the model key's doc).
std::string contact_law_doc(ParticleEngine e);

// The engine's section's `model` key: one of its laws (default `def`), each with its title.
void add_contact_law_key(SectionSpec& s, ParticleEngine e, std::string def);

// The row of `name` (a value the schema has checked); throws Error for a name not in the table.
const ContactLaw& contact_law(const std::string& name);
// The row of `name`, or nullptr (a results file's model, which an older version may have written).
const ContactLaw* find_contact_law(const std::string& name);

}  // namespace granlub
