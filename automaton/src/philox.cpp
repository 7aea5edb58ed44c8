// Batched Philox4x32-10 (see philox.h): kPhiloxBatch = 16 blocks at a time, lane-parallel (one
// block per SIMD lane). The 32 x 32 -> 64-bit multiplies are pmuludq on the even lanes and on the
// odd lanes shifted down. x86-64: an SSE2 version (part of the baseline ISA, so it runs on any
// x86-64 machine) and an AVX2 version chosen at run time when the CPU has AVX2; elsewhere the
// scalar reference. The words are the same in all three (test_philox checks them).
#include "granlub/automaton/philox.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define GRANLUB_PHILOX_X86 1
#include <immintrin.h>
#endif

namespace granlub::automaton {

namespace {

constexpr std::uint32_t M0 = 0xD2511F53u, M1 = 0xCD9E8D57u;
constexpr std::uint32_t W0 = 0x9E3779B9u, W1 = 0xBB67AE85u;

void batch_scalar(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key, std::uint32_t* out) {
    for (int k = 0; k < kPhiloxBatch; ++k) {
        const std::uint64_t c = ctr + static_cast<std::uint64_t>(k);
        const Philox4x32 b = philox4x32_10({static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(c >> 32),
                                            static_cast<std::uint32_t>(stream), static_cast<std::uint32_t>(stream >> 32)},
                                           key);
        for (int w = 0; w < 4; ++w) out[4 * k + w] = b[static_cast<std::size_t>(w)];
    }
}

#ifdef GRANLUB_PHILOX_X86
// 4 blocks per __m128i: lanes of c0..c3 are the blocks' words 0..3.
void batch_sse2(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key, std::uint32_t* out) {
    constexpr int V = kPhiloxBatch / 4;
    const __m128i lo_mask = _mm_set1_epi64x(0xffffffffLL);
    const __m128i m0 = _mm_set1_epi32(static_cast<int>(M0)), m1 = _mm_set1_epi32(static_cast<int>(M1));
    __m128i c0[V], c1[V], c2[V], c3[V];
    for (int v = 0; v < V; ++v) {
        alignas(16) std::uint32_t lo[4], hi[4];
        for (int l = 0; l < 4; ++l) {
            const std::uint64_t c = ctr + static_cast<std::uint64_t>(4 * v + l);
            lo[l] = static_cast<std::uint32_t>(c);
            hi[l] = static_cast<std::uint32_t>(c >> 32);
        }
        c0[v] = _mm_load_si128(reinterpret_cast<const __m128i*>(lo));
        c1[v] = _mm_load_si128(reinterpret_cast<const __m128i*>(hi));
        c2[v] = _mm_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(stream)));
        c3[v] = _mm_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(stream >> 32)));
    }
    std::uint32_t k0 = key[0], k1 = key[1];
    for (int round = 0; round < 10; ++round) {
        const __m128i kk0 = _mm_set1_epi32(static_cast<int>(k0)), kk1 = _mm_set1_epi32(static_cast<int>(k1));
        for (int v = 0; v < V; ++v) {
            const __m128i e0 = _mm_mul_epu32(c0[v], m0), o0 = _mm_mul_epu32(_mm_srli_epi64(c0[v], 32), m0);
            const __m128i e1 = _mm_mul_epu32(c2[v], m1), o1 = _mm_mul_epu32(_mm_srli_epi64(c2[v], 32), m1);
            const __m128i hi0 = _mm_or_si128(_mm_srli_epi64(e0, 32), _mm_andnot_si128(lo_mask, o0));
            const __m128i lo0 = _mm_or_si128(_mm_and_si128(e0, lo_mask), _mm_slli_epi64(o0, 32));
            const __m128i hi1 = _mm_or_si128(_mm_srli_epi64(e1, 32), _mm_andnot_si128(lo_mask, o1));
            const __m128i lo1 = _mm_or_si128(_mm_and_si128(e1, lo_mask), _mm_slli_epi64(o1, 32));
            c0[v] = _mm_xor_si128(_mm_xor_si128(hi1, c1[v]), kk0);
            c2[v] = _mm_xor_si128(_mm_xor_si128(hi0, c3[v]), kk1);
            c1[v] = lo1;
            c3[v] = lo0;
        }
        k0 += W0;  // the key bump before rounds 1..9 (the one after round 9 is unused)
        k1 += W1;
    }
    for (int v = 0; v < V; ++v) {  // 4 x 4 transpose: block by block
        const __m128i t0 = _mm_unpacklo_epi32(c0[v], c1[v]), t1 = _mm_unpacklo_epi32(c2[v], c3[v]);
        const __m128i t2 = _mm_unpackhi_epi32(c0[v], c1[v]), t3 = _mm_unpackhi_epi32(c2[v], c3[v]);
        __m128i* o = reinterpret_cast<__m128i*>(out + 16 * v);
        _mm_storeu_si128(o, _mm_unpacklo_epi64(t0, t1));
        _mm_storeu_si128(o + 1, _mm_unpackhi_epi64(t0, t1));
        _mm_storeu_si128(o + 2, _mm_unpacklo_epi64(t2, t3));
        _mm_storeu_si128(o + 3, _mm_unpackhi_epi64(t2, t3));
    }
}

