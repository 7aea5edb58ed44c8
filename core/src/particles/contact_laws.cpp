// The contact-law table (contact_laws.h). A row per law; the sources of each law are in its
// engine's code (LIGGGHTS: plugins/liggghts/models and LIGGGHTS' own; YADE: granlub_yade.py).
#include "granlub/particles/contact_laws.h"

#include <array>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

namespace {

constexpr std::array kLaws{
    // Sawyer & Tichy 2001, the impulse operator (plugins/liggghts/models/normal_model_impulse.h)
    ContactLaw{.name = "impulse",
               .title = "Sawyer & Tichy 2001 impulse operator (granlub plugin)",
               .liggghts = "model impulse tangential impulse",
               .yade = nullptr,
               .contacts = nullptr,
               .step = StepRule::Travel,
               .stiffness = Stiffness::Rigid,
               .impulse_options = true},
    // YADE's ViscElMat spring-dashpot (Pournin et al. 2001), small e_t: the closest to the impulse operator
    ContactLaw{.name = "viscel",
               .title = "ViscElMat spring-dashpot with small e_t (YADE; closest to the impulse operator)",
               .liggghts = nullptr,
               .yade = "viscel",
               .contacts = "contacts: linear visco-elastic springs (soft spheres)",
               .step = StepRule::ContactTime,
               .stiffness = Stiffness::Linear},
    // LIGGGHTS' Hertz-Mindlin with history; YADE's Hertz-Mindlin with Tsuji damping (granlub_yade.py)
    ContactLaw{.name = "hertz",
               .title = "Hertz-Mindlin, the soft-sphere reference (LIGGGHTS' built-in with history; YADE's with "
                        "Tsuji damping)",
               .liggghts = "model hertz tangential history",
               .yade = "hertz",
               .contacts = "contacts: Hertz–Mindlin springs (soft spheres)",
               .step = StepRule::Rayleigh,
               .stiffness = Stiffness::Hertz},
};

bool in_engine(const ContactLaw& l, ParticleEngine e) {
    return (e == ParticleEngine::Liggghts ? l.liggghts : l.yade) != nullptr;
}

}  // namespace

std::span<const ContactLaw> contact_laws() { return kLaws; }

std::vector<std::string> contact_law_names(ParticleEngine e) {
    std::vector<std::string> names;
    for (const ContactLaw& l : kLaws)
        if (in_engine(l, e)) names.emplace_back(l.name);
    return names;
}

std::string contact_law_doc(ParticleEngine e) {
    std::string doc;
    for (const ContactLaw& l : kLaws)
        if (in_engine(l, e)) doc += fmt::format("{}{} = {}", doc.empty() ? "" : "; ", l.name, l.title);
    return doc;
}

void add_contact_law_key(SectionSpec& s, ParticleEngine e, std::string def) {
    s.choice("model", std::move(def), contact_law_names(e),
             "contact law (granlub/particles/contact_laws.h): " + contact_law_doc(e));
}

const ContactLaw* find_contact_law(const std::string& name) {
    for (const ContactLaw& l : kLaws)
        if (name == l.name) return &l;
    return nullptr;
}

const ContactLaw& contact_law(const std::string& name) {
    if (const ContactLaw* l = find_contact_law(name)) return *l;
    throw Error(fmt::format("internal: no contact law '{}' (granlub/particles/contact_laws.h)", name));
}

}  // namespace granlub
