// Philox4x32-10 against the Random123 known-answer vectors (kat_vectors), and the derived draws.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "granlub/automaton/params.h"
#include "granlub/automaton/philox.h"
#include "granlub/error.h"

using namespace granlub::automaton;

BOOST_AUTO_TEST_CASE(philox_known_answers) {
    using A = Philox4x32;
    BOOST_TEST((philox4x32_10({0, 0, 0, 0}, {0, 0}) == A{0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8}));
    BOOST_TEST((philox4x32_10({0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff}, {0xffffffff, 0xffffffff}) ==
                A{0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd}));
    BOOST_TEST((philox4x32_10({0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344}, {0xa4093822, 0x299f31d0}) ==
                A{0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1}));
}

BOOST_AUTO_TEST_CASE(streams_are_reproducible_and_distinct) {
    Philox a(42, 3), b(42, 3), c(42, 4), d(43, 3);
    int same_c = 0, same_d = 0;
    for (int k = 0; k < 1000; ++k) {
        const auto x = a.next32();
        BOOST_TEST(x == b.next32());
        same_c += x == c.next32();
        same_d += x == d.next32();
    }
    BOOST_TEST(same_c < 3);
    BOOST_TEST(same_d < 3);
}

BOOST_AUTO_TEST_CASE(draws_are_uniform) {
    Philox g(1, 0);
    const int n = 7, draws = 700000;
    std::vector<int> hist(n, 0);
    double sum = 0;
    int heads = 0;
    for (int k = 0; k < draws; ++k) {
        const auto v = g.below(n);
        BOOST_REQUIRE(v < static_cast<unsigned>(n));
        ++hist[v];
        const double u = g.uniform();
        BOOST_REQUIRE((u >= 0.0 && u < 1.0));
        sum += u;
        heads += g.coin();
    }
    const double expect = double(draws) / n, sd = std::sqrt(expect * (1 - 1.0 / n));
    for (int h : hist) BOOST_TEST(std::abs(h - expect) < 5 * sd);
    BOOST_TEST(std::abs(sum / draws - 0.5) < 5 * std::sqrt(1.0 / 12 / draws));
    BOOST_TEST(std::abs(heads - draws / 2.0) < 5 * std::sqrt(draws / 4.0));
}

BOOST_AUTO_TEST_CASE(parameter_validation_names_the_problem) {
    auto fails_with = [](Params p, const std::string& key) {
        try {
            validate(p);
        } catch (const granlub::Error& e) {
            return std::string(e.what()).find(key) != std::string::npos;
        }
        return false;
    };
    Params ok;
    BOOST_CHECK_NO_THROW(validate(ok));
    Params p = ok;
    p.lattice.fill = 1.2;
    BOOST_TEST(fails_with(p, "fill = 1.2"));
    p = ok;
    p.lattice.rows = 2;
    BOOST_TEST(fails_with(p, "rows = 2"));
    p = ok;
    p.rules.e_p = 1.5;
    BOOST_TEST(fails_with(p, "e_p"));
    p = ok;
    p.rules.pp_deflect = 60;
    BOOST_TEST(fails_with(p, "pp_deflect = 60"));
    p = ok;
    p.run.t_avg_start = 2100;
    BOOST_TEST(fails_with(p, "t_avg_start = 2100"));
    p = ok;
    p.run.steps = 2400;  // no full block after t_avg_start
    BOOST_TEST(fails_with(p, "steps = 2400"));
}
