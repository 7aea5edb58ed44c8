// [case] base (core/src/case/case_base.h): a case file merged over the case it is a variant of.
#include <boost/test/unit_test.hpp>

#include <fstream>

#include "case_text.h"
#include "granlub/case/case.h"
#include "granlub/error.h"

using namespace granlub;
using granlub::test::kValidCase;
using granlub::test::load_error;
using granlub::test::TmpDir;
using granlub::test::with;

namespace {
namespace fs = std::filesystem;

fs::path write(const fs::path& dir, const std::string& text) {
    fs::create_directories(dir);
    std::ofstream(dir / "case.toml") << text;
    return dir;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A base with a sweep and a per-wall table; the twin names it.
const std::string kBase =
    with("name = \"t\"", "name = \"parent\"\ntitle = \"the parent\"") + "\n[walls.bottom]\nroughness = 0.3\n";
}  // namespace

BOOST_AUTO_TEST_CASE(a_twin_is_its_base_with_its_own_keys_over_it) {
    TmpDir tmp("case_base_merge");
    write(tmp.path / "parent", kBase);
    const auto twin = write(tmp.path / "twin", "[case]\nbase = \"../parent\"\n\n[cell]\nwidth = 0.01\n\n"
                                               "[walls.bottom]\nfriction = 0.2\n\n[operating]\nspeed = [3.0]\n");
    const Case c = load_case(twin, Schema::common());
    const Case p = load_case(tmp.path / "parent", Schema::common());
    BOOST_TEST(c.cell.width == 0.01);          // given here
    BOOST_TEST(c.cell.gap == p.cell.gap);      // the rest of [cell] is the base's
    BOOST_TEST(c.grains.density == 2500.0);    // a table not given is the base's
    BOOST_TEST(c.bottom.roughness == 0.3);     // a sub-table merged key by key: the base's roughness...
    BOOST_TEST(c.bottom.friction == 0.2);      // ... and this file's friction
    BOOST_REQUIRE_EQUAL(c.points.size(), 1u);  // a list replaces the base's as a whole
    BOOST_TEST(c.points[0].id == "U3.0");
    BOOST_TEST(c.points[0].solid_fraction == 0.5);
    // [case] is never inherited: the name is the directory's, the title none
    BOOST_TEST(c.name == "twin");
    BOOST_TEST(c.title.empty());
    BOOST_REQUIRE_EQUAL(c.bases.size(), 1u);
    BOOST_TEST(c.bases[0] == tmp.path / "parent" / "case.toml");
    // every value keeps the file it came from (a path in it is relative to that file: [report] slice_case)
    const std::string base_file = (tmp.path / "parent" / "case.toml").string();
    BOOST_TEST(c.section("cell").file_of("gap") == base_file);
    BOOST_TEST(c.section("cell").file_of("width") == (twin / "case.toml").string());
    BOOST_TEST(c.section("walls.bottom").file_of("roughness") == base_file);
    const std::string text = describe(c);
    BOOST_TEST(has(text, "# base: " + base_file), text);
    BOOST_TEST(has(text, "(from base " + base_file + ")"), text);
}

BOOST_AUTO_TEST_CASE(a_base_of_a_base_is_read_first_each_path_relative_to_its_file) {
    TmpDir tmp("case_base_chain");
    write(tmp.path / "a", kBase);
    write(tmp.path / "sub" / "b", "[case]\nbase = \"../../a/case.toml\"\n\n[cell]\nwidth = 0.01\n");
    const auto c3 = write(tmp.path / "c", "[case]\nname = \"c\"\nbase = \"../sub/b\"\n\n[cell]\ngap = 6.0e-3\n");
    const Case c = load_case(c3, Schema::common());
    BOOST_TEST(c.name == "c");
    BOOST_TEST(c.cell.gap == 6.0e-3);
    BOOST_TEST(c.cell.width == 0.01);
    BOOST_TEST(c.bottom.roughness == 0.3);
    BOOST_REQUIRE_EQUAL(c.bases.size(), 2u);  // nearest first
    BOOST_TEST(c.bases[0] == tmp.path / "sub" / "b" / "case.toml");
    BOOST_TEST(c.bases[1] == tmp.path / "a" / "case.toml");
}

BOOST_AUTO_TEST_CASE(a_change_in_the_base_is_a_new_case) {
    TmpDir tmp("case_base_hash");
    write(tmp.path / "parent", kBase);
    const auto twin = write(tmp.path / "twin", "[case]\nbase = \"../parent\"\n");
    const Case before = load_case(twin, Schema::common());
    // without a base the hash is the file's bytes', as before bases existed
    BOOST_TEST(load_case(tmp.path / "parent", Schema::common()).file_hash == hash_hex(kBase));
    write(tmp.path / "parent", kBase + "# a comment\n");
    const Case comment = load_case(twin, Schema::common());
    BOOST_TEST(comment.file_hash != before.file_hash);               // provenance covers the base's bytes
    BOOST_TEST(comment.inputs_hash("x") == before.inputs_hash("x"));  // a comment is no input
    write(tmp.path / "parent", with("density = 2500.0", "density = 2600.0", kBase));
    const Case physics = load_case(twin, Schema::common());
    BOOST_TEST(physics.inputs_hash("x") != before.inputs_hash("x"));  // a base's value is an input
    // where the values were written is not: the base's text pasted in is the same inputs
    std::string pasted = with("name = \"parent\"\ntitle = \"the parent\"", "", kBase);  // [case] as the twin's
    write(tmp.path / "twin", pasted);
    write(tmp.path / "parent", kBase);
    BOOST_TEST(load_case(twin, Schema::common()).inputs_hash("x") == before.inputs_hash("x"));
}

BOOST_AUTO_TEST_CASE(bad_bases_are_named_where_they_are_given) {
    TmpDir tmp("case_base_errors");
    const auto missing = write(tmp.path / "missing", "[case]\nbase = \"../nowhere\"\n");
    const std::string m = load_error(missing);
    BOOST_TEST(has(m, (missing / "case.toml").string() + ":2:8: [case] base = \"../nowhere\": "), m);
    BOOST_TEST(has(m, "no such case directory or file"), m);

    write(tmp.path / "x", "[case]\nbase = \"../y\"\n");
    write(tmp.path / "y", "[case]\nbase = \"../x/case.toml\"\n");
    const std::string cycle = load_error(tmp.path / "x");
    BOOST_TEST(has(cycle, "a cycle: "), cycle);
    BOOST_TEST(has(cycle, (tmp.path / "y" / "case.toml").string() + ":2:8: [case] base"), cycle);
    BOOST_TEST(has(load_error(write(tmp.path / "self", "[case]\nbase = \".\"\n")), "a cycle: "));

    // a chain longer than the bound: each file names the next
    for (int i = 0; i < 12; ++i)
        write(tmp.path / ("n" + std::to_string(i)), "[case]\nbase = \"../n" + std::to_string(i + 1) + "\"\n");
    write(tmp.path / "n12", kBase);
    const std::string chain = load_error(tmp.path / "n0");
    BOOST_TEST(has(chain, "a chain of more than 8 bases"), chain);
    BOOST_TEST(load_error(tmp.path / "n5").empty());  // 7 bases under n5: allowed

    const std::string bad_type = load_error(write(tmp.path / "typed", with("name = \"t\"", "name = \"t\"\nbase = 3")));
    BOOST_TEST(has(bad_type, "[case] base = 3: expected a string"), bad_type);
}

BOOST_AUTO_TEST_CASE(a_base_s_bad_key_is_reported_in_the_base_s_file) {
    TmpDir tmp("case_base_keys");
    const auto parent = write(tmp.path / "parent", with("gap = 5.0e-3", "gap = 5.0e-3\ngapp = 1.0"));
    const auto twin = write(tmp.path / "twin", "[case]\nbase = \"../parent\"\n");
    const std::string unknown = load_error(twin);
    BOOST_TEST(has(unknown, (parent / "case.toml").string() + ":16:8: [cell] gapp: unknown key"), unknown);

    // a check across keys that fails on a base's value names the file that gave that value
    write(tmp.path / "parent", kBase);
    write(tmp.path / "twin", "[case]\nbase = \"../parent\"\n\n[grains]\ndiameter = 3.0e-3\n");
    const std::string cross = load_error(twin);
    BOOST_TEST(has(cross, (parent / "case.toml").string() + ":16:7: [cell] gap = 0.005: the gap must hold"), cross);
    // and one of this file's own keys names this file
    write(tmp.path / "twin", "[case]\nbase = \"../parent\"\n\n[cell]\nwidth = 1.0e-3\n");
    const std::string own = load_error(twin);
    BOOST_TEST(has(own, (twin / "case.toml").string() + ":5:9: [cell] width = 0.001: the width must be"), own);
}
