// Result files: round trip, refusal of non-finite data, atomicity, and the resume test.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <fmt/format.h>

#include "case_text.h"
#include "granlub/case/case.h"
#include "granlub/error.h"
#include "granlub/results/file_io.h"
#include "granlub/results/results.h"
#include "granlub/results/run_id.h"

using namespace granlub;
using granlub::test::TmpDir;
namespace fs = std::filesystem;

namespace {


Case test_case() { return parse_case(granlub::test::kValidCase, "t.toml", Schema::common()); }

Profile small_profile() {
    Profile p;
    p.add("y_over_H", {0.0, 0.5, 1.0})
        .add("u_over_U", {0.9, 0.5, 0.1})
        .add("solid_fraction", {0.50, 0.55, 0.50})
        .add("temperature_over_U2", {0.02, 0.015, 0.02})
        .add("u_over_U_stderr", {0.01, 0.01, 0.01});
    return p;
}

Summary small_summary(const Case& c, std::uint64_t seed = 7) {
    Summary s = make_summary(c, c.points[0], "toy", seed);
    s.set("normal_stress_bottom", 1000.0, "Pa", 12.5)
        .set("normal_stress_top", 990.0, "Pa", 13.0)
        .set("shear_stress_bottom", 300.0, "Pa")
        .set("shear_stress_top", 301.0, "Pa")
        .set("slip_bottom", 0.1, "m/s")
        .set("slip_top", 0.1, "m/s")
        .set("mean_solid_fraction", 0.52, "")
        .set("max_solid_fraction", 0.65, "");
    s.run = {{"steps", 1000}};
    return s;
}

fs::path point_dir(const fs::path& root, const Case& c) {
    const fs::path d = result_dir(root, "toy", c.points[0].id);
    fs::create_directories(d);
    return d;
}

bool tmp_files_left(const fs::path& dir) {
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp.") != std::string::npos) return true;
    return false;
}

}  // namespace

BOOST_AUTO_TEST_CASE(round_trip) {
    TmpDir t("roundtrip");
    const Case c = test_case();
    write_result(t.path, small_profile(), small_summary(c));
    const Profile p = read_profile(t.path / "profile.csv");
    BOOST_TEST(p.names == small_profile().names, boost::test_tools::per_element());
    BOOST_TEST(p.column("u_over_U") == small_profile().column("u_over_U"), boost::test_tools::per_element());
    const Summary s = read_summary(t.path / "summary.json");
    BOOST_TEST(s.solver == "toy");
    BOOST_TEST(s.point == "U1.0");
    BOOST_TEST(s.value("normal_stress_bottom") == 1000.0);
    BOOST_TEST(*s.outputs.at("normal_stress_bottom").stderr_ == 12.5);
    BOOST_TEST(!s.outputs.at("shear_stress_bottom").stderr_.has_value());
    BOOST_TEST(s.provenance.seed.value() == 7u);
    BOOST_TEST(s.provenance.case_hash == c.file_hash);
    BOOST_TEST(s.provenance.inputs_hash == c.inputs_hash("toy"));
    BOOST_TEST(!s.provenance.version.empty());
    BOOST_TEST(s.provenance.utc_time.size() == 20u);  // 2026-11-21T12:00:00Z
    BOOST_TEST(s.inputs.at("speed").get<double>() == 1.0);
    BOOST_TEST(s.run.at("steps").get<int>() == 1000);
}

BOOST_AUTO_TEST_CASE(non_finite_values_write_nothing) {
    TmpDir t("nan");
    const Case c = test_case();
    Profile p = small_profile();
    p.columns[1][1] = std::nan("");
    BOOST_CHECK_THROW(write_result(t.path, p, small_summary(c)), SolverError);
    Summary s = small_summary(c);
    s.set("slip_top", INFINITY, "m/s");
    BOOST_CHECK_THROW(write_result(t.path, small_profile(), s), SolverError);
    Summary neg = small_summary(c);
    neg.set("shear_stress_top", 301.0, "Pa", -2.0);
    BOOST_CHECK_THROW(write_result(t.path, small_profile(), neg), SolverError);
    BOOST_TEST(fs::is_empty(t.path));
}

BOOST_AUTO_TEST_CASE(incomplete_outputs_are_refused) {
    TmpDir t("incomplete");
    const Case c = test_case();
    Summary s = small_summary(c);
    s.outputs.erase("slip_top");
    BOOST_CHECK_THROW(write_result(t.path, small_profile(), s), Error);
    Profile p;
    p.add("y_over_H", {0, 1}).add("u_over_U", {1, 0});
    BOOST_CHECK_THROW(write_result(t.path, p, small_summary(c)), Error);
    BOOST_TEST(fs::is_empty(t.path));
}

