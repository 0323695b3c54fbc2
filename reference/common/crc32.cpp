#include "reference/common/crc32.h"
#include "reference/common/crc32_paths.h"

#include <array>
#include <cstddef>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace voxref::ref {
namespace {

constexpr std::uint32_t kReflectedPolynomial = 0xEDB88320u;

// The byte-wise table of the reflected polynomial (Sarwate's algorithm), and the seven tables of
// slicing-by-8 (Kounavis and Berry, "A Systematic Approach to Building High Performance
// Software-Based CRC Generators", 2005): table j gives the CRC of a byte followed by j zero bytes,
// so eight bytes are folded in by eight independent lookups.
using Tables = std::array<std::array<std::uint32_t, 256>, 8>;
constexpr Tables makeTables() {
  Tables t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int b = 0; b < 8; ++b) c = (c & 1) ? kReflectedPolynomial ^ (c >> 1) : c >> 1;
    t[0][i] = c;
  }
  for (std::size_t j = 1; j < 8; ++j)
    for (std::size_t i = 0; i < 256; ++i) t[j][i] = (t[j - 1][i] >> 8) ^ t[0][t[j - 1][i] & 0xffu];
  return t;
}
constexpr Tables kTables = makeTables();

std::uint32_t littleEndian32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

// The register form of the table algorithms: state c (the checksum's complement) over n bytes.
std::uint32_t slicedState(std::uint32_t c, const unsigned char* p, std::size_t n) {
  for (; n >= 8; n -= 8, p += 8) {
    const std::uint32_t lo = c ^ littleEndian32(p), hi = littleEndian32(p + 4);
    c = kTables[7][lo & 0xffu] ^ kTables[6][(lo >> 8) & 0xffu] ^ kTables[5][(lo >> 16) & 0xffu] ^ kTables[4][lo >> 24] ^
        kTables[3][hi & 0xffu] ^ kTables[2][(hi >> 8) & 0xffu] ^ kTables[1][(hi >> 16) & 0xffu] ^ kTables[0][hi >> 24];
  }
  for (; n > 0; --n, ++p) c = kTables[0][(c ^ *p) & 0xffu] ^ (c >> 8);
  return c;
}

#if defined(__x86_64__)
// x^n mod P in the reflected form the folding multiplies by: the 32-bit remainder bit-reversed,
// shifted left by one (the product of two reflected operands comes out one bit low). Gopal et al.,
// "Fast CRC Computation for Generic Polynomials Using PCLMULQDQ Instruction" (Intel, 2009): a
// 64-bit half of a 128-bit block moves forward by d bits when it is multiplied by
// x^(d + 32) (the half that comes first in the stream) or x^(d - 32) (the other).
constexpr std::uint64_t foldConstant(int n) {
  std::uint32_t r = 1;  // x^0, bit i the coefficient of x^i (the normal form, polynomial 0x04C11DB7)
  for (int i = 0; i < n; ++i) r = (r & 0x80000000u) ? (r << 1) ^ 0x04C11DB7u : r << 1;
  std::uint64_t reflected = 0;
  for (int i = 0; i < 32; ++i) reflected |= static_cast<std::uint64_t>((r >> i) & 1u) << (31 - i);
  return reflected << 1;
}

constexpr std::uint64_t kFold512[2] = {foldConstant(4 * 128 + 32), foldConstant(4 * 128 - 32)};
constexpr std::uint64_t kFold128[2] = {foldConstant(128 + 32), foldConstant(128 - 32)};
static_assert(kFold512[0] == 0x154442bd4u && kFold128[1] == 0x0ccaa009eu,
              "k1 and k4 of the CRC-32 constants at the end of Gopal et al.");

__m128i load(const unsigned char* q) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(q)); }

// A lane moved forward by the distance of k's constants, added to the lane there.
__attribute__((target("pclmul"))) __m128i fold(__m128i lane, __m128i k, __m128i next) {
  return _mm_xor_si128(_mm_xor_si128(_mm_clmulepi64_si128(lane, k, 0x00), _mm_clmulepi64_si128(lane, k, 0x11)), next);
}

// The checksum's state over n >= 64 bytes by carry-less multiplication: four 128-bit lanes fold
// forward by 512 bits until fewer than 64 bytes are left, then into one lane, which folds forward by
// 128 bits while 16 bytes are left. Folding keeps the message's remainder modulo P, so the lane's
// 16 bytes followed by the bytes not folded have the checksum of the whole (with the state, put
// into the first four bytes, already in the lane): the table algorithm finishes from state 0.
__attribute__((target("pclmul"))) std::uint32_t foldedState(std::uint32_t c, const unsigned char* p, std::size_t n) {
  // Each lane's first half (its low 64 bits, the earlier bytes) times the first constant.
  const __m128i by512 = _mm_set_epi64x(static_cast<long long>(kFold512[1]), static_cast<long long>(kFold512[0]));
  const __m128i by128 = _mm_set_epi64x(static_cast<long long>(kFold128[1]), static_cast<long long>(kFold128[0]));
  __m128i x0 = _mm_xor_si128(load(p), _mm_cvtsi32_si128(static_cast<int>(c))), x1 = load(p + 16), x2 = load(p + 32),
          x3 = load(p + 48);
  p += 64;
  n -= 64;
  for (; n >= 64; n -= 64, p += 64) {
    x0 = fold(x0, by512, load(p));
    x1 = fold(x1, by512, load(p + 16));
    x2 = fold(x2, by512, load(p + 32));
    x3 = fold(x3, by512, load(p + 48));
  }
  x0 = fold(fold(fold(x0, by128, x1), by128, x2), by128, x3);
  for (; n >= 16; n -= 16, p += 16) x0 = fold(x0, by128, load(p));
  alignas(16) unsigned char lane[16];
  _mm_store_si128(reinterpret_cast<__m128i*>(lane), x0);
  return slicedState(slicedState(0, lane, 16), p, n);
}

bool hasCarrylessMultiply() {
  static const bool has = __builtin_cpu_supports("pclmul");
  return has;
}
#endif

}  // namespace

namespace crc32_detail {

std::uint32_t slicedUpdate(std::uint32_t crc, std::string_view bytes) {
  return ~slicedState(~crc, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

bool foldedAvailable() {
#if defined(__x86_64__)
  return hasCarrylessMultiply();
#else
  return false;
#endif
}

std::uint32_t foldedUpdate(std::uint32_t crc, std::string_view bytes) {
#if defined(__x86_64__)
  if (hasCarrylessMultiply() && bytes.size() >= 64)
    return ~foldedState(~crc, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
#endif
  return slicedUpdate(crc, bytes);
}

}  // namespace crc32_detail

std::uint32_t crc32Update(std::uint32_t crc, std::string_view bytes) { return crc32_detail::foldedUpdate(crc, bytes); }

}  // namespace voxref::ref
