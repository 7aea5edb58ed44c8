// Sweep expansion, stable point ids, per-point walls, defaults, hashes and the two shipped cases.
#include <boost/test/unit_test.hpp>

#include "case_text.h"
#include "granlub/case/case.h"
#include "granlub/error.h"

using namespace granlub;
using granlub::test::kValidCase;
using granlub::test::with;

namespace {
std::vector<std::string> ids(const Case& c) {
    std::vector<std::string> out;
    for (const auto& p : c.points) out.push_back(p.id);
    return out;
}
}  // namespace

BOOST_AUTO_TEST_CASE(cartesian_product_in_declared_order) {
    Case c = parse_case(with("solid_fraction = 0.5", "solid_fraction = [0.4, 0.5]\nroughness = [0, 1]"), "t.toml",
                        Schema::common());
    BOOST_REQUIRE_EQUAL(c.points.size(), 8u);
    const std::vector<std::string> expect = {"U1.0_nu0.4_R0", "U1.0_nu0.4_R1", "U1.0_nu0.5_R0", "U1.0_nu0.5_R1",
                                             "U2.0_nu0.4_R0", "U2.0_nu0.4_R1", "U2.0_nu0.5_R0", "U2.0_nu0.5_R1"};
    BOOST_TEST(ids(c) == expect, boost::test_tools::per_element());
    BOOST_TEST(c.points[5].speed == 2.0);
    BOOST_TEST(c.points[5].solid_fraction == 0.4);
    BOOST_TEST(c.points[5].bottom.roughness == 1.0);
    BOOST_TEST(c.points[5].top.roughness == 1.0);
    for (std::size_t i = 0; i < c.points.size(); ++i) BOOST_TEST(c.points[i].index == i);
}

BOOST_AUTO_TEST_CASE(ids_are_stable_when_a_list_grows) {
    Case a = parse_case(kValidCase, "t.toml", Schema::common());
    Case b = parse_case(with("speed = [1.0, 2.0]", "speed = [1.0, 2.0, 3.5]"), "t.toml", Schema::common());
    BOOST_TEST(ids(a) == (std::vector<std::string>{"U1.0", "U2.0"}), boost::test_tools::per_element());
    BOOST_TEST(ids(b) == (std::vector<std::string>{"U1.0", "U2.0", "U3.5"}), boost::test_tools::per_element());
    // A scalar key does not enter the id; a one-element list does (it is declared as swept).
    Case s = parse_case(with("speed = [1.0, 2.0]", "speed = 1.5"), "t.toml", Schema::common());
    BOOST_TEST(ids(s) == (std::vector<std::string>{"U1.5"}), boost::test_tools::per_element());
    Case l = parse_case(with("normal_stress = 1000.0", "normal_stress = [1000.0]"), "t.toml", Schema::common());
    BOOST_TEST(l.points[0].id == "U1.0_P1000");
}

BOOST_AUTO_TEST_CASE(per_wall_overrides) {
    Case c = parse_case(kValidCase + "\n[walls.top]\nrestitution = 0.6\n", "t.toml", Schema::common());
    BOOST_TEST(c.bottom.restitution == 0.8);
    BOOST_TEST(c.top.restitution == 0.6);
    BOOST_TEST(c.top.roughness == 0.5);
    BOOST_TEST(c.points[0].top.restitution == 0.6);
    BOOST_TEST(c.top.friction == 0.5);  // default of [walls] friction
}

BOOST_AUTO_TEST_CASE(selection_by_point_id) {
    Case c = parse_case(kValidCase, "t.toml", Schema::common());
    BOOST_TEST(c.select("").size() == 2u);
    BOOST_TEST(c.select("U2.0").front()->speed == 2.0);
    try {
        c.select("U9");
        BOOST_FAIL("unknown point accepted");
    } catch (const Error& e) {
        BOOST_TEST(std::string(e.what()).find("no operating point 'U9' (points: U1.0, U2.0)") != std::string::npos,
                   e.what());
    }
}

BOOST_AUTO_TEST_CASE(hashes_track_what_results_depend_on) {
    SectionSpec toy("toy", "toy");
    toy.integer("steps", 100, Range::at_least(1), "steps");
    Schema schema = Schema::common();
    schema.add(toy);
    Case a = parse_case(kValidCase, "t.toml", schema);
    Case comment = parse_case("# another comment\n" + kValidCase, "t.toml", schema);
    Case toy_changed = parse_case(kValidCase + "\n[toy]\nsteps = 7\n", "t.toml", schema);
    Case physics_changed = parse_case(with("density = 2500.0", "density = 2600.0"), "t.toml", schema);
    BOOST_TEST(a.file_hash != comment.file_hash);
    BOOST_TEST(a.inputs_hash("toy") == comment.inputs_hash("toy"));        // comments do not matter
    BOOST_TEST(a.inputs_hash("toy") != toy_changed.inputs_hash("toy"));    // own section matters
    BOOST_TEST(a.inputs_hash("other") == toy_changed.inputs_hash("other")); // others' sections do not
    BOOST_TEST(a.inputs_hash("other") != physics_changed.inputs_hash("other"));
    // a key with a neutral default ([walls] sides = "plane", added after results existed) is no
    // input at its default, whether defaulted or written out; any other value is
    KeySpec added;
    added.name = "added";
    added.type = KeyType::Choice;
    added.default_value = Value(std::string("off"));
    added.choices = {"off", "on"};
    added.doc = "added later";
    added.neutral_default = true;
    toy.keys.push_back(added);
    Schema later = Schema::common();
    later.add(toy);
    const Case at_default = parse_case(kValidCase + "\n[toy]\nadded = \"off\"\n", "t.toml", later);
    const Case set = parse_case(kValidCase + "\n[toy]\nadded = \"on\"\n", "t.toml", later);
    BOOST_TEST(parse_case(kValidCase, "t.toml", later).inputs_hash("toy") == a.inputs_hash("toy"));
    BOOST_TEST(at_default.inputs_hash("toy") == a.inputs_hash("toy"));
    BOOST_TEST(!at_default.inputs("toy").count("[toy] added"));
    BOOST_TEST(set.inputs_hash("toy") != a.inputs_hash("toy"));
    BOOST_TEST(set.inputs("toy").at("[toy] added") == "\"on\"");
    const Case sides = parse_case(with("roughness = 0.5", "roughness = 0.5\nsides = \"plane\""), "t.toml", schema);
    BOOST_TEST(sides.inputs_hash("toy") == a.inputs_hash("toy"));
}

