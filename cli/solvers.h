// Every solver module compiled in (GRANLUB_HAVE_<MODULE>), one row each, in `granlub run` order:
//   GRANLUB_SOLVER(module)
// `module` is the module's namespace; what the solver is (its name as a string, its description,
// kind and options) is its row module::kSolver (granlub/run/solver_info.h) in granlub/<module>/command.h,
// with section(), run() and check(). Adding a solver is its module (a library granlub_<name> that
// registers its section with granlub_case_section()), one row here, its #include in
// solver_commands.h, its folder in GRANLUB_MODULES (the top CMakeLists.txt) and its name in
// cli/CMakeLists.txt's module list. The includer defines GRANLUB_SOLVER: modules.cpp makes the
// command table, full_schema.cpp the case schema (sections only, so the case-parser fuzzer can
// build it without the solvers).
#ifdef GRANLUB_HAVE_CONTINUUM
GRANLUB_SOLVER(continuum)
#endif
#ifdef GRANLUB_HAVE_AUTOMATON
GRANLUB_SOLVER(automaton)
#endif
#ifdef GRANLUB_HAVE_DEM
GRANLUB_SOLVER(dem)
#endif
#ifdef GRANLUB_HAVE_YADE
GRANLUB_SOLVER(yade)
#endif
