// granlub's LIGGGHTS plugin: registers the impulse contact models (model impulse, tangential
// impulse) and every combination in style_contact_model_user.whitelist. Call once before the
// first LAMMPS instance is made; the shared library also registers itself when loaded.
#pragma once

#ifdef __cplusplus
extern "C" {
#endif
// Returns the number of contact-model combinations registered by this call (0 if already done).
int granlub_liggghts_register(void);
#ifdef __cplusplus
}
#endif
