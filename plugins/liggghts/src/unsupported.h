// Registers, for every combination of LIGGGHTS' model names with `model impulse` or `tangential
// impulse` that is not in style_contact_model_user.whitelist, a pair and a wall creator that stops
// with a message naming the supported combinations. Returns how many combinations it covered.
#pragma once

int granlub_liggghts_register_unsupported();
