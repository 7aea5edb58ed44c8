// The command.h (section() and run()) of every solver module compiled in (GRANLUB_HAVE_<MODULE>).
#pragma once

#ifdef GRANLUB_HAVE_CONTINUUM
#include "granlub/continuum/command.h"
#endif
#ifdef GRANLUB_HAVE_AUTOMATON
#include "granlub/automaton/command.h"
#endif
#ifdef GRANLUB_HAVE_DEM
#include "granlub/dem/command.h"
#endif
#ifdef GRANLUB_HAVE_YADE
#include "granlub/yade/command.h"
#endif