BOOST_AUTO_TEST_CASE(failure_mid_write_leaves_nothing_complete_looking) {
    TmpDir t("midwrite");
    const Case c = test_case();
    const std::string hash = c.inputs_hash("toy");
    const fs::path dir = point_dir(t.path, c);  // <root>/<solver>/<point>, as the contract has it
    write_result(dir, small_profile(), small_summary(c));
    BOOST_TEST((result_status(dir, hash).state == ResultState::Complete));
    // Make the second file impossible to put in place (a non-empty directory where summary.json
    // goes): the profile is rewritten, the summary rename fails.
    fs::remove(dir / "summary.json");
    fs::create_directories(dir / "summary.json" / "blocker");
    BOOST_CHECK_THROW(write_result(dir, small_profile(), small_summary(c)), Error);
    BOOST_TEST((result_status(dir, hash).state != ResultState::Complete));
    BOOST_TEST(!tmp_files_left(dir));
    // A failed write of a single file leaves neither the target nor a temp file.
    BOOST_CHECK_THROW(write_file_atomic(dir / "summary.json", "x"), Error);
    BOOST_TEST(!tmp_files_left(dir));
}

BOOST_AUTO_TEST_CASE(atomic_write_replaces_whole_file) {
    TmpDir t("atomic");
    write_file_atomic(t.path / "a.txt", "first version, long content\n");
    write_file_atomic(t.path / "a.txt", "second\n");
    std::ifstream in(t.path / "a.txt");
    std::string all((std::istreambuf_iterator<char>(in)), {});
    BOOST_TEST(all == "second\n");
    BOOST_TEST(!tmp_files_left(t.path));
}

// Two threads writing one file at once (as two processes, or two nodes over a shared filesystem,
// may): every read and the file they leave is one of the writes, whole, and no temp file is left.
BOOST_AUTO_TEST_CASE(concurrent_writers_of_one_file_leave_one_write_whole) {
    TmpDir t("atomic_concurrent");
    const fs::path file = t.path / "summary.json";
    constexpr int kRounds = 60;
    // write r of writer w: a header naming both, then a body of w's letter whose length depends on both
    const auto content = [](int w, int r) {
        return fmt::format("writer {} round {}\n", w, r) + std::string(20000 + 997 * r + 5000 * w, w ? 'b' : 'a');
    };
    const auto whole = [&](const std::string& text) {
        int w = -1, r = -1;
        return std::sscanf(text.c_str(), "writer %d round %d", &w, &r) == 2 && (w == 0 || w == 1) && r >= 0 &&
               r < kRounds && text == content(w, r);
    };
    write_file_atomic(file, content(0, 0));
    std::atomic<int> done{0}, torn{0}, reads{0};
    std::vector<std::thread> writers;
    for (int w = 0; w < 2; ++w)
        writers.emplace_back([&, w] {
            for (int r = 0; r < kRounds; ++r) write_file_atomic(file, content(w, r));
            ++done;
        });
    std::thread reader([&] {
        while (done < 2) {
            if (!whole(read_file(file))) ++torn;
            ++reads;
        }
    });
    for (auto& th : writers) th.join();
    reader.join();
    BOOST_TEST(torn.load() == 0, torn.load() << " of " << reads.load() << " reads were no whole write");
    const std::string last = read_file(file);
    BOOST_TEST((last == content(0, kRounds - 1) || last == content(1, kRounds - 1)));
    BOOST_TEST(!tmp_files_left(t.path));
}

BOOST_AUTO_TEST_CASE(resume_detection) {
    TmpDir t("resume");
    const Case c = test_case();
    const std::string hash = c.inputs_hash("toy");
    const fs::path dir = point_dir(t.path, c);  // <root>/<solver>/<point>, as the contract has it
    BOOST_TEST((result_status(dir, hash).state == ResultState::Missing));
    write_result(dir, small_profile(), small_summary(c));
    BOOST_TEST((result_status(dir, hash).state == ResultState::Complete));
    // A changed case makes the result stale.
    const Case changed =
        parse_case(granlub::test::with("density = 2500.0", "density = 2600.0"), "t.toml", Schema::common());
    const auto stale = result_status(dir, changed.inputs_hash("toy"));
    BOOST_TEST((stale.state == ResultState::Stale));
    BOOST_TEST(stale.reason.find("computed for inputs") != std::string::npos);
    // Given the case, the reason names the key that changed, not two hashes.
    const auto named = load_result(dir, result_key(changed, "toy")).status;
    BOOST_TEST((named.state == ResultState::Stale));
    BOOST_TEST(named.reason.find("computed before the case changed: [grains] density = 2500 -> 2600") !=
                   std::string::npos,
               named.reason);
    // Truncated JSON, a broken profile or a missing profile are corrupt, not complete.
    { std::ofstream(dir / "summary.json") << "{\"format\": \"granlub-summary-1\", "; }
    BOOST_TEST((result_status(dir, hash).state == ResultState::Corrupt));
    write_result(dir, small_profile(), small_summary(c));
    { std::ofstream(dir / "profile.csv") << "y_over_H,u_over_U\n0,abc\n"; }
    const auto bad = result_status(dir, hash);
    BOOST_TEST((bad.state == ResultState::Corrupt));
    BOOST_TEST(bad.reason.find("'abc' is not a number") != std::string::npos, bad.reason);
    fs::remove(dir / "profile.csv");
    BOOST_TEST((result_status(dir, hash).state == ResultState::Corrupt));
}

