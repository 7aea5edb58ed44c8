// Counter-based random numbers: Philox4x32-10 (Salmon, Moraes, Dror & Shaw, "Parallel random
// numbers: as easy as 1, 2, 3", SC'11). A stream is (key = seed, counter high words = stream id),
// so every ensemble replica and every role (update order, rule draws) gets an independent,
// reproducible stream without shared state. Never std::rand.
#pragma once
#include <array>
#include <cstdint>

namespace granlub::automaton {

using Philox4x32 = std::array<std::uint32_t, 4>;

// One Philox4x32-10 block: the bijection counter -> 128 random bits under `key`.
constexpr Philox4x32 philox4x32_10(Philox4x32 ctr, std::array<std::uint32_t, 2> key) {
    constexpr std::uint32_t M0 = 0xD2511F53u, M1 = 0xCD9E8D57u;
    constexpr std::uint32_t W0 = 0x9E3779B9u, W1 = 0xBB67AE85u;
    for (int round = 0; round < 10; ++round) {
        if (round > 0) {
            key[0] += W0;
            key[1] += W1;
        }
        const std::uint64_t p0 = std::uint64_t{M0} * ctr[0];
        const std::uint64_t p1 = std::uint64_t{M1} * ctr[2];
        ctr = {static_cast<std::uint32_t>(p1 >> 32) ^ ctr[1] ^ key[0], static_cast<std::uint32_t>(p1),
               static_cast<std::uint32_t>(p0 >> 32) ^ ctr[3] ^ key[1], static_cast<std::uint32_t>(p0)};
    }
    return ctr;
}

// kPhiloxBatch consecutive blocks, counters ctr, ctr + 1, ... under (key, stream), written to out
// word by word (block k's words at out[4k .. 4k+3]): exactly the words philox4x32_10 gives one
// block at a time. SIMD on x86-64 (SSE2, or AVX2 when the CPU has it; philox.cpp).
inline constexpr int kPhiloxBatch = 32;
void philox4x32_10_batch(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key,
                         std::uint32_t* out);
// The individual versions, for the tests: the scalar reference; the SSE2 and AVX2 versions exist
// on x86-64 only (the AVX2 one returns false, writing nothing, on a CPU without AVX2).
void philox4x32_10_batch_reference(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key,
                                   std::uint32_t* out);
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
void philox4x32_10_batch_sse2(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key,
                              std::uint32_t* out);
bool philox4x32_10_batch_avx2(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key,
                              std::uint32_t* out);
#endif

// The engine's random source. The interface (below, coin, uniform) is what the rules use; tests
// substitute a scripted source with the same interface. Words are generated kPhiloxBatch blocks
// at a time; the stream (block c's four words in order, c = 0, 1, ...) is the same as one block
// at a time.
class Philox {
public:
    Philox(std::uint64_t seed, std::uint64_t stream)
        : key_{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)},
          stream_(stream) {}

    // The draws are forced inline: they sit in the step loop's hottest paths, and the compiler's
    // inlining budget for that big loop body would otherwise turn some of them into calls
    // (measured with bench_automaton).
    [[gnu::always_inline]] std::uint32_t next32() {
        if (pos_ == kWords) [[unlikely]] refill();
        return buf_[pos_++];
    }
    // Uniform integer in [0, n), n >= 1, unbiased (Lemire, ACM TOMS 2019 "Fast random integer
    // generation in an interval").
    [[gnu::always_inline]] std::uint32_t below(std::uint32_t n) {
        std::uint64_t m = std::uint64_t{next32()} * n;
        auto low = static_cast<std::uint32_t>(m);
        if (low < n) {
            const std::uint32_t threshold = (0u - n) % n;
            while (low < threshold) {
                m = std::uint64_t{next32()} * n;
                low = static_cast<std::uint32_t>(m);
            }
        }
        return static_cast<std::uint32_t>(m >> 32);
    }
    // A fair coin, one bit at a time from a 32-bit word, lowest bit first. The reservoir holds
    // the unused bits below a sentinel bit: it is empty when only the sentinel is left.
    struct Coins {
        std::uint64_t bits = 1;
    };
    bool coin() { return coin_from(coins_); }
    // The same coin with the reservoir held elsewhere (the engine keeps it in a register for a
    // whole step and hands it back with coins()): same words, same bits, same order.
    [[gnu::always_inline]] bool coin_from(Coins& c) {
        if (c.bits == 1) [[unlikely]] refill_coins(c);
        const bool b = c.bits & 1u;
        c.bits >>= 1;
        return b;
    }
    Coins& coins() { return coins_; }
    // Refill an empty reservoir with the next word (callers that test for "empty" themselves).
    void refill_coins(Coins& c) { c.bits = next32() | (std::uint64_t{1} << 32); }
    // Uniform double in [0, 1) with 53 random bits.
    [[gnu::always_inline]] double uniform() {
        const std::uint64_t hi = next32() >> 5;  // 27 + 26 bits
        const std::uint64_t lo = next32() >> 6;
        return static_cast<double>((hi << 26) | lo) * 0x1.0p-53;
    }
    std::uint64_t blocks_generated() const { return counter_; }

private:
    static constexpr int kWords = 4 * kPhiloxBatch;
    [[gnu::noinline]] void refill() {
        philox4x32_10_batch(counter_, stream_, key_, buf_.data());
        counter_ += kPhiloxBatch;
        pos_ = 0;
    }
    std::array<std::uint32_t, 2> key_;
    std::uint64_t stream_;
    std::uint64_t counter_ = 0;
    std::array<std::uint32_t, kWords> buf_{};
    int pos_ = kWords;
    Coins coins_;
};

// Stream ids: replica r uses 2r for its update order and 2r + 1 for its rule draws.
constexpr std::uint64_t order_stream(std::uint64_t replica) { return 2 * replica; }
constexpr std::uint64_t rules_stream(std::uint64_t replica) { return 2 * replica + 1; }

}  // namespace granlub::automaton
