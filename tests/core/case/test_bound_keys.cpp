// BoundKeys (granlub/case/bound_keys.h): each key declared with the field it fills; read() sets the
// fields from given or defaulted values, an old key name reads into the same field, and binding an
// undeclared key is refused; a part's member, an optional key, a registry choice and a --full
// partner fill their fields, and get() gives each field back as the case file writes it.
#include <boost/test/unit_test.hpp>

#include "case_text.h"
#include "granlub/case/bound_keys.h"
#include "granlub/case/case.h"
#include "granlub/error.h"

using namespace granlub;
using granlub::test::kValidCase;

namespace {

enum class Shape { Round, Square };
struct ShapeRow {
    const char* name;
    Shape value;
};
const std::vector<ShapeRow> kShapes = {{"round", Shape::Round}, {"square", Shape::Square}};

struct Run {
    int cells = 0;
};

struct Toy {
    double gap = -1;
    std::int64_t steps = -1;
    std::size_t rows = 0;
    bool on = false;
    std::string label;  // read by hand: not bound
    Run run;
    double cap = -2;  // optional: kept when the key is absent
    double span = 0;
    Shape shape = Shape::Round;
    int frames = 0;   // --vtk only
};

BoundKeys<Toy> toy_keys() {
    BoundKeys<Toy> k(SectionSpec("toy", "stand-in solver"));
    k.real("gap", &Toy::gap, 0.5, Range::positive(), "m", "a length").old_names({"spacing"});
    k.integer("steps", &Toy::steps, 10, Range::at_least(1), "a count");
    k.spec.integer("rows", 3, Range::at_least(1), "declared by a shared helper");
    k.bind("rows", &Toy::rows);
    k.boolean("on", &Toy::on, true, "a switch");
    k.spec.string("label", "x", "not bound");
    k.integer("cells", part(&Toy::run, &Run::cells), 20, Range::at_least(1), "a part's member")
        .full("cells_full", 80, "cells with --full");
    k.real_optional("cap", &Toy::cap, Range::positive(), "", "no default");
    k.real("span", &Toy::span, 1.5, Range::positive(), "s", "a real with a --full partner")
        .full("span_full", 4.0, "span with --full");
    k.choice("shape", &Toy::shape, kShapes, Shape::Square, "a registry choice");
    k.integer("frames", &Toy::frames, 5, Range::at_least(1), "read with --vtk only").only_with_vtk().output_only();
    return k;
}

const BoundKeys<Toy>& keys() {
    static const BoundKeys<Toy> k = toy_keys();
    return k;
}

Toy read(const std::string& text, KeyUse use = {}) {
    Schema schema = Schema::common();
    schema.add(keys().spec);
    const Case c = parse_case(kValidCase + "\n[toy]\n" + text, "t.toml", schema);
    Toy t;
    keys().read(t, c.section("toy"), use);
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

BOOST_AUTO_TEST_CASE(bound_keys_fill_parts_options_choices_and_run_variants) {
    const Toy d = read("");
    BOOST_TEST(d.run.cells == 20);
    BOOST_TEST(d.cap == -2);  // absent optional key: the field's own value
    BOOST_TEST((d.shape == Shape::Square));
    BOOST_TEST(d.frames == 0);  // without --vtk
    const Toy g = read("cells = 30\ncells_full = 90\ncap = 0.5\nshape = \"round\"\nframes = 7\n");
    BOOST_TEST(g.run.cells == 30);
    BOOST_TEST(g.cap == 0.5);
    BOOST_TEST((g.shape == Shape::Round));
    BOOST_TEST(g.frames == 0);
    const Toy f = read("cells = 30\ncells_full = 90\nframes = 7\n", {true, true});
    BOOST_TEST(f.run.cells == 90);  // the --full partner
    BOOST_TEST(f.span == 4.0);
    BOOST_TEST(d.span == 1.5);
    const KeySpec& span_full = *keys().spec.find("span_full");
    BOOST_TEST((span_full.type == KeyType::Real));
    BOOST_TEST(span_full.unit == "s");
    BOOST_TEST(f.frames == 7);
    BOOST_TEST(keys().key_name("cells", {true, false}) == "cells_full");
    BOOST_TEST(keys().key_name("cells", {false, false}) == "cells");
    BOOST_TEST(keys().key_name("gap", {true, false}) == "gap");
    BOOST_TEST(keys().spec.find("cells_full")->range.text() == keys().spec.find("cells")->range.text());
    BOOST_TEST(keys().spec.find("shape")->choices == std::vector<std::string>({"round", "square"}),
               boost::test_tools::per_element());
    // get() writes each field back as the case file does: the choice by its name, counts as integers
    std::map<std::string, Value> back;
    for (const auto& b : keys().bindings()) back[b.key] = b.get(g);
    BOOST_TEST(std::get<std::string>(back.at("shape")) == "round");
    BOOST_TEST(std::get<std::int64_t>(back.at("cells")) == 30);
    BOOST_TEST(std::get<double>(back.at("cap")) == 0.5);
    BOOST_TEST(std::get<bool>(back.at("on")));
    BOOST_TEST(keys().bindings().back().output_only);
    BoundKeys<Toy> k(SectionSpec("toy", "stand-in solver"));
    BOOST_CHECK_THROW(k.output_only(), Error);  // nothing bound yet
}