BOOST_AUTO_TEST_CASE(describe_marks_defaults_and_lists_points) {
    Case c = parse_case(kValidCase, "t.toml", Schema::common());
    const std::string d = describe(c);
    BOOST_TEST(d.find("friction             = 0.5                    # (default)") != std::string::npos, d);
    BOOST_TEST(d.find("diameter             = 0.001                  # [m]") != std::string::npos, d);
    BOOST_TEST(d.find("# 2 operating point(s)") != std::string::npos);
    BOOST_TEST(d.find("U2.0") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(shipped_cases) {
    // the fixed-fill variant (the default case has an [automaton] section, like jasti2006 below)
    Case s = load_case(std::string(GRANLUB_SOURCE_DIR) + "/cases/sawyer2001_fill", Schema::common());
    BOOST_TEST(ids(s) == (std::vector<std::string>{"U1.4", "U2.0", "U2.8"}), boost::test_tools::per_element());
    BOOST_TEST(s.grains.diameter == 0.787e-3);
    BOOST_TEST(s.cell.gap / s.grains.diameter > 5.0);
    BOOST_TEST((s.points[1].control == Control::Fill));
    BOOST_TEST(s.points[1].solid_fraction == 0.595);
    // jasti2006 has an [automaton] section, declared by that module: with the common schema only
    // it must be rejected as unknown, by name.
    try {
        load_case(std::string(GRANLUB_SOURCE_DIR) + "/cases/jasti2006", Schema::common());
        BOOST_FAIL("unknown section accepted");
    } catch (const CaseError& e) {
        BOOST_TEST(std::string(e.what()).find("[automaton]: unknown section") != std::string::npos);
    }
    SectionSpec a("automaton", "stand-in");
    a.real("fill", 0.5, Range::open_closed(0, 1), "", "lattice fill");
    Schema schema = Schema::common();
    schema.add(a);
    Case j = load_case(std::string(GRANLUB_SOURCE_DIR) + "/cases/jasti2006", schema);
    BOOST_TEST(ids(j) == (std::vector<std::string>{"U2.0_R0", "U2.0_R0.25", "U2.0_R0.5", "U2.0_R0.65", "U2.0_R0.75",
                                                   "U2.0_R1"}),
               boost::test_tools::per_element());
    BOOST_TEST(j.points[2].bottom.roughness == 0.5);
    BOOST_TEST(j.points[2].bottom.restitution == 0.65);
    BOOST_TEST(j.section("automaton").real("fill") == 0.85);
}

BOOST_AUTO_TEST_CASE(old_key_names_read_with_a_warning) {
    // A renamed key (SectionSpec::old_names): the old name still sets it, with a warning naming the
    // file, both names and what to write; both names at once are refused; the key table says so.
    SectionSpec x("extra", "stand-in solver");
    x.integer("snapshot_every", 100, Range::at_least(1), "interval").old_names({"vtk_every"});
    x.real("tolerance", 0.1, Range::positive(), "", "a key declared after the renamed one");
    Schema schema = Schema::common();
    schema.add(x);
    const std::string base = kValidCase + "\n[extra]\n";
    const Case now = parse_case(base + "snapshot_every = 7\n", "t.toml", schema);
    BOOST_TEST(now.warnings.empty());
    BOOST_TEST(now.section("extra").integer("snapshot_every") == 7);
    const Case old = parse_case(base + "vtk_every = 7\n", "t.toml", schema);
    BOOST_TEST(old.section("extra").integer("snapshot_every") == 7);
    BOOST_TEST(!old.section("extra").is_default("snapshot_every"));
    BOOST_TEST(old.inputs_hash("extra") == now.inputs_hash("extra"));  // the same input, however spelled
    BOOST_REQUIRE_EQUAL(old.warnings.size(), 1u);
    BOOST_TEST(old.warnings[0].find("t.toml:") != std::string::npos, old.warnings[0]);
    BOOST_TEST(old.warnings[0].find("[extra] vtk_every is the old name of snapshot_every") != std::string::npos,
               old.warnings[0]);
    for (const std::string both : {"vtk_every = 7\nsnapshot_every = 7\n", "snapshot_every = 7\nvtk_every = 7\n"}) {
        try {
            parse_case(base + both, "t.toml", schema);
            BOOST_FAIL("both names accepted");
        } catch (const CaseError& e) {
            BOOST_TEST(std::string(e.what()).find("which is also given") != std::string::npos, e.what());
        }
    }
    // an old value of the renamed key is range-checked as the key
    BOOST_CHECK_THROW(parse_case(base + "vtk_every = 0\n", "t.toml", schema), CaseError);
    BOOST_TEST(key_table(x).find("old name still read: vtk_every") != std::string::npos);
    // an old name that is a key, or an old name twice, is a declaration error
    BOOST_CHECK_THROW(SectionSpec(x).old_names({"tolerance"}), Error);
    BOOST_CHECK_THROW(SectionSpec(x).old_names({"vtk_every"}), Error);
}
