// The scalar field an isosurface is extracted from: the values and quantized gradients at every
// point of an LEB grid (reference/leb/leb_grid.h), read either from an uncompressed array or from
// the compressed stream through the page cache (Gregorski et al. 2004, section 4: "the data is
// decompressed on demand as the mesh is refined").
//
// The field on the grid is the volume extended to (2^k + 1)^3 points by the LEB codec's padding
// rule (reference/leb/prediction.h: a padding point takes its prediction, the floor mean of its
// split-edge endpoints; root corners outside the volume are 0), so both sources give the same
// value at every grid point, bit for bit. Surfaces are clipped to the volume's box
// [0, X-1] x [0, Y-1] x [0, Z-1] by the extraction, so the padding never shows.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "reference/common/volume.h"
#include "reference/leb/leb_grid.h"
#include "reference/leb/leb_reader.h"

namespace voxref::ref {

// What the field holds at a grid point: the value and the stored gradient, snorm8 per component
// (reference/leb/gradients.h).
struct FieldSample {
  std::uint16_t value = 0;
  std::array<std::int8_t, 3> gradient{};
};

class GridField {
 public:
  virtual ~GridField() = default;
  virtual const LebGrid& grid() const = 0;
  virtual const Dims3& volumeDims() const = 0;
  // Both at once: extraction needs both for every corner, and a compressed field finds the point
  // once.
  virtual FieldSample at(const GridPoint& p) = 0;
};

// The volume (and its quantized gradients) extended to the grid, held uncompressed: 2 + 3 bytes
// per grid point. Throws std::invalid_argument for gradients of the wrong size.
class DenseGridField final : public GridField {
 public:
  DenseGridField(const Volume<std::uint16_t>& volume, const std::vector<std::int8_t>& gradients);
  const LebGrid& grid() const override { return grid_; }
  const Dims3& volumeDims() const override { return dims_; }
  FieldSample at(const GridPoint& p) override;
  const std::vector<std::uint16_t>& values() const { return values_; }

 private:
  LebGrid grid_;
  Dims3 dims_;
  std::vector<std::uint16_t> values_;   // linearIndex order
  std::vector<std::int8_t> gradients_;  // 3 per point, linearIndex order
};

// The field read from a compressed stream with a gradients channel: every value comes from
// LebReader (pages decoded on demand, kept in its LRU cache, one walk of the hierarchy for a
// point's sample and gradient; points already asked for come from its memo, whose slots keep grid
// neighbours together: leb_reader.h). In front of the reader, the last answers sit in a small
// direct-mapped table (kRecentPoints entries by linear index, 192 KiB, within a core's second-level
// cache): an extraction reads each grid point for every tetrahedron around it, one after another,
// and those repeats cost a table lookup instead of a query of the reader (whose memo spans tens of
// megabytes). The field does not change, so a remembered answer is the reader's answer.
// Throws std::invalid_argument for a stream without gradients.
class CompressedGridField final : public GridField {
 public:
  CompressedGridField(std::shared_ptr<const LebStream> stream, std::size_t pageCacheBytes);
  const LebGrid& grid() const override { return grid_; }
  const Dims3& volumeDims() const override { return dims_; }
  FieldSample at(const GridPoint& p) override;
  const LebReader& reader() const { return reader_; }

 private:
  static constexpr std::size_t kRecentPoints = std::size_t{1} << 14;
  struct Recent {
    std::uint32_t key = ~std::uint32_t{0};  // the point's linear index (all ones: empty)
    FieldSample sample;
  };
  LebGrid grid_;
  Dims3 dims_;
  LebReader reader_;
  std::vector<Recent> recent_ = std::vector<Recent>(kRecentPoints);
};

// The gradient as a unit-free vector (components / 127).
inline glm::dvec3 gradientVector(const std::array<std::int8_t, 3>& g) { return glm::dvec3(g[0], g[1], g[2]) / 127.0; }

}  // namespace voxref::ref
