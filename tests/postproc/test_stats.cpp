// The statistics behind the metrics, against values worked out by hand from the definitions.
#include <cmath>

#include <boost/test/unit_test.hpp>

#include "formats/svg_plot.h"
#include "statistics/stats.h"

using namespace granlub::postproc;

BOOST_AUTO_TEST_SUITE(stats)

BOOST_AUTO_TEST_CASE(interpolation_is_exact_for_linear_data_and_holds_the_ends) {
    const std::vector<double> x{0.0, 0.3, 1.0}, y{1.0, 1.6, 3.0};  // y = 1 + 2x
    BOOST_TEST(interpolate(x, y, 0.65) == 2.3, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(interpolate(x, y, -1.0) == 1.0);
    BOOST_TEST(interpolate(x, y, 2.0) == 3.0);
}

BOOST_AUTO_TEST_CASE(profile_difference_of_an_offset_and_of_a_ramp) {
    // Different station sets; linear data, so interpolation is exact.
    std::vector<double> ya, a, yb, b, ramp;
    for (int k = 0; k <= 10; ++k) ya.push_back(k / 10.0), a.push_back(2 * k / 10.0);
    for (int k = 0; k <= 4; ++k) yb.push_back(k / 4.0), b.push_back(2 * k / 4.0 - 0.1), ramp.push_back(k / 4.0);
    const auto off = profile_difference(ya, a, {}, yb, b, {});
    BOOST_TEST(off.rms == 0.1, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(off.max == 0.1, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(!off.noise_rms.has_value());
    // a - b = y/H on the 101-point grid: rms = sqrt(sum k^2 / 100^2 / 101) = sqrt(201 / 600), max 1 at y = 1.
    std::vector<double> zero(5, 0.0);
    const auto d = profile_difference(yb, ramp, std::vector<double>(5, 0.03), yb, zero, std::vector<double>(5, 0.04));
    BOOST_TEST(d.rms == std::sqrt(201.0 / 600.0), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(d.max == 1.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(d.y_at_max == 1.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(*d.noise_rms == 0.05, boost::test_tools::tolerance(1e-12));  // sqrt(0.03^2 + 0.04^2)
}

BOOST_AUTO_TEST_CASE(profile_difference_uses_only_the_overlap) {
    const std::vector<double> ya{0.0, 1.0}, a{0.0, 0.0}, yb{0.5, 1.0}, b{1.0, 1.0};
    const auto d = profile_difference(ya, a, {}, yb, b, {});
    BOOST_TEST(d.lo == 0.5);
    BOOST_TEST(d.hi == 1.0);
    BOOST_TEST(d.rms == 1.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(combined_standard_error) {
    BOOST_TEST(*combined_stderr(3.0, 4.0) == 5.0);
    BOOST_TEST(*combined_stderr(std::nullopt, 2.0) == 2.0);
    BOOST_TEST(!combined_stderr(std::nullopt, std::nullopt).has_value());
}

BOOST_AUTO_TEST_CASE(power_fit_recovers_exponent_and_its_error) {
    const std::vector<double> u{1, 2, 4}, s{3, 12, 48};  // 3 U^2
    const auto plain = power_fit(u, s, {});
    BOOST_TEST_REQUIRE(plain.has_value());
    BOOST_TEST(plain->exponent == 2.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(plain->prefactor == 3.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(!plain->weighted);
    BOOST_TEST(*plain->exponent_stderr < 1e-12);  // exact data: no residual
    // 10 % relative errors: se(n) = 0.1 / sqrt(sum (ln U - mean)^2) = 0.1 / (sqrt(2) ln 2).
    const auto w = power_fit(u, s, {0.3, 1.2, 4.8});
    BOOST_TEST_REQUIRE(w.has_value());
    BOOST_TEST(w->weighted);
    BOOST_TEST(w->exponent == 2.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(*w->exponent_stderr == 0.1 / (std::sqrt(2.0) * std::log(2.0)), boost::test_tools::tolerance(1e-12));
    // Scatter beyond the stated errors inflates se(n) by sqrt(chi^2/dof).
    const auto scattered = power_fit(u, {3, 14, 48}, {0.03, 0.12, 0.48});
    BOOST_TEST(*scattered->exponent_stderr > 0.01 / (std::sqrt(2.0) * std::log(2.0)) * 1.5);
}

BOOST_AUTO_TEST_CASE(power_fit_needs_two_speeds) {
    BOOST_TEST(!power_fit({2.0}, {5.0}, {}).has_value());
    BOOST_TEST(!power_fit({2.0, 2.0}, {5.0, 6.0}, {}).has_value());
    const auto two = power_fit({1.0, 2.0}, {1.0, 4.0}, {});
    BOOST_TEST(two->exponent == 2.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(!two->exponent_stderr.has_value());  // no degree of freedom left
}

BOOST_AUTO_TEST_CASE(axis_ticks) {
    const auto lin = linear_ticks(0.0, 1.0);
    BOOST_TEST_REQUIRE(lin.size() == 6u);
    BOOST_TEST(lin[1].label == "0.2");
    BOOST_TEST(lin.back().label == "1.0");
    auto labels = [](const std::vector<Tick>& ticks) {
        std::vector<std::string> out;
        for (const auto& t : ticks)
            if (!t.label.empty()) out.push_back(t.label);
        return out;
    };
    // Up to three decades: 1-2-5 in each, so that 300 Pa can be read off.
    const std::vector<std::string> three = {"1e+00", "2", "5", "1e+01", "20", "50", "1e+02", "200", "500", "1e+03"};
    BOOST_TEST(labels(log_ticks(1.0, 1000.0)) == three, boost::test_tools::per_element());
    // More decades: the powers of ten only.
    BOOST_TEST(labels(log_ticks(1.0, 1e6)).size() == 7u);
    // A narrow span (the speeds 1.4 to 2.8 m/s): every mantissa and the halves between.
    const std::vector<std::string> narrow = {"1.5", "2", "2.5", "3", "3.5"};
    BOOST_TEST(labels(log_ticks(1.2, 3.5)) == narrow, boost::test_tools::per_element());
    // Under a decade with only 2000 and 5000 of 1-2-5 inside: every thousand is labelled, not the halves.
    const std::vector<std::string> load = {"2000", "3000", "4000", "5000", "6000"};
    BOOST_TEST(labels(log_ticks(1300.0, 6500.0)) == load, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_SUITE_END()
