// Every solver module compiled in (GRANLUB_HAVE_<MODULE>), one row each, in `granlub run` order:
//   GRANLUB_SOLVER(name, "one-line description", engine)
// engine: its points are processes of an external engine (LIGGGHTS, YADE), which `granlub run`
// runs side by side with the other engines' (run_all.cpp).
// `name` is the module's namespace, command, case section and result folder; the module provides
// granlub/<name>/command.h with section(), run() and check(). Adding a solver is its module (a
// library granlub_<name> that registers its section with granlub_case_section()), one row here,
// its #include in solver_commands.h, its folder in GRANLUB_MODULES (the top CMakeLists.txt) and
// its name in cli/CMakeLists.txt's module list. The includer defines GRANLUB_SOLVER:
// modules.cpp makes the command table, full_schema.cpp the case schema (sections only, so the
// case-parser fuzzer can build it without the solvers).
#ifdef GRANLUB_HAVE_CONTINUUM
GRANLUB_SOLVER(continuum, "granular kinetic lubrication (GKL) continuum solver", false)
#endif
#ifdef GRANLUB_HAVE_AUTOMATON
GRANLUB_SOLVER(automaton, "lattice cellular automaton (Jasti & Higgs 2006)", false)
#endif
#ifdef GRANLUB_HAVE_DEM
GRANLUB_SOLVER(dem, "particle simulation in LIGGGHTS with granlub's contact models", true)
#endif
#ifdef GRANLUB_HAVE_YADE
GRANLUB_SOLVER(yade, "particle simulation in YADE (cross-check)", true)
#endif
