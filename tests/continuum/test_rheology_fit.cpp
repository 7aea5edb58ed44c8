// The fit of the closures' constants on a bulk-rheology table (rheology_fit.h, `granlub continuum-fit`): on synthetic
// tables made from known constants by the closures' own homogeneous shear (simple_shear.h) with Gaussian noise of
// the rows' stated errors (fixed seed), it recovers the constants within its own error bars; a constant mu, which
// the closures cannot follow, gets a chi2 that says so; the same table gives the same bytes; bad input stops
// naming the key, the row and what is allowed.
#define BOOST_TEST_MODULE continuum_rheology_fit
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <boost/test/unit_test.hpp>

#include "granlub/case/case.h"
#include "granlub/case/wall_bumps.h"
#include "granlub/continuum/case_setup.h"
#include "granlub/continuum/command.h"
#include "granlub/continuum/rheology_fit.h"
#include "granlub/continuum/simple_shear.h"
#include "granlub/error.h"
#include "granlub/particles/bulk_rheology.h"
#include "granlub/results/file_io.h"
#include "temp_dir.h"

using namespace granlub;
using namespace granlub::continuum;
namespace fs = std::filesystem;

namespace {

// The rough cases' extended kinetic theory (cases/sawyer2001_regimes_rough) with Johnson & Jackson's contact stress;
// the constants are the fit's start (or, in truth(), the table's).
const std::string kCase = R"(
[case]
name = "fit_test"
[grains]
diameter = 0.787e-3
density = 2550.0
restitution = 0.9
friction = 0.5
[walls]
restitution = 0.9
roughness = 0.5
[cell]
gap = 24.0e-3
length = 15.74e-3
max_solid_fraction = 0.65
[operating]
speed = 1.0
control = "load"
normal_stress = [2250.0, 5550.0]
[continuum]
closures = "garzo_dufty"
g0 = "chialvo_sundaresan"
max_solid_fraction = 0.587
friction_restitution = "chialvo_sundaresan"
correlation_length = "jenkins_berzi"
correlation_constant = 0.44
contact_stress = "johnson_jackson"
contact_coefficient = 0.05
contact_onset_fraction = 0.5
contact_exponent_onset = 2.0
contact_exponent_jamming = 5.0
contact_friction = 0.36
)";

Schema schema() {
    Schema s = Schema::common();
    s.add(continuum::section());
    return s;
}

// kCase with `from` replaced by `to` (each must occur)
std::string with(std::string text, const std::vector<std::pair<std::string, std::string>>& edits) {
    for (const auto& [from, to] : edits) {
        const auto at = text.find(from);
        if (at == std::string::npos) throw std::logic_error("case text lacks " + from);
        text.replace(at, from.size(), to);
    }
    return text;
}

Case parse(const std::string& text) { return parse_case(text, "fit.toml", schema()); }

// the case without its contact stress: the extended kinetic theory alone
std::string kinetic_only(const std::string& text) {
    return with(text, {{"contact_stress = \"johnson_jackson\"", ""},
                       {"contact_coefficient = 0.05", ""},
                       {"contact_onset_fraction = 0.5", ""},
                       {"contact_exponent_onset = 2.0", ""},
                       {"contact_exponent_jamming = 5.0", ""},
                       {"contact_friction = 0.36", ""}});
}

// The fit's start: c = 0.8, where the correlation length exceeds 1 at every row (at the rough cases' c = 0.44 it is
// 1 below nu ~ 0.56 and the contact stress keeps nu below that: c would act on no row).
const std::string kStart = with(kCase, {{"correlation_constant = 0.44", "correlation_constant = 0.8"}});
// The table's constants: c, Fr and mu_c away from the start's.
const std::string kTruth = with(kCase, {{"correlation_constant = 0.44", "correlation_constant = 1.0"},
                                        {"contact_coefficient = 0.05", "contact_coefficient = 0.08"},
                                        {"contact_friction = 0.36", "contact_friction = 0.33"}});
const std::vector<std::string> kFree = {"correlation_constant", "contact_coefficient", "contact_friction"};