// 8 blocks per __m256i; the same steps as batch_sse2 in two 128-bit halves (blocks 0-3, 4-7).
__attribute__((target("avx2"))) void batch_avx2(std::uint64_t ctr, std::uint64_t stream,
                                                std::array<std::uint32_t, 2> key, std::uint32_t* out) {
    constexpr int V = kPhiloxBatch / 8;
    const __m256i lo_mask = _mm256_set1_epi64x(0xffffffffLL);
    const __m256i m0 = _mm256_set1_epi32(static_cast<int>(M0)), m1 = _mm256_set1_epi32(static_cast<int>(M1));
    __m256i c0[V], c1[V], c2[V], c3[V];
    for (int v = 0; v < V; ++v) {
        alignas(32) std::uint32_t lo[8], hi[8];
        for (int l = 0; l < 8; ++l) {
            const std::uint64_t c = ctr + static_cast<std::uint64_t>(8 * v + l);
            lo[l] = static_cast<std::uint32_t>(c);
            hi[l] = static_cast<std::uint32_t>(c >> 32);
        }
        c0[v] = _mm256_load_si256(reinterpret_cast<const __m256i*>(lo));
        c1[v] = _mm256_load_si256(reinterpret_cast<const __m256i*>(hi));
        c2[v] = _mm256_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(stream)));
        c3[v] = _mm256_set1_epi32(static_cast<int>(static_cast<std::uint32_t>(stream >> 32)));
    }
    std::uint32_t k0 = key[0], k1 = key[1];
    for (int round = 0; round < 10; ++round) {
        const __m256i kk0 = _mm256_set1_epi32(static_cast<int>(k0)), kk1 = _mm256_set1_epi32(static_cast<int>(k1));
        for (int v = 0; v < V; ++v) {
            const __m256i e0 = _mm256_mul_epu32(c0[v], m0), o0 = _mm256_mul_epu32(_mm256_srli_epi64(c0[v], 32), m0);
            const __m256i e1 = _mm256_mul_epu32(c2[v], m1), o1 = _mm256_mul_epu32(_mm256_srli_epi64(c2[v], 32), m1);
            const __m256i hi0 = _mm256_or_si256(_mm256_srli_epi64(e0, 32), _mm256_andnot_si256(lo_mask, o0));
            const __m256i lo0 = _mm256_or_si256(_mm256_and_si256(e0, lo_mask), _mm256_slli_epi64(o0, 32));
            const __m256i hi1 = _mm256_or_si256(_mm256_srli_epi64(e1, 32), _mm256_andnot_si256(lo_mask, o1));
            const __m256i lo1 = _mm256_or_si256(_mm256_and_si256(e1, lo_mask), _mm256_slli_epi64(o1, 32));
            c0[v] = _mm256_xor_si256(_mm256_xor_si256(hi1, c1[v]), kk0);
            c2[v] = _mm256_xor_si256(_mm256_xor_si256(hi0, c3[v]), kk1);
            c1[v] = lo1;
            c3[v] = lo0;
        }
        k0 += W0;
        k1 += W1;
    }
    for (int v = 0; v < V; ++v) {
        const __m256i t0 = _mm256_unpacklo_epi32(c0[v], c1[v]), t1 = _mm256_unpacklo_epi32(c2[v], c3[v]);
        const __m256i t2 = _mm256_unpackhi_epi32(c0[v], c1[v]), t3 = _mm256_unpackhi_epi32(c2[v], c3[v]);
        const __m256i b0 = _mm256_unpacklo_epi64(t0, t1), b1 = _mm256_unpackhi_epi64(t0, t1);  // blocks 0|4, 1|5
        const __m256i b2 = _mm256_unpacklo_epi64(t2, t3), b3 = _mm256_unpackhi_epi64(t2, t3);  // blocks 2|6, 3|7
        __m256i* o = reinterpret_cast<__m256i*>(out + 32 * v);
        _mm256_storeu_si256(o, _mm256_permute2x128_si256(b0, b1, 0x20));      // blocks 0, 1
        _mm256_storeu_si256(o + 1, _mm256_permute2x128_si256(b2, b3, 0x20));  // blocks 2, 3
        _mm256_storeu_si256(o + 2, _mm256_permute2x128_si256(b0, b1, 0x31));  // blocks 4, 5
        _mm256_storeu_si256(o + 3, _mm256_permute2x128_si256(b2, b3, 0x31));  // blocks 6, 7
    }
}

using BatchFn = void (*)(std::uint64_t, std::uint64_t, std::array<std::uint32_t, 2>, std::uint32_t*);
BatchFn pick() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") ? batch_avx2 : batch_sse2;
}
#endif

}  // namespace

void philox4x32_10_batch(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key,
                         std::uint32_t* out) {
#ifdef GRANLUB_PHILOX_X86
    static const BatchFn fn = pick();
    fn(ctr, stream, key, out);
#else
    batch_scalar(ctr, stream, key, out);
#endif
}

void philox4x32_10_batch_reference(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key,
                                   std::uint32_t* out) {
    batch_scalar(ctr, stream, key, out);
}

#ifdef GRANLUB_PHILOX_X86
void philox4x32_10_batch_sse2(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key,
                              std::uint32_t* out) {
    batch_sse2(ctr, stream, key, out);
}
bool philox4x32_10_batch_avx2(std::uint64_t ctr, std::uint64_t stream, std::array<std::uint32_t, 2> key,
                              std::uint32_t* out) {
    if (!__builtin_cpu_supports("avx2")) return false;
    batch_avx2(ctr, stream, key, out);
    return true;
}
#endif

}  // namespace granlub::automaton
