// toml++'s implementation, compiled here with the fuzzer's instrumentation and sanitizers
// instead of linked from the (uninstrumented) shared library, so coverage sees inside the TOML
// parser. One translation unit of its own: it compiles in parallel with case.cpp and is rebuilt
// only when toml++ changes.
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
