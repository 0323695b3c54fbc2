// Test helper: the volumes and coders the LEB codec tests encode, shared by the codec and the
// derived-gradients tests, and the error a corrupt stream's decode gives.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>

#include "reference/common/byte_stream.h"
#include "reference/common/volume.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_stream.h"

namespace voxref::ref::test_support {

// Uniform random samples of `bits` bits.
inline Volume<std::uint16_t> noise(const Dims3& d, int bits, unsigned seed) {
  Volume<std::uint16_t> v(d);
  std::mt19937 rng(seed);
  for (auto& s : v.data()) s = static_cast<std::uint16_t>(rng() & ((1u << bits) - 1));
  return v;
}

// A smooth field with some structure (so predictions are mostly good).
inline Volume<std::uint16_t> smooth(const Dims3& d, int bits) {
  Volume<std::uint16_t> v(d);
  const double top = (1 << bits) - 1;
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x)
        v.at(x, y, z) =
            static_cast<std::uint16_t>(top * (0.5 + 0.5 * std::sin(0.21 * x + 0.13 * y * y / (1.0 + y) - 0.17 * z)));
  return v;
}

inline constexpr LebCoder kLebCoders[] = {LebCoder::Lead1, LebCoder::Adaptive};

// The StreamError of parsing and decoding a whole stream, or "" when it decodes.
inline std::string lebDecodeError(std::string bytes) {
  try {
    decodeLeb(parseLebStream(std::move(bytes)));
  } catch (const StreamError& e) {
    return e.what();
  }
  return "";
}

}  // namespace voxref::ref::test_support
