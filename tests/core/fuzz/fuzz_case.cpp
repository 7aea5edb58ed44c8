// libFuzzer entry: any input must either parse or raise granlub::CaseError; anything else (a
// crash, a sanitizer report, another exception type) is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "granlub/case.h"
#include "granlub/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const granlub::Schema schema = granlub::Schema::common();
    try {
        granlub::Case c = granlub::parse_case(std::string_view(reinterpret_cast<const char*>(data), size),
                                              "fuzz.toml", schema);
        (void)granlub::describe(c);
    } catch (const granlub::CaseError&) {
    }
    return 0;
}
