// The input layout of context_page_fuzz (tests/fuzz/context_page_fuzz.cpp), shared with the seed
// maker (make_fuzz_seeds context_page) so that its seeds are pages of the volume the target builds.
//
// Byte 0 selects the channel (bit 1: a page of gradients, "Context gradient pages"; else of
// samples) and the sample bits (bit 0: 16, else 8), bytes 1-3 the extents (1 + byte mod 12 each),
// byte 4 the page bits (4 + byte mod 3), byte 5 which of the volume's stored pages (those holding
// one of its points, by byte mod their count) the rest of the input is. The volume's samples are a
// fixed smooth field, its gradients fixed int8 triples (on the unit sphere and off it).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "reference/leb/context_gradient_coder.h"
#include "reference/leb/context_value_coder.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_padding.h"

namespace voxref::fuzz {

struct ContextPageInput {
  int bits = 8, pageBits = 4;
  ref::Dims3 dims{1, 1, 1};
  std::uint64_t page = 0;
  bool gradients = false;
  std::vector<std::int32_t> volume;                 // x fastest
  std::vector<std::array<std::int8_t, 3>> vectors;  // x fastest
};

inline constexpr std::size_t kContextPageHeader = 6;

inline ContextPageInput contextPageInput(const ref::HzOrder& order, const std::uint8_t* header) {
  ContextPageInput in;
  in.bits = (header[0] & 1) ? 16 : 8;
  in.gradients = (header[0] & 2) != 0;
  in.dims = {1 + header[1] % 12, 1 + header[2] % 12, 1 + header[3] % 12};
  in.pageBits = 4 + header[4] % 3;
  std::vector<std::uint64_t> pages;
  order.forEachInside(in.dims, 0, order.size(), [&](std::uint64_t h, const ref::GridPoint&, int, int, unsigned) {
    if (pages.empty() || pages.back() != h >> in.pageBits) pages.push_back(h >> in.pageBits);
  });
  in.page = pages[header[5] % pages.size()];
  in.volume.resize(static_cast<std::size_t>(in.dims[0] * in.dims[1] * in.dims[2]));
  for (int z = 0; z < in.dims[2]; ++z)
    for (int y = 0; y < in.dims[1]; ++y)
      for (int x = 0; x < in.dims[0]; ++x)
        in.volume[ref::volumeIndex({x, y, z}, in.dims)] =
            static_cast<std::int32_t>(((1 << in.bits) - 1) * (0.5 + 0.5 * std::sin(0.4 * x - 0.3 * y + 0.2 * z)));
  in.vectors.resize(in.volume.size());
  for (std::size_t i = 0; i < in.vectors.size(); ++i) {
    const double a = 0.7 * static_cast<double>(i), b = 0.3 * static_cast<double>(i);
    const double v[3] = {std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)};
    for (std::size_t k = 0; k < 3; ++k)  // every fifth off the sphere, every seventh zero
      in.vectors[i][k] = i % 7 == 0 ? 0 : static_cast<std::int8_t>(std::lround((i % 5 == 0 ? 90.0 : 127.0) * v[k]));
  }
  return in;
}

// Decodes `page` as the input's page into `values` (the volume: its other pages hold their own
// samples, the corners the page reads); throws StreamError as ContextPageReader does.
inline void decodeInputPage(const std::string& page, const ref::HzOrder& order, const ContextPageInput& in,
                            std::vector<std::int32_t>& values) {
  ref::ContextPageReader reader(page, in.bits, in.pageBits, in.page, 0, "context page " + std::to_string(in.page));
  reader.decode(
      order, in.dims, [&](const ref::GridPoint& q) { return values[ref::volumeIndex(q, in.dims)]; },
      [&](std::uint64_t, const ref::GridPoint& p, std::int32_t v) { values[ref::volumeIndex(p, in.dims)] = v; });
}

// The same for a page of gradients into `vectors` (ContextGradientPageReader).
inline void decodeInputGradientPage(const std::string& page, const ref::HzOrder& order, const ContextPageInput& in,
                                    std::vector<std::array<std::int8_t, 3>>& vectors) {
  ref::ContextGradientPageReader reader(page, in.pageBits, in.page, 0, "gradients page " + std::to_string(in.page));
  reader.decode(
      order, in.dims, [&](const ref::GridPoint& q) { return vectors[ref::volumeIndex(q, in.dims)]; },
      [&](std::uint64_t, const ref::GridPoint& p, const std::array<std::int8_t, 3>& g) {
        vectors[ref::volumeIndex(p, in.dims)] = g;
      });
}

// The grid the header's extents lie in.
inline ref::LebGrid contextPageGrid(const std::uint8_t* header) {
  return ref::lebGridCovering({1 + header[1] % 12, 1 + header[2] % 12, 1 + header[3] % 12});
}

}  // namespace voxref::fuzz
