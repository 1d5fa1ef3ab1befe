// largestIndex (detail/geometry/largest_index.hpp): a plain loop, and on x86 where the CPU has
// AVX2 the same maximum eight lanes at a time (unsigned max; the restart index, where it is one,
// masked to 0 first), with the tail by the plain loop.
#include <softraster/detail/geometry/largest_index.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <cstddef>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace softraster::detail {
namespace {

std::uint32_t largestIndexPlain(const std::uint32_t* p, std::size_t n, bool restart) {
  std::uint32_t largest = 0;
  for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, restart && p[i] == kPrimitiveRestartIndex ? 0u : p[i]);
  return largest;
}

#if defined(__x86_64__) && defined(__GNUC__)
// Eight indices, with restart (maskRestart all ones) the restart index among them as 0.
[[gnu::target("avx2"), gnu::always_inline]] inline __m256i eightIndices(const std::uint32_t* q, __m256i maskRestart) {
  const __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(q));
  const __m256i restartIndex = _mm256_set1_epi32(-1);  // kPrimitiveRestartIndex
  return _mm256_andnot_si256(_mm256_and_si256(maskRestart, _mm256_cmpeq_epi32(v, restartIndex)), v);
}

// Two vectors a step, so the maximum's dependency chain does not set the pace.
[[gnu::target("avx2")]] std::uint32_t largestIndexAvx2(const std::uint32_t* p, std::size_t n, bool restart) {
  const __m256i maskRestart = restart ? _mm256_set1_epi32(-1) : _mm256_setzero_si256();
  __m256i a = _mm256_setzero_si256(), b = _mm256_setzero_si256();
  std::size_t i = 0;
  for (; i + 16 <= n; i += 16) {
    a = _mm256_max_epu32(a, eightIndices(p + i, maskRestart));
    b = _mm256_max_epu32(b, eightIndices(p + i + 8, maskRestart));
  }
  if (i + 8 <= n) {
    a = _mm256_max_epu32(a, eightIndices(p + i, maskRestart));
    i += 8;
  }
  a = _mm256_max_epu32(a, b);
  __m128i m = _mm_max_epu32(_mm256_castsi256_si128(a), _mm256_extracti128_si256(a, 1));
  m = _mm_max_epu32(m, _mm_shuffle_epi32(m, 0x4E));
  m = _mm_max_epu32(m, _mm_shuffle_epi32(m, 0xB1));
  const auto vectors = static_cast<std::uint32_t>(_mm_cvtsi128_si32(m));
  return std::max(vectors, largestIndexPlain(p + i, n - i, restart));
}
#endif

}  // namespace

std::uint32_t largestIndex(std::span<const std::uint32_t> indices, bool restart) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (__builtin_cpu_supports("avx2")) return largestIndexAvx2(indices.data(), indices.size(), restart);
#endif
  return largestIndexPlain(indices.data(), indices.size(), restart);
}

}  // namespace softraster::detail
