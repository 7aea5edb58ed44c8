// granlub's LIGGGHTS plugin: registers the impulse contact models (model impulse, tangential
// impulse) and every combination their headers list (GRAN_MODEL lines). Call once before the
// first LAMMPS instance is made; the shared library also registers itself when loaded.
#pragma once

#ifdef __cplusplus
extern "C" {
#endif
// Returns the number of contact-model combinations registered by this call (0 if already done).
int granlub_liggghts_register(void);
// Adds granlub's fix and compute styles (fix centripetal/annulus, fix impulse/solve, compute
// wall/gran/force) to one LAMMPS instance (a LAMMPS_NS::LAMMPS*); call after constructing it. The
// driver granlub-liggghts does; every pair_style gran / fix wall/gran with the plugin's models does
// it again (so `LD_PRELOAD` with the stock binary, and decks after `clear`, have the styles from
// there on). Returns the number of styles added.
int granlub_liggghts_register_styles(void* lammps);
// The plugin's contact-model combinations, fix and compute styles, for `granlub-liggghts -h` (a FILE*).
void granlub_liggghts_print_styles(void* file);
// The registered combinations as a user writes them ('model impulse', ...), comma-separated.
const char* granlub_liggghts_combinations(void);
#ifdef __cplusplus
}
#endif
