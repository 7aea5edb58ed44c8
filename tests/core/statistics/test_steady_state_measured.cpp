// The steady-state detector (granlub/statistics/steady_state.h) on series measured on cases/sawyer2001
// (tests/core/statistics/data): U = 2.0 m/s, which MSER-5 alone called a transient over a 0.4 % bump of the
// gap, and U = 2.8 m/s, which it called steady from 0.055 s while the gap still compacted.
#include <boost/test/unit_test.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "granlub/statistics/steady_state.h"

using namespace granlub;

namespace {

struct Measured {
    std::vector<double> step, nb, nt, sb, st, gap;
};

Measured read(const std::string& name) {
    const std::string path = std::string(GRANLUB_TEST_DATA) + "/" + name;
    std::ifstream in(path);
    BOOST_TEST_REQUIRE(in.good(), "cannot read " << path);
    Measured m;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        double v[6];
        for (double& x : v) row >> x;
        BOOST_TEST_REQUIRE(!row.fail(), path << ": bad row '" << line << "'");
        m.step.push_back(v[0]), m.nb.push_back(v[1]), m.nt.push_back(v[2]), m.sb.push_back(v[3]),
            m.st.push_back(v[4]), m.gap.push_back(v[5]);
    }
    return m;
}

SteadyWindow window(const Measured& m, const PlateSeries& plate) {
    return steady_window({{"normal_stress_bottom", m.nb, kStressDrift},
                          {"normal_stress_top", m.nt, kStressDrift},
                          {"shear_stress_bottom", m.sb, kStressDrift},
                          {"shear_stress_top", m.st, kStressDrift}},
                         m.step, 100, 5.48e-6, &plate, 100);
}

double mean(const std::vector<double>& v, std::size_t from, std::size_t to) {
    double s = 0;
    for (std::size_t i = from; i < to; ++i) s += v[i];
    return s / static_cast<double>(to - from);
}

}  // namespace

BOOST_AUTO_TEST_CASE(measured_U2_0_is_steady) {
    const Measured m = read("sawyer2001_U2.0_0.3s.txt");
    const PlateSeries plate{m.step, m.gap};
    const SteadyWindow w = window(m, plate);
    BOOST_TEST_MESSAGE("U2.0: steady " << w.steady << " from " << w.t_start << " s; " << w.to_json().dump());
    BOOST_TEST(w.steady);
    BOOST_TEST(w.t_start < 0.15);
}

BOOST_AUTO_TEST_CASE(measured_U2_8_leaves_the_compaction_out) {
    const Measured m = read("sawyer2001_U2.8_0.3s.txt");
    const PlateSeries plate{m.step, m.gap};
    const SteadyWindow w = window(m, plate);
    BOOST_TEST_MESSAGE("U2.8: steady " << w.steady << " from " << w.t_start << " s; " << w.to_json().dump());
    const std::size_t n = m.gap.size();
    const double end = mean(m.gap, n - n / 5, n);  // where the gap ends: the last fifth
    BOOST_TEST(w.t_start > 0.055);                 // MSER-5 alone's start
    if (w.steady) BOOST_TEST(std::abs(mean(m.gap, w.plate_start, n) / end - 1.0) < kGapDrift);
}