// The stated errors of the synthetic rows, of the size the DEM's core gives (cases/bulk_shear/README.md):
// mu +- 0.005, nu +- 0.002, T/(d gdot)^2 +- 5 %.
constexpr double kMuErr = 0.005, kNuErr = 0.002, kTRelErr = 0.05;

// Standard normal deviates from mt19937_64 by Box-Muller: the same numbers with every standard library
// (std::normal_distribution's algorithm is the library's own).
struct Normal {
    std::mt19937_64 rng;
    explicit Normal(std::uint64_t seed) : rng(seed) {}
    double uniform() { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; }
    double operator()() {
        return std::sqrt(-2 * std::log(uniform())) * std::cos(2 * 3.14159265358979323846 * uniform());
    }
};

struct Row {
    std::string id;
    double P, I, mu, nu, T;
    std::string status = "steady", core = "converged";
};

// The closures' homogeneous shear of `truth` at (I, P) for each point: at 2250 and 5550 Pa, I from 1e-3 to 0.2,
// plus noise of the stated errors when a seed is given (seed 0: exact).
std::vector<Row> synthetic(const std::string& truth, std::uint64_t seed, const std::vector<double>& Is = {
                                                                              1e-3, 3e-3, 0.01, 0.03, 0.1, 0.2}) {
    const Settings s = resolve_settings(parse(truth));
    Normal noise(seed ? seed : 1);
    std::vector<Row> rows;
    for (double P : {2250.0, 5550.0})
        for (double I : Is) {
            ContactStress cs = s.contact;
            cs.coefficient /= P;
            const SimpleShear h = simple_shear_at_inertial(s.closures->with_contact(cs), I);
            Row r{fmt::format("I{}_P{}", I, P), P, I, h.stress_ratio, h.nu, h.temperature};
            if (seed) {
                r.mu += kMuErr * noise();
                r.nu += kNuErr * noise();
                r.T *= 1 + kTRelErr * noise();
            }
            rows.push_back(r);
        }
    return rows;
}

std::string table_text(const std::vector<Row>& rows, const std::string& format = "granlub-bulk-rheology 1") {
    std::string t = fmt::format("# format {}\n# case synthetic (test_rheology_fit.cpp)\n", format);
    t += "point,load_Pa,status,core_dt_check,pressure_Pa,pressure_err,I,I_err,mu,mu_err,nu,nu_err,T_scaled,"
         "T_scaled_err\n";
    for (const Row& r : rows)
        t += fmt::format("{},{},{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", r.id, r.P,
                         r.status, r.core, r.P, 0.01 * r.P, r.I, 0.01 * r.I, r.mu, kMuErr, r.nu, kNuErr, r.T,
                         kTRelErr * r.T);
    return t;
}

FitResult fit(const std::string& case_text, const std::vector<Row>& rows, std::vector<std::string> free = kFree,
              bool temperature = false) {
    const BulkRows t = parse_bulk_table(table_text(rows), "synthetic.csv");
    return fit_bulk_rheology(resolve_settings(parse(case_text)), t.answers(), {std::move(free), temperature, nullptr, {}},
                             "synthetic.csv");
}

double constant(const FitResult& r, const std::string& key) {
    for (const auto& c : r.constants)
        if (c.key == key) return c.value;
    throw std::logic_error("no constant " + key);
}

double truth(const std::string& key) {
    const Case c = parse(kTruth);
    return c.section("continuum").real(key);
}

using testing::TempDir;

