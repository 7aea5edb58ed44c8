// The one reader of the bulk-rheology table (bulk_rheology_table.h, read_bulk_table): its format line, the
// columns it needs, the reading rule that picks the answers, and every refusal naming the file, line and column.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "granlub/error.h"
#include "granlub/particles/bulk_rheology_table.h"

using namespace granlub;
namespace tt = boost::test_tools;

namespace {

// The header and two rows of the shipped cases/bulk_shear/bulk_rheology.csv (written 2026-12-06), one an answer,
// and a transient row whose check cells are empty (as the writer leaves them without a Delta-t check).
const std::string kHeader =
    "point,speed_m_s,load_Pa,status,dt_check,core_dt_check,time_step_s,check_time_step_s,gap_m,grains,"
    "core_from_y_over_H,core_to_y_over_H,core_stations,shear_rate_1_s,shear_rate_err,shear_rate_halves,pressure_Pa,"
    "pressure_err,shear_stress_Pa,shear_stress_err,wall_shear_imbalance,wall_normal_imbalance,I,I_err,I_dt_change,mu,"
    "mu_err,mu_dt_change,nu,nu_err,nu_dt_change,T_scaled,T_scaled_err,T_scaled_dt_change,Z,Z_err,Z_dt_change,Z_source\n";
const std::string kAnswer =
    "U9.0_P5550,9,5550,steady,converged,converged,7.22986e-07,1.44597e-06,0.0246322,6446,0.333333,0.666667,21,158.832,"
    "0.581317,-0.0276479,5557.88,66.1085,2398.99,31.3404,-0.026796,-0.0146398,0.08467,0.000591268,-0.00364661,0.431637,"
    "0.00762604,0.000999752,0.578768,0.00245291,0.000783702,0.546733,0.0131114,-0.0581041,4.84644,0.00820056,"
    "-0.00361199,core\n";
const std::string kSteadyUnconverged =
    "U9.0_P2250,9,2250,steady,converged,unconverged:I,7.22986e-07,1.44597e-06,0.0252351,6446,0.333333,0.666667,21,"
    "167.386,0.742311,0.0547723,2257.38,42.0726,1028.91,17.0044,-0.0157749,-0.00786552,0.140011,0.00144496,-0.0179753,"
    "0.4558,0.0113539,7.20097e-05,0.570893,0.00255075,0.00191981,0.42723,0.0104369,-0.0011378,4.5882,0.0105391,"
    "0.0523788,core\n";
const std::string kTransientUnchecked =
    "U0.3_P2250,0.3,2250,transient,not-checked,not-checked,7.08868e-06,,0.0228,6446,0.333333,0.666667,21,3.1,0.2,"
    "-0.2,2260,6,800,3,-0.3,-0.1,0.0025,0.0001,,0.34,0.002,,0.63,0.002,,1.3,0.07,,,,,none\n";
const std::string kTop =
    "# format granlub-bulk-rheology 1\n"
    "# case bulk_shear (cases/bulk_shear/case.toml), case file hash 76faa1b28f5bb960\n"
    "# written 2026-12-06T08:15:27Z by granlub 0.1.0+g510be37\n";

std::string error_of(const std::string& text) {
    try {
        parse_bulk_table(text, "b.csv");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// `text` with the first `from` replaced by `to`
std::string with(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

}  // namespace

BOOST_AUTO_TEST_CASE(rows_their_values_and_the_answers_by_the_reading_rule) {
    const BulkRows t = parse_bulk_table(kTop + kHeader + kSteadyUnconverged + kAnswer + kTransientUnchecked, "b.csv");
    BOOST_REQUIRE(t.rows.size() == 3u);
    BOOST_TEST(t.source == "b.csv");
    BOOST_TEST(t.provenance.size() == 2u);
    BOOST_TEST(t.provenance[1] == "written 2026-12-06T08:15:27Z by granlub 0.1.0+g510be37");
    const BulkRow& a = t.rows[1];
    BOOST_TEST(a.point == "U9.0_P5550");
    BOOST_TEST(a.line == 6u);
    BOOST_TEST(a.load == 5550.0);
    BOOST_TEST(a.pressure.value == 5557.88);
    BOOST_TEST(a.inertial.value == 0.08467);
    BOOST_TEST(a.inertial.error == 0.000591268);
    BOOST_TEST(a.friction.value == 0.431637);
    BOOST_TEST(a.friction.error == 0.00762604);
    BOOST_TEST(a.solid_fraction.value == 0.578768);
    BOOST_TEST(a.temperature_scaled.error == 0.0131114);
    // steady by the pipeline but unconverged in the core, and a transient row: labelled measurements
    BOOST_TEST(!is_answer(t.rows[0]));
    BOOST_TEST(is_answer(a));
    BOOST_TEST(!is_answer(t.rows[2]));
    BOOST_REQUIRE(t.answers().size() == 1u);
    BOOST_TEST(t.answers()[0].point == "U9.0_P5550");
    // the writer's empty cells read as "not available" in rows that are not answers
    BOOST_TEST(t.rows[2].friction.value == 0.34);
}

// A table written before the walls' columns reads as before: its wall values NaN, the columns named as missing (the
// wall fit refuses naming them); with them, every row carries its walls.
BOOST_AUTO_TEST_CASE(a_table_without_the_walls_columns_reads_and_names_them) {
    const BulkRows old = parse_bulk_table(kTop + kHeader + kAnswer, "b.csv");
    BOOST_TEST(old.missing_wall_columns.size() == std::size(kWallColumns));
    BOOST_TEST(old.missing_wall_columns.front() == "slip_bottom_over_U");
    BOOST_TEST(std::isnan(old.rows[0].slip_bottom.value));
    BOOST_TEST(std::isnan(old.rows[0].T_wall_top.error));
    BOOST_TEST(old.rows[0].speed == 9.0);
    const auto walls = [](std::string row, const std::string& cells) { return row.insert(row.size() - 1, cells); };
    const std::string header = walls(kHeader, ",slip_bottom_over_U,slip_bottom_err,slip_top_over_U,slip_top_err,"
                                              "T_wall_bottom_over_U2,T_wall_bottom_err,T_wall_top_over_U2,T_wall_top_err");
    const BulkRows t = parse_bulk_table(
        kTop + header + walls(kAnswer, ",0.122,0.0011,0.111,0.0006,0.00137,2.8e-05,0.00116,1.8e-05") +
            walls(kTransientUnchecked, ",,,,,,,,"),
        "b.csv");
    BOOST_TEST(t.missing_wall_columns.empty());
    BOOST_TEST(t.rows[0].slip_bottom.value == 0.122);
    BOOST_TEST(t.rows[0].slip_top.error == 0.0006);
    BOOST_TEST(t.rows[0].T_wall_bottom.value == 0.00137);
    BOOST_TEST(t.rows[0].T_wall_top.error == 1.8e-05);
    BOOST_TEST(std::isnan(t.rows[1].slip_bottom.value));  // empty cells: not available
}

BOOST_AUTO_TEST_CASE(the_shipped_table_reads_and_its_answers_follow_the_rule) {
    const BulkRows t = read_bulk_table(GRANLUB_SOURCE_DIR "/cases/bulk_shear/bulk_rheology.csv");
    BOOST_TEST(!t.rows.empty());
    std::size_t answers = 0;
    for (const BulkRow& r : t.rows) answers += r.status == "steady" && r.core_dt_check == "converged";
    BOOST_TEST(t.answers().size() == answers);
}

BOOST_AUTO_TEST_CASE(another_format_or_no_format_line_is_refused) {
    BOOST_TEST(error_of(with(kTop, "rheology 1", "rheology 2") + kHeader + kAnswer) ==
               "b.csv:1: a table of format 'granlub-bulk-rheology 2'; expected 'granlub-bulk-rheology 1' (what "
               "`granlub bulk-rheology` writes: cases/bulk_shear/README.md)");
    BOOST_TEST(error_of(kHeader + kAnswer).starts_with("b.csv:1: not a bulk-rheology table: its first line is 'point,"));
    BOOST_TEST(error_of("").starts_with("b.csv:1: not a bulk-rheology table: its first line is ''"));
}

BOOST_AUTO_TEST_CASE(a_missing_column_is_named_with_its_unit) {
    BOOST_TEST(error_of(kTop + with(kHeader, ",pressure_Pa,", ",pressure_kPa,") + kAnswer) ==
               "b.csv: no column 'pressure_Pa' (the core's pressure P, Pa): a granlub-bulk-rheology 1 table has it "
               "(cases/bulk_shear/README.md)");
    BOOST_TEST(error_of(kTop + with(kHeader, ",mu_err,", ",mu_error,") + kAnswer).starts_with("b.csv: no column 'mu_err'"));
    BOOST_TEST(error_of(kTop + with(kHeader, ",status,", ",state,") + kAnswer).starts_with("b.csv: no column 'status'"));
}

BOOST_AUTO_TEST_CASE(an_answer_a_fit_cannot_use_is_refused_naming_row_and_column) {
    BOOST_TEST(error_of(kTop + kHeader + with(kAnswer, ",0.431637,", ",,")) ==
               "b.csv:5: point U9.0_P5550 is an answer (status = steady, core_dt_check = converged) but its mu = nan "
               "(allowed: a finite number)");
    BOOST_TEST(error_of(kTop + kHeader + with(kAnswer, ",0.578768,", ",1.2,")).find("its nu = 1.2 (allowed: (0, 1))") !=
               std::string::npos);
    BOOST_TEST(error_of(kTop + kHeader + with(kAnswer, ",0.00762604,", ",-0.01,"))
                   .find("its mu_err = -0.01 (allowed: a finite standard error >= 0)") != std::string::npos);
    BOOST_TEST(error_of(kTop + kHeader + with(kAnswer, ",0.08467,", ",x,")) ==
               "b.csv:5: 'x' is not a number (column 'I')");
}
