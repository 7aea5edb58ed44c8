// libFuzzer entry for the case parser with the schema `granlub` itself uses (cli/full_schema.cpp:
// the common sections plus every solver's section and its cross-key checks). Any input must
// either parse or raise granlub::CaseError; anything else (a crash, a sanitizer report, another
// exception type) is a bug. A parsed case then goes through what `granlub check` and the solvers
// do next: describe(), point selection and the per-solver input hashes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "full_schema.h"
#include "granlub/case/case.h"
#include "granlub/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const granlub::Schema schema = granlub::cli::full_schema();
    try {
        const granlub::Case c = granlub::parse_case(
            std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml", schema);
        (void)granlub::describe(c);
        if (c.select("").size() != c.points.size()) std::abort();
        for (const auto& p : c.points)
            if (c.select(p.id).size() != 1) std::abort();  // ids are unique (repeated sweep values are rejected)
        for (const auto& spec : schema.sections())
            if (!granlub::common_sections_contains(spec.name)) (void)c.inputs_hash(spec.name);
    } catch (const granlub::CaseError&) {
    }
    return 0;
}
