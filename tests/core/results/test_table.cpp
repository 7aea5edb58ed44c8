// The one table reader: both dialects, and every rejection names the source and line.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "granlub/error.h"
#include "granlub/results/table.h"

using namespace granlub;

namespace {
std::string error_of(std::string_view text, const TableFormat& f = {}) {
    try {
        parse_table(text, "t.txt", f);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}
TableFormat whitespace(std::vector<std::string> names = {}) {
    TableFormat f;
    f.separator = TableFormat::Separator::whitespace;
    f.header = false;
    f.names = std::move(names);
    return f;
}
}  // namespace

BOOST_AUTO_TEST_CASE(csv_with_header_reads_columns_and_their_lines) {
    const Table t = parse_table("# made by a test\r\na,b\r\n\r\n1,2.5\r\n# mid\r\n-3,4e-3\r\n", "t.csv");
    BOOST_TEST(t.names == (std::vector<std::string>{"a", "b"}));
    BOOST_TEST(t.column("b") == (std::vector<double>{2.5, 4e-3}));
    BOOST_TEST(t.line == (std::vector<std::size_t>{4, 6}));
    BOOST_TEST(error_of("a,b\n1,2\n3\n") == "t.txt:3: 1 values, the header has 2 columns");
    BOOST_TEST(error_of("a,b\n1,x\n") == "t.txt:2: 'x' is not a number (column 'b')");
    BOOST_TEST(error_of("a,b\n1,\n") == "t.txt:2: '' is not a number (column 'b')");
    BOOST_TEST(error_of("# only a comment\n") == "t.txt: empty table (no header row)");
    TableFormat exact;
    exact.expected_header = "a,b";
    BOOST_TEST(error_of("a,c\n1,2\n", exact) == "t.txt:1: header 'a,c', expected 'a,b'");
}

BOOST_AUTO_TEST_CASE(nonfinite_values_are_read_unless_the_format_forbids_them) {
    BOOST_TEST(std::isnan(parse_table("a\nnan\n", "t.csv").columns[0][0]));
    TableFormat f;
    f.finite = true;
    f.nonfinite_hint = "reduce the time step";
    BOOST_TEST(error_of("a\n1\n-inf\n", f) == "t.txt:3: non-finite value '-inf' in column 'a': reduce the time step");
}

BOOST_AUTO_TEST_CASE(whitespace_tables_without_header_take_names_or_the_first_rows_width) {
    const Table t = parse_table("# TimeStep c_1\n100  1\t2\n  \n200 3 4\n", "t.txt", whitespace());
    BOOST_TEST(t.names == (std::vector<std::string>{"1", "2", "3"}));
    BOOST_TEST(t.columns[2] == (std::vector<double>{2, 4}));
    BOOST_TEST(error_of("100 1 2\n200 3\n", whitespace()) == "t.txt:2: 2 values, expected 3 as on line 1");
    const Table named = parse_table("1 2\n", "t.txt", whitespace({"step", "gap"}));
    BOOST_TEST(named.column("gap") == (std::vector<double>{2}));
    BOOST_TEST(error_of("1 2 3\n", whitespace({"step", "gap"})) == "t.txt:1: 3 values, expected 2: step gap");
    BOOST_TEST(parse_table("# nothing yet\n", "t.txt", whitespace()).rows() == 0u);
}

BOOST_AUTO_TEST_CASE(solver_outputs_fail_as_the_solvers_run) {
    BOOST_CHECK_EXCEPTION(read_solver_output("/nonexistent/w.txt", {}, "LIGGGHTS wrote no wall-force file"), SolverError,
                          [](const SolverError& e) {
                              return std::string(e.what()) == "/nonexistent/w.txt: LIGGGHTS wrote no wall-force file";
                          });
    BOOST_CHECK_THROW(read_table("/nonexistent/w.txt"), Error);
}

BOOST_AUTO_TEST_CASE(named_text_columns_stay_text_and_empty_cells_may_mean_not_available) {
    TableFormat f;
    f.text = {"id", "absent"};
    const Table t = parse_table("id,a,b\nU1,1,2\nU2,3,4\n", "t.csv", f);
    BOOST_TEST(t.names == (std::vector<std::string>{"a", "b"}));
    BOOST_TEST(t.text("id") == (std::vector<std::string>{"U1", "U2"}));
    BOOST_TEST(t.has_text("id"));
    BOOST_TEST(!t.has_text("absent"));
    BOOST_TEST(!t.has("id"));
    BOOST_TEST(t.rows() == 2u);
    BOOST_TEST(error_of("id,a\nU1,\n", f) == "t.txt:2: '' is not a number (column 'a')");
    BOOST_TEST(error_of("id,a\nU1,x\n", f) == "t.txt:2: 'x' is not a number (column 'a')");
    f.empty_cells = true;
    f.finite = true;
    const Table e = parse_table("id,a\nU1,\n", "t.csv", f);
    BOOST_TEST(std::isnan(e.column("a")[0]));
    BOOST_TEST(e.text("id")[0] == "U1");
    BOOST_CHECK_THROW(e.text("a"), Error);
}
