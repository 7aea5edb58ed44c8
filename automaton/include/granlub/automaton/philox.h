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

// The engine's random source. The interface (below, coin, uniform) is what the rules use; tests
// substitute a scripted source with the same interface.
class Philox {
public:
    Philox(std::uint64_t seed, std::uint64_t stream)
        : key_{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)},
          stream_(stream) {}

    std::uint32_t next32() {
        if (pos_ == 4) refill();
        return buf_[pos_++];
    }
    // Uniform integer in [0, n), n >= 1, unbiased (Lemire, ACM TOMS 2019 "Fast random integer
    // generation in an interval").
    std::uint32_t below(std::uint32_t n) {
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
    // A fair coin, one bit at a time from a 32-bit reservoir.
    bool coin() {
        if (bits_left_ == 0) {
            bits_ = next32();
            bits_left_ = 32;
        }
        const bool b = bits_ & 1u;
        bits_ >>= 1;
        --bits_left_;
        return b;
    }
    // Uniform double in [0, 1) with 53 random bits.
    double uniform() {
        const std::uint64_t hi = next32() >> 5, lo = next32() >> 6;  // 27 + 26 bits
        return static_cast<double>((hi << 26) | lo) * 0x1.0p-53;
    }
    std::uint64_t blocks_used() const { return counter_; }

private:
    void refill() {
        buf_ = philox4x32_10({static_cast<std::uint32_t>(counter_), static_cast<std::uint32_t>(counter_ >> 32),
                              static_cast<std::uint32_t>(stream_), static_cast<std::uint32_t>(stream_ >> 32)},
                             key_);
        ++counter_;
        pos_ = 0;
    }
    std::array<std::uint32_t, 2> key_;
    std::uint64_t stream_;
    std::uint64_t counter_ = 0;
    Philox4x32 buf_{};
    int pos_ = 4;
    std::uint32_t bits_ = 0;
    int bits_left_ = 0;
};

// Stream ids: replica r uses 2r for its update order and 2r + 1 for its rule draws.
constexpr std::uint64_t order_stream(std::uint64_t replica) { return 2 * replica; }
constexpr std::uint64_t rules_stream(std::uint64_t replica) { return 2 * replica + 1; }

}  // namespace granlub::automaton