BOOST_AUTO_TEST_CASE(malformed_files_give_clear_errors) {
    BOOST_CHECK_EXCEPTION(parse_profile_csv("y_over_H,u_over_U,solid_fraction\n0,1,0.5\n1,0,0.5\n", "p.csv"), Error,
                          [](const Error& e) {
                              return std::string(e.what()).find("missing required column 'temperature_over_U2'") !=
                                     std::string::npos;
                          });
    BOOST_CHECK_EXCEPTION(
        parse_profile_csv("y_over_H,u_over_U,solid_fraction,temperature_over_U2\n0,1,0.5\n", "p.csv"), Error,
        [](const Error& e) { return std::string(e.what()).find("p.csv:2: 3 values, the header has 4") != std::string::npos; });
    BOOST_CHECK_EXCEPTION(summary_from_json(nlohmann::json{{"format", "other"}}, "s.json"), Error, [](const Error& e) {
        return std::string(e.what()).find("not a granlub summary") != std::string::npos;
    });
}

// Issue: one definition of "complete" for the solvers and compare, and a corrupt file never
// aborts the reader (a 1e999 used to escape as json out_of_range).
BOOST_AUTO_TEST_CASE(unsound_results_are_corrupt_not_fatal) {
    TmpDir t("unsound");
    const Case c = test_case();
    const std::string hash = c.inputs_hash("toy");
    const fs::path dir = point_dir(t.path, c);
    auto corrupt_after = [&](const char* what, auto&& spoil, const std::string& expect) {
        write_result(dir, small_profile(), small_summary(c));
        BOOST_TEST_REQUIRE((result_status(dir, hash, c.name).state == ResultState::Complete));
        spoil();
        const LoadedResult r = load_result(dir, hash, c.name);
        BOOST_TEST((r.status.state == ResultState::Corrupt), what);
        BOOST_TEST(r.status.reason.find(expect) != std::string::npos, what << ": " << r.status.reason);
        BOOST_TEST(!r.summary.has_value());
    };
    auto replace_in = [&](const fs::path& f, const std::string& from, const std::string& to) {
        std::ifstream in(f);
        std::string text((std::istreambuf_iterator<char>(in)), {});
        const auto pos = text.find(from);
        BOOST_TEST_REQUIRE(pos != std::string::npos, f.string() << " lacks " << from);
        text.replace(pos, from.size(), to);
        std::ofstream(f) << text;
    };
    corrupt_after("1e999 in the summary", [&] { replace_in(dir / "summary.json", "1000.0", "1e999"); },
                  "summary.json: not valid JSON");
    corrupt_after("NaN in the profile", [&] { replace_in(dir / "profile.csv", "0.55", "nan"); },
                  "solid_fraction is not a finite number");
    corrupt_after("negative stderr column", [&] { replace_in(dir / "profile.csv", ",0.01\n", ",-0.01\n"); },
                  "u_over_U_stderr = -0.01");
    corrupt_after("y not increasing", [&] { replace_in(dir / "profile.csv", "\n0.5,", "\n1.5,"); },
                  "y_over_H = 1.5");
    corrupt_after("another point's summary", [&] { replace_in(dir / "summary.json", "\"point\": \"U1.0\"", "\"point\": \"U9\""); },
                  "says point \"U9\"");
    corrupt_after("another case", [&] { replace_in(dir / "summary.json", "\"case\": \"t\"", "\"case\": \"u\""); },
                  "says case \"u\"");
    corrupt_after("summary is a directory", [&] {
        fs::remove(dir / "summary.json");
        fs::create_directories(dir / "summary.json");
    }, "not a regular file");
    fs::remove_all(dir / "summary.json");
}

// The run id (run_id.h): one per process, readable, and read back from the comment lines of a
// table, never from its data.
BOOST_AUTO_TEST_CASE(run_id_names_this_process_and_is_read_back_from_tables) {
    const std::string& id = run_id();
    BOOST_TEST(&id == &run_id());  // made once
    // UTC time, host, pid, 8 hex digits
    const auto dash = id.rfind('-');
    BOOST_TEST_REQUIRE(dash != std::string::npos);
    BOOST_TEST(id.size() - dash - 1 == 8u, id);
    BOOST_TEST(id.find(fmt::format("-{}-", ::getpid())) != std::string::npos, id);
    BOOST_TEST(id.substr(8, 1) == "T", id);
    BOOST_TEST(id.substr(15, 2) == "Z-", id);
    BOOST_TEST(id.find_first_of(" \t\n,#") == std::string::npos, id);

    const std::string csv = profile_csv(small_profile(), {"case t point U1.0"});
    BOOST_TEST(table_run_id(csv).value_or("") == id);
    BOOST_TEST(table_run_id(profile_csv(small_profile(), {}, "another-run")).value_or("") == "another-run");
    BOOST_TEST(!table_run_id("# a table before run ids\ny_over_H\n0\n").has_value());
    BOOST_TEST(!table_run_id("y_over_H\n# run_id late\n0\n").has_value());  // not a leading comment
    // the profile still parses as before: the run is a comment
    BOOST_TEST(parse_profile_csv(csv, "p.csv").rows() == 3u);
}