// The CaseError's message of running `f`, "" when it throws none.
template <class F>
std::string case_error(F&& f) {
    try {
        f();
    } catch (const CaseError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// Without noise the fit lands on the table's constants (chi2 ~ 0): the model the table was made with and the one
// fitted are the same closures through two paths (the solver's Settings, the fit's trial constants).
BOOST_AUTO_TEST_CASE(an_exact_table_gives_back_its_constants) {
    const FitResult r = fit(kStart, synthetic(kTruth, 0));
    for (const auto& k : kFree) BOOST_TEST(constant(r, k) == truth(k), boost::test_tools::tolerance(1e-5));
    BOOST_TEST(r.chi2 < 1e-8);
    BOOST_TEST(r.dof == 24u - 3u);
    // started on the answer, it stays there
    const FitResult at = fit(kTruth, synthetic(kTruth, 0));
    for (const auto& k : kFree) BOOST_TEST(constant(at, k) == truth(k), boost::test_tools::tolerance(1e-6));
    BOOST_TEST_MESSAGE(at.stop);
}

// The other constants a fit may free, from exact tables: g0's nu_max (also the contact stress's nu_c), the contact
// stress's onset fraction (its range ends at nu_c) and its exponents.
BOOST_AUTO_TEST_CASE(every_fittable_constant_comes_back_from_an_exact_table) {
    const std::vector<std::pair<std::string, std::string>> moves = {
        {"max_solid_fraction = 0.587", "max_solid_fraction = 0.6"},
        {"contact_onset_fraction = 0.5", "contact_onset_fraction = 0.52"},
        {"contact_exponent_onset = 2.0", "contact_exponent_onset = 2.5"},
        {"contact_exponent_jamming = 5.0", "contact_exponent_jamming = 4.0"}};
    for (const auto& [from, to] : moves) {
        const std::string key = from.substr(0, from.find(' '));
        BOOST_TEST_CONTEXT(to) {
            const FitResult r = fit(kTruth, synthetic(with(kTruth, {{from, to}}), 0), {key, "contact_friction"});
            BOOST_TEST(r.constants[0].value == std::stod(to.substr(to.find('=') + 1)), boost::test_tools::tolerance(1e-5));
            BOOST_TEST(r.chi2 < 1e-8);
        }
    }
}

// With noise of the stated errors (seed 1) each constant comes back within three of its own standard errors, the
// errors are informative (below a third of the value), and chi2 is what noise of those errors gives.
BOOST_AUTO_TEST_CASE(a_noisy_table_gives_back_its_constants_within_the_fits_errors) {
    for (std::uint64_t seed : {1u, 2u}) {
        const FitResult r = fit(kStart, synthetic(kTruth, seed));
        BOOST_TEST_MESSAGE("seed " << seed << ":\n" << fit_report(r));
        for (const auto& c : r.constants)
            BOOST_TEST_CONTEXT("seed " << seed << ", " << c.key << " = " << c.value << " +- " << c.error << ", truth "
                                       << truth(c.key)) {
                BOOST_TEST(c.determined);
                BOOST_TEST(std::abs(c.value - truth(c.key)) < 3 * c.error);
                BOOST_TEST(c.error < c.value / 3);
            }
        BOOST_TEST(r.p_value > 1e-3);
        BOOST_TEST(r.p_value < 1 - 1e-3);
    }
}

// At the rough cases' c = 0.44 the correlation length is 1 at every row (the contact stress keeps nu below where it
// leaves 1): no row depends on c, and the fit says so instead of reporting a number for it.
BOOST_AUTO_TEST_CASE(a_constant_no_row_depends_on_is_reported_undetermined) {
    const FitResult r = fit(kCase, synthetic(kTruth, 1));
    BOOST_TEST(r.constants[0].key == "correlation_constant");
    BOOST_TEST(!r.constants[0].determined);
    BOOST_TEST(r.constants[0].no_effect);
    BOOST_TEST(r.constants[0].value == 0.44, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(r.constants[1].determined);
    BOOST_TEST(fit_report(r).find("correlation_constant: not determined by these rows: no row's mu or nu depends on it") !=
               std::string::npos);
}

// A constant mu (no rise with I): the table's nu and T with mu = 0.40 at every I from 1e-3 to 0.2. The kinetic theory
// alone cannot follow it (its mu falls towards 0 as I -> 0): chi2 rejects it. With the contact stress the branch
// absorbs it: mu_c takes the constant, the kinetic part's rise is cancelled by its pi_c weighting, and chi2 (with T
// too) does not reject it. The fit on the bulk table alone cannot tell a flat mu(I) from these closures: the rise
// must be judged on the wall-bounded targets (issue 73, item 5), not on the fit's chi2.
BOOST_AUTO_TEST_CASE(a_constant_mu_is_rejected_by_the_kinetic_theory_and_absorbed_by_the_contact_friction) {
    std::vector<Row> rows = synthetic(kTruth, 1);
    for (Row& r : rows) r.mu = 0.40;
    const std::string kinetic = kinetic_only(kStart);
    const FitResult k = fit(kinetic, rows, {"correlation_constant"});
    BOOST_TEST_MESSAGE("kinetic theory alone:\n" << fit_report(k));
    BOOST_TEST(k.p_value < 1e-6);
    BOOST_TEST(k.rows.front().mu < -5.0);  // at I = 1e-3 the kinetic mu lies far below the constant
    BOOST_TEST(fit_report(k).find("the closures do not describe the table within its errors") != std::string::npos);
    for (bool temperature : {false, true}) {
        const FitResult r = fit(kStart, rows, kFree, temperature);
        BOOST_TEST_MESSAGE("contact stress" << (temperature ? ", T fitted" : "") << ":\n" << fit_report(r));
        BOOST_TEST(std::abs(r.constants[2].value - 0.40) < 3 * r.constants[2].error);
        BOOST_TEST(r.p_value > 1e-3);
    }
}

// The command: the same table gives the same fragment, byte for byte, with its provenance.
BOOST_AUTO_TEST_CASE(the_same_table_gives_the_same_bytes) {
    TempDir tmp("fit");
    write_file_atomic(tmp.path / "t.csv", table_text(synthetic(kTruth, 1)));
    const Case c = parse(kStart);
    FitCommand o{tmp.path / "t.csv", tmp.path / "a.toml", kFree, false, {}};
    BOOST_TEST(run_fit(c, o) == 0);
    o.out = tmp.path / "b.toml";
    BOOST_TEST(run_fit(c, o) == 0);
    const std::string a = read_file(tmp.path / "a.toml"), b = read_file(tmp.path / "b.toml");
    BOOST_TEST(a == b);
    BOOST_TEST(a.find("[continuum]\ncorrelation_constant = ") != std::string::npos, a);
    BOOST_TEST(a.find(fmt::format("hash {}", hash_hex(read_file(tmp.path / "t.csv")))) != std::string::npos, a);
    BOOST_TEST(a.find("case file hash " + c.file_hash) != std::string::npos, a);
    // its lines are [continuum] keys a case can hold: put in place of the case's, they parse to the fitted values
    std::string refit = kStart;
    for (const auto& key : kFree) {
        const auto at = a.find("\n" + key + " = ") + 1;
        const std::string line = a.substr(at, a.find('\n', at) - at);
        const auto old = refit.find(key + " = ");
        refit.replace(old, refit.find('\n', old) - old, line);
    }
    const Settings s = resolve_settings(parse(refit));
    BOOST_TEST(s.contact.friction != 0.36);
    BOOST_TEST(s.contact.friction == truth("contact_friction"), boost::test_tools::tolerance(0.1));
}

BOOST_AUTO_TEST_CASE(fewer_answers_than_free_constants_is_refused_saying_how_many) {
    std::vector<Row> rows = synthetic(kTruth, 0, {0.01});  // two rows, at 2250 and 5550 Pa
    rows.push_back(rows[0]);
    rows.back().id = "transient";
    rows.back().status = "transient";
    BOOST_TEST(case_error([&] { fit(kCase, rows); }) ==
               "synthetic.csv: 2 answer row(s) (status = steady and core_dt_check = converged); the fit of 3 free "
               "constant(s) (correlation_constant, contact_coefficient, contact_friction) needs at least 3: one answer "
               "per free constant, and two at least (one row fixes mu and nu at a single I, not their course with I); "
               "allowed: a table with at least 3 answers, or at most 2 constants with --free");
    // one answer fixes no course with I, even for one constant
    rows.resize(1);
    BOOST_TEST(case_error([&] { fit(kCase, rows, {"contact_friction"}); }).find("needs at least 2") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_row_the_closures_cannot_reach_is_named_with_the_range) {
    std::vector<Row> rows = synthetic(kTruth, 0);
    rows[3].I = 5.0;
    const std::string e = case_error([&] { fit(kCase, rows); });
    BOOST_TEST(e.starts_with("synthetic.csv:7: point I0.03_P2250 (P = 2250 Pa): I = 5 is outside what the case's "
                             "closures reach at its constants (homogeneous shear: I = 5 is outside the closures' dense "
                             "branch (0, "),
               e);
}

BOOST_AUTO_TEST_CASE(a_free_key_outside_the_cases_branches_is_refused_naming_the_allowed) {
    const std::string kinetic = kinetic_only(kCase);
    BOOST_TEST(case_error([&] { fit(kinetic, synthetic(kTruth, 0), {"contact_friction"}); }) ==
               "continuum-fit --free contact_friction: a constant of contact_stress = \"johnson_jackson\", which this "
               "case does not choose (allowed in this case: correlation_constant, max_solid_fraction, slip_dissipation, r5; "
               "or choose the branch in [continuum] and set its constants as the fit's start)");
    BOOST_TEST(case_error([&] { fit(kCase, synthetic(kTruth, 0), {"viscosity_alpha"}); })
                   .starts_with("continuum-fit --free viscosity_alpha: not a constant a fit can free (allowed in this "
                                "case: correlation_constant, contact_coefficient,"));
    // the default free set is the constants of the branches the case chooses
    BOOST_TEST(default_free_keys(resolve_settings(parse(kinetic))) == std::vector<std::string>{"correlation_constant"});
}

// A branch without its constants stops where the case is read, naming the key (case_setup.cpp).
BOOST_AUTO_TEST_CASE(a_branch_without_its_constants_is_refused_naming_the_key) {
    const std::string e = case_error([&] { resolve_settings(parse(with(kCase, {{"contact_friction = 0.36", ""}}))); });
    BOOST_TEST(e.find("contact_stress = \"johnson_jackson\" needs its constant contact_friction (mu_c)") !=
                   std::string::npos,
               e);
}

BOOST_AUTO_TEST_CASE(a_zero_error_cannot_weight_the_fit) {
    std::string t = table_text(synthetic(kTruth, 0));
    const std::string needle = fmt::format(",{:.9g},", kMuErr);
    t.replace(t.find(needle), needle.size(), ",0,");
    const BulkRows rows = parse_bulk_table(t, "z.csv");
    BOOST_TEST(case_error([&] {
                   fit_bulk_rheology(resolve_settings(parse(kCase)), rows.answers(), {kFree, false, nullptr, {}}, "z.csv");
               }).starts_with("z.csv:4: point I0.001_P2250: mu_err = 0 cannot weight a fit"));
}

// The command on tables it cannot use: another format, a missing column (bad input: CaseError, exit 2).
BOOST_AUTO_TEST_CASE(the_command_refuses_other_tables_naming_them) {
    TempDir tmp("fit");
    const Case c = parse(kCase);
    write_file_atomic(tmp.path / "v2.csv", table_text(synthetic(kTruth, 0), "granlub-bulk-rheology 2"));
    BOOST_TEST(case_error([&] { run_fit(c, {tmp.path / "v2.csv", tmp.path / "o.toml", kFree, false, {}}); })
                   .find("v2.csv:1: a table of format 'granlub-bulk-rheology 2'") != std::string::npos);
    std::string t = table_text(synthetic(kTruth, 0));
    t.replace(t.find(",nu_err,"), 8, ",nu_stderr,");
    write_file_atomic(tmp.path / "cols.csv", t);
    BOOST_TEST(case_error([&] { run_fit(c, {tmp.path / "cols.csv", tmp.path / "o.toml", kFree, false, {}}); })
                   .find("cols.csv: no column 'nu_err'") != std::string::npos);
    BOOST_TEST(!fs::exists(tmp.path / "o.toml"));
    BOOST_TEST(case_error([&] { run_fit(c, {tmp.path / "none.csv", tmp.path / "o.toml", kFree, false, {}}); })
                   .find("none.csv: cannot be read") != std::string::npos);
}

// ---- The wall constant slip_dissipation (f_t), fitted on the walls' columns against the bulk case's 1-D solve ----

namespace {

// cases/bulk_shear's cell (bumps of the grains' size, periodic width, no gravity, the load on the top) at two speeds
// and its two loads, with the rough cases' kinetic closures, the gap under the load, the wall at the bumps' tops;
// f_t = 0.2 is the fit's start; 100 cells (the least allowed) keep the tests fast.
const std::string kBulk = with(kinetic_only(kCase),
                               {{"roughness = 0.5\n", "roughness = 0.5\nfriction = 0.5\nsurface = \"bumps\"\n"},
                                {"length = 15.74e-3\n", "length = 15.74e-3\nwidth = 0.0\n"},
                                {"[operating]", "[particles]\nperiodic_depth = 7.87e-3\n[operating]"},
                                {"speed = 1.0", "speed = [3.0, 9.0]"},
                                {"normal_stress = [2250.0, 5550.0]",
                                 "normal_stress = [2250.0, 5550.0]\nsolid_fraction = 0.57\n[body_forces]\ngravity = 0.0"},
                                {"correlation_constant = 0.44", "correlation_constant = 0.44\ngap = \"inventory\"\n"
                                                                "wall_plane = \"bump_tops\"\nslip_dissipation = 0.2\ncells = 100"}});
const std::string kWallTruth = with(kBulk, {{"slip_dissipation = 0.2", "slip_dissipation = 0.5"}});
constexpr double kWallRelErr = 0.01;

// The table made by the continuum itself from `truth`: per point of the bulk case its 1-D solve, read as the
// reducer reads the DEM (the slips over U; T/U^2 within 2 d of the bump tops, near_wall_temperature), errors 1 %;
// the core's columns the closures' homogeneous shear at the solve's mid-gap I.
std::string wall_table(const std::string& truth, const std::string& bulk_file = "bulk.toml") {
    const Case c = parse(truth);
    const Settings s = resolve_settings(c);
    std::string t = fmt::format("# format granlub-bulk-rheology 1\n# case bulk_test ({})\n", bulk_file);
    t += "point,speed_m_s,load_Pa,status,core_dt_check,pressure_Pa,pressure_err,I,I_err,mu,mu_err,nu,nu_err,T_scaled,"
         "T_scaled_err";
    for (const char* w : kWallColumns) t += fmt::format(",{}", w);
    t += "\n";
    for (const OperatingPoint& p : c.points) {
        const PointResult r = solve_point(c, p, s);
        const auto& o = r.summary.outputs;
        const NearWallTemperature nw = near_wall_temperature(r.profile, o.at("gap").value, c.grains.diameter,
                                                             bump_protrusion(c, p.bottom), bump_protrusion(c, p.top),
                                                             BandMean::Interpolated);
        const double I = o.at("inertial_number").value;
        const SimpleShear h = simple_shear_at_inertial(*s.closures, I);
        t += fmt::format("{},{},{},steady,converged,{},{},{:.9g},{:.9g},{:.9g},{},{:.9g},{},{:.9g},{:.9g}", p.id, p.speed,
                         p.normal_stress, p.normal_stress, 0.01 * p.normal_stress, I, 0.01 * I, h.stress_ratio, kMuErr,
                         h.nu, kNuErr, h.temperature, kTRelErr * h.temperature);
        for (double v : {o.at("slip_bottom").value / p.speed, o.at("slip_top").value / p.speed, nw.bottom.value,
                         nw.top.value})
            t += fmt::format(",{:.12g},{:.12g}", v, kWallRelErr * v);
        t += "\n";
    }
    return t;
}

FitResult wall_fit(const std::string& case_text, const std::string& table, std::vector<std::string> free,
                   const Case* bulk) {
    const BulkRows t = parse_bulk_table(table, "walls.csv");
    FitOptions o{std::move(free), false, bulk, t.missing_wall_columns};
    return fit_bulk_rheology(resolve_settings(parse(case_text)), t.answers(), o, "walls.csv");
}

}  // namespace

// From the continuum's own walls at f_t = 0.5 the fit started at 0.2 gives back 0.5 (chi2 ~ 0): the slips and the
// near-wall T depend on f_t, and the fit's model is the solve the table was made with, through Settings and trial.
BOOST_AUTO_TEST_CASE(a_wall_fit_gives_back_the_slip_dissipation_of_the_continuums_own_walls) {
    const Case fitted = parse(kBulk), bulk = bulk_case_for(parse(kBulk), fitted);
    const FitResult r = wall_fit(kBulk, wall_table(kWallTruth), {"slip_dissipation"}, &bulk);
    BOOST_TEST_MESSAGE(fit_report(r));
    BOOST_TEST(r.walls);
    BOOST_TEST(!r.core);
    BOOST_TEST(r.constants[0].start == 0.2);
    BOOST_TEST(std::abs(r.constants[0].value - 0.5) < 1e-3);
    BOOST_TEST(r.constants[0].error > 0.0);
    BOOST_TEST(r.chi2 < 1e-4);
    BOOST_TEST(r.dof == 4u * 4u - 1u);
    BOOST_TEST(fit_report(r).find("slip_b/U table") != std::string::npos);
    BOOST_TEST(fit_fragment(r, {}).find("slip_dissipation = 0.5") != std::string::npos, fit_fragment(r, {}));
    // the case's default f_t = 0 (on its range's edge) starts mid-range and gets there too
    const std::string zero = with(kBulk, {{"slip_dissipation = 0.2", ""}});
    const FitResult z = wall_fit(zero, wall_table(kWallTruth), {"slip_dissipation"}, &bulk);
    BOOST_TEST(z.constants[0].moved_inside);
    BOOST_TEST(std::abs(z.constants[0].value - 0.5) < 1e-3);
}

// R5 (one value at both walls) with f_t: from the continuum's walls at R5 = 0.4, f_t = 0.5, started at the walls'
// roughness 0.5 and f_t = 0.2; a case that sets the walls' R5 apart is refused.
BOOST_AUTO_TEST_CASE(a_wall_fit_gives_back_r5_and_the_slip_dissipation) {
    const Case fitted = parse(kBulk), bulk = bulk_case_for(parse(kBulk), fitted);
    const std::string truth = with(kWallTruth, {{"slip_dissipation = 0.5", "slip_dissipation = 0.5\nr5 = 0.4"}});
    const FitResult r = wall_fit(kBulk, wall_table(truth), {"r5", "slip_dissipation"}, &bulk);
    BOOST_TEST_MESSAGE(fit_report(r));
    BOOST_TEST(r.constants[0].start == 0.5);
    BOOST_TEST(std::abs(r.constants[0].value - 0.4) < 1e-3);
    BOOST_TEST(std::abs(r.constants[1].value - 0.5) < 1e-3);
    BOOST_TEST(fit_fragment(r, {}).find("\nr5 = 0.4") != std::string::npos, fit_fragment(r, {}));
    const std::string apart = with(kBulk, {{"slip_dissipation = 0.2", "slip_dissipation = 0.2\nr5_top = 0.3"}});
    const Case fitted_apart = parse(apart), bulk_apart = bulk_case_for(parse(kBulk), fitted_apart);
    BOOST_TEST(case_error([&] { wall_fit(apart, wall_table(truth), {"r5"}, &bulk_apart); })
                   .starts_with("continuum-fit --free r5: the case sets r5_top"));
}

// Jointly with a closure constant: nu_max and f_t from one table, the core's rows and the walls' together.
BOOST_AUTO_TEST_CASE(a_joint_fit_gives_back_a_closure_constant_and_the_slip_dissipation) {
    const std::string start = with(kBulk, {{"max_solid_fraction = 0.587", "max_solid_fraction = 0.6"}});
    const Case fitted = parse(start), bulk = bulk_case_for(parse(kBulk), fitted);
    const FitResult r = wall_fit(start, wall_table(kWallTruth), {"max_solid_fraction", "slip_dissipation"}, &bulk);
    BOOST_TEST_MESSAGE(fit_report(r));
    BOOST_TEST(r.core);
    BOOST_TEST(r.walls);
    BOOST_TEST(r.constants[0].value == 0.587, boost::test_tools::tolerance(1e-4));
    BOOST_TEST(std::abs(r.constants[1].value - 0.5) < 1e-3);
    BOOST_TEST(r.dof == 4u * (2u + 4u) - 2u);
}

// The command takes the bulk case from the table's provenance line and writes f_t into the fragment.
BOOST_AUTO_TEST_CASE(the_command_fits_the_walls_of_the_bulk_case_the_table_names) {
    TempDir tmp("wallfit");
    write_file_atomic(tmp.path / "bulk.toml", kBulk);
    write_file_atomic(tmp.path / "t.csv", wall_table(kWallTruth, (tmp.path / "bulk.toml").string()));
    const Case c = parse(kBulk);
    BOOST_TEST(run_fit(c, {tmp.path / "t.csv", tmp.path / "a.toml", {"slip_dissipation"}, false, {}}) == 0);
    const std::string a = read_file(tmp.path / "a.toml");
    BOOST_TEST(a.find("[continuum]\nslip_dissipation = 0.5") != std::string::npos, a);
    BOOST_TEST(a.find("the walls' slips and near-wall T of the bulk case") != std::string::npos, a);
    // --bulk-case naming a case without the table's points
    write_file_atomic(tmp.path / "other.toml", with(kBulk, {{"speed = [3.0, 9.0]", "speed = [1.0]"}}));
    BOOST_TEST(case_error([&] {
                   run_fit(c, {tmp.path / "t.csv", tmp.path / "b.toml", {"slip_dissipation"}, false,
                               tmp.path / "other.toml"});
               }).find("point U3.0_P2250: the bulk case") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_wall_fit_is_refused_where_it_would_mean_nothing) {
    const Case fitted = parse(kBulk), bulk = bulk_case_for(parse(kBulk), fitted);
    // a table written before the walls' columns: named
    BOOST_TEST(case_error([&] { wall_fit(kBulk, table_text(synthetic(kTruth, 0)), {"slip_dissipation"}, &bulk); })
                   .starts_with("walls.csv: no column(s) slip_bottom_over_U, slip_bottom_err, slip_top_over_U, "
                                "slip_top_err, T_wall_bottom_over_U2, T_wall_bottom_err, T_wall_top_over_U2, "
                                "T_wall_top_err: --free slip_dissipation fits the walls' slips and near-wall T"));
    // no bulk case
    BOOST_TEST(case_error([&] { wall_fit(kBulk, wall_table(kWallTruth), {"slip_dissipation"}, nullptr); })
                   .find("no bulk case was given (allowed: --bulk-case DIR)") != std::string::npos);
    // R7 = 0 at both walls: f_t acts on nothing
    const std::string r7 = with(kBulk, {{"slip_dissipation = 0.2", "slip_dissipation = 0.2\nr7 = 0.0"}});
    const Case fitted7 = parse(r7), bulk7 = bulk_case_for(parse(kBulk), fitted7);
    BOOST_TEST(case_error([&] { wall_fit(r7, wall_table(kWallTruth), {"slip_dissipation"}, &bulk7); })
                   .find("R7 = 0 at both walls of the bulk case") != std::string::npos);
    // an answer whose wall error is zero cannot weight the fit
    std::string t = wall_table(kWallTruth);
    const auto row = t.find("U3.0_P2250");
    const auto cell = t.rfind(',', t.find('\n', row));  // T_wall_top_err of that row
    t.replace(cell + 1, t.find('\n', row) - cell - 1, "0");
    BOOST_TEST(case_error([&] { wall_fit(kBulk, t, {"slip_dissipation"}, &bulk); })
                   .find("point U3.0_P2250: T_wall_top = ") != std::string::npos);
}
