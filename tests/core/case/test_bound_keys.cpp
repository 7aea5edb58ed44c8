// BoundKeys (granlub/case/bound_keys.h): each key declared with the field it fills; read() sets the
// fields from given or defaulted values, an old key name reads into the same field, and binding an
// undeclared key is refused.
#include <boost/test/unit_test.hpp>

#include "case_text.h"
#include "granlub/case/bound_keys.h"
#include "granlub/case/case.h"
#include "granlub/error.h"

using namespace granlub;
using granlub::test::kValidCase;

namespace {

struct Toy {
    double gap = -1;
    std::int64_t steps = -1;
    std::size_t rows = 0;
    bool on = false;
    std::string label;  // read by hand: not bound
};

BoundKeys<Toy> toy_keys() {
    BoundKeys<Toy> k(SectionSpec("toy", "stand-in solver"));
    k.real("gap", &Toy::gap, 0.5, Range::positive(), "m", "a length").old_names({"spacing"});
    k.integer("steps", &Toy::steps, 10, Range::at_least(1), "a count");
    k.spec.integer("rows", 3, Range::at_least(1), "declared by a shared helper");
    k.bind("rows", &Toy::rows);
    k.boolean("on", &Toy::on, true, "a switch");
    k.spec.string("label", "x", "not bound");
    return k;
}

Toy read(const std::string& keys) {
    static const BoundKeys<Toy> k = toy_keys();
    Schema schema = Schema::common();
    schema.add(k.spec);
    const Case c = parse_case(kValidCase + "\n[toy]\n" + keys, "t.toml", schema);
    Toy t;
    k.read(t, c.section("toy"));
    return t;
}

}  // namespace

BOOST_AUTO_TEST_CASE(bound_keys_fill_their_fields) {
    const Toy d = read("");
    BOOST_TEST(d.gap == 0.5);
    BOOST_TEST(d.steps == 10);
    BOOST_TEST(d.rows == 3u);
    BOOST_TEST(d.on);
    BOOST_TEST(d.label.empty());
    const Toy g = read("gap = 0.25\nsteps = 7\nrows = 9\non = false\nlabel = \"y\"\n");
    BOOST_TEST(g.gap == 0.25);
    BOOST_TEST(g.steps == 7);
    BOOST_TEST(g.rows == 9u);
    BOOST_TEST(!g.on);
    BOOST_TEST(g.label.empty());
    BOOST_TEST(read("spacing = 0.125\n").gap == 0.125);  // the old name fills the same field
    BoundKeys<Toy> k(SectionSpec("toy", "stand-in solver"));
    BOOST_CHECK_THROW(k.bind("rows", &Toy::rows), Error);  // not declared
}
