// granlub's LIGGGHTS plugin: registers the impulse contact models (model impulse, tangential
// impulse) and every combination in style_contact_model_user.whitelist. Call once before the
// first LAMMPS instance is made; the shared library also registers itself when loaded.
#pragma once

#ifdef __cplusplus
extern "C" {
#endif
// Returns the number of contact-model combinations registered by this call (0 if already done).
int granlub_liggghts_register(void);
// Adds granlub's fix and compute styles (fix centripetal/annulus, fix impulse/solve, compute
// wall/gran/force) to one LAMMPS instance (a LAMMPS_NS::LAMMPS*); call after constructing it (the
// input command `clear` remakes its style tables without them). The driver granlub-liggghts does;
// `LD_PRELOAD` with the stock binary gets the contact models only. Returns the number of styles added.
int granlub_liggghts_register_styles(void* lammps);
#ifdef __cplusplus
}
#endif
