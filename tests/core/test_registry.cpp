// The one registry helper (granlub/registry.h): lookup by name, the error that lists the allowed
// names, and tables with empty or repeated names refused.
#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

#include "granlub/error.h"
#include "granlub/registry.h"

using namespace granlub;

namespace {
struct Row {
    const char* name;
    int value;
};
}  // namespace

BOOST_AUTO_TEST_CASE(registry_finds_rows_and_names_the_allowed_ones) {
    const std::vector<Row> t{{"ogawa", 1}, {"ls", 2}, {"cs", 3}};
    BOOST_TEST(registry_find(t, "ls", "g0").value == 2);
    BOOST_TEST((registry_names(t) == std::vector<std::string>{"ogawa", "ls", "cs"}));
    try {
        registry_find(t, "lun", "g0");
        BOOST_FAIL("an unknown name must throw");
    } catch (const Error& e) {
        BOOST_TEST(std::string(e.what()) == "unknown g0 \"lun\" (allowed: ogawa, ls, cs)");
    }
    BOOST_CHECK_NO_THROW(registry_checked(t, "g0"));
    const std::vector<Row> twice{{"k", 1}, {"k", 2}};
    BOOST_CHECK_THROW(registry_checked(twice, "wall_model"), Error);
    const std::vector<Row> empty{{"", 1}};
    BOOST_CHECK_THROW(registry_checked(empty, "wall_model"), Error);
}
