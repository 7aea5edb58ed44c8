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

// The batched generator (16-32 blocks at a time, SIMD) gives exactly the one-block-at-a-time words.
BOOST_AUTO_TEST_CASE(batched_blocks_equal_single_blocks) {
    const std::array<std::uint32_t, 2> key = {0xa4093822u, 0x299f31d0u};
    const std::uint64_t stream = 0x0370734413198a2eULL;
    for (std::uint64_t ctr : {std::uint64_t{0}, std::uint64_t{0xfffffff0u}, std::uint64_t{123456789012345}}) {
        std::vector<std::uint32_t> ref(4 * kPhiloxBatch), got(4 * kPhiloxBatch);
        for (int k = 0; k < kPhiloxBatch; ++k) {
            const std::uint64_t c = ctr + static_cast<std::uint64_t>(k);
            const Philox4x32 b = philox4x32_10({static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(c >> 32),
                                                static_cast<std::uint32_t>(stream), static_cast<std::uint32_t>(stream >> 32)},
                                               key);
            for (int w = 0; w < 4; ++w) ref[static_cast<std::size_t>(4 * k + w)] = b[static_cast<std::size_t>(w)];
        }
        philox4x32_10_batch(ctr, stream, key, got.data());
        BOOST_TEST(got == ref, boost::test_tools::per_element());
        philox4x32_10_batch_reference(ctr, stream, key, got.data());
        BOOST_TEST(got == ref, boost::test_tools::per_element());
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
        philox4x32_10_batch_sse2(ctr, stream, key, got.data());
        BOOST_TEST(got == ref, boost::test_tools::per_element());
        if (philox4x32_10_batch_avx2(ctr, stream, key, got.data())) BOOST_TEST(got == ref, boost::test_tools::per_element());
#endif
    }
    // The stream across several batches: block c's words in order.
    Philox g(0x299f31d0a4093822ULL, 7);
    for (std::uint32_t c = 0; c < 3 * kPhiloxBatch + 5; ++c) {
        const Philox4x32 b = philox4x32_10({c, 0, 7, 0}, {0xa4093822u, 0x299f31d0u});
        for (int w = 0; w < 4; ++w) BOOST_TEST(g.next32() == b[static_cast<std::size_t>(w)]);
    }
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

// The coin contract the engine's bit-identical results rest on: coin k is bit k % 32 (lowest
// first) of the stream's word k / 32, interleaved draws taking the next words.
BOOST_AUTO_TEST_CASE(coins_are_the_bits_of_successive_words) {
    Philox coins(5, 3), words(5, 3);
    std::uint32_t w = 0;
    for (int k = 0; k < 100; ++k) {
        if (k % 32 == 0) w = words.next32();
        BOOST_TEST_REQUIRE(coins.coin() == (((w >> (k % 32)) & 1u) != 0), "coin " << k);
    }
    // Four bits of the fourth word are left in the reservoir; a draw in between takes word 5.
    BOOST_TEST(coins.next32() == words.next32());
    for (int k = 4; k < 32; ++k) BOOST_TEST_REQUIRE(coins.coin() == (((w >> k) & 1u) != 0));
    const std::uint32_t w6 = words.next32();
    BOOST_TEST(coins.coin() == ((w6 & 1u) != 0));
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
    p.rules.tf_max = 70000;  // the integer clock is 16 bits
    BOOST_TEST(fails_with(p, "tf_max = 70000"));
    p = ok;
    p.run.t_avg_start = 2100;
    BOOST_TEST(fails_with(p, "t_avg_start = 2100"));
    p = ok;
    p.run.steps = 2400;  // no full block after t_avg_start
    BOOST_TEST(fails_with(p, "steps = 2400"));
}
