// Registers, for every combination of LIGGGHTS' model names with one of the plugin's models
// (`model impulse`, `tangential impulse`) that its headers do not list (GRAN_MODEL lines), a pair
// and a wall creator that stops with a message naming the supported combinations. Returns how many combinations it covered.
#pragma once

int granlub_liggghts_register_unsupported();
