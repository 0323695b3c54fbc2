#include "reference/iso/grid_field.h"

#include <stdexcept>
#include <string>

#include "reference/leb/hz_order.h"
#include "reference/leb/leb_page.h"
#include "reference/leb/prediction.h"

namespace voxref::ref {

DenseGridField::DenseGridField(const Volume<std::uint16_t>& volume, const std::vector<std::int8_t>& gradients)
    : grid_(lebGridCovering(volume.dims())), dims_(volume.dims()) {
  requireIndexedGrid(grid_, "the isosurface field");
  if (gradients.size() != 3 * volume.data().size())
    throw std::invalid_argument("gradients: " + std::to_string(gradients.size()) + " components for " +
                                std::to_string(volume.data().size()) + " samples (3 per sample expected)");
  values_.assign(grid_.pointCount(), 0);
  gradients_.assign(3 * grid_.pointCount(), 0);
  // Walk the points coarse to fine (hierarchical order), so every padding point finds its split
  // edge's endpoints already set: the codec's padding rule (prediction.h).
  const HzOrder order(grid_);
  for (HzCursor c(order, 0); !c.done(); c.next()) {
    const GridPoint& p = c.point();
    const std::uint64_t i = grid_.linearIndex(p);
    if (insideVolume(p, dims_)) {
      const std::size_t s = volume.index(p[0], p[1], p[2]);
      values_[i] = volume.data()[s];
      for (int a = 0; a < 3; ++a)
        gradients_[3 * i + static_cast<std::uint64_t>(a)] = gradients[3 * s + static_cast<std::size_t>(a)];
    } else if (c.level() >= 0) {
      const SplitEdge e = splitEdgeOf(p, c.scaleLog2(), c.oddAxes());
      const std::uint64_t ia = grid_.linearIndex(e.a), ib = grid_.linearIndex(e.b);
      values_[i] = static_cast<std::uint16_t>(predictMidpoint(values_[ia], values_[ib]));
      for (std::uint64_t a = 0; a < 3; ++a)
        gradients_[3 * i + a] =
            static_cast<std::int8_t>(predictMidpoint(gradients_[3 * ia + a], gradients_[3 * ib + a]));
    }  // a root corner outside the volume: 0 (its prediction)
  }
}

FieldSample DenseGridField::at(const GridPoint& p) {
  const std::uint64_t i = grid_.linearIndex(p);
  return {values_[i], {gradients_[3 * i], gradients_[3 * i + 1], gradients_[3 * i + 2]}};
}

CompressedGridField::CompressedGridField(std::shared_ptr<const LebStream> stream, std::size_t pageCacheBytes)
    : grid_(stream->grid), dims_(stream->dims), reader_(stream, pageCacheBytes) {
  if (!stream->hasGradients())
    throw std::invalid_argument(
        "the stream has no gradients (encoded with --no-gradients): isosurfaces need the gradients for "
        "shading");
}

FieldSample CompressedGridField::at(const GridPoint& p) {
  if (!grid_.contains(p)) reader_.sampleAndGradient(p);  // throws, naming the point
  const auto key = static_cast<std::uint32_t>(grid_.linearIndex(p));
  Recent& r = recent_[key & (kRecentPoints - 1)];
  if (r.key == key) return r.sample;
  const LebReader::SampleAndGradient both = reader_.sampleAndGradient(p);
  r = {key, FieldSample{both.sample, both.gradient}};
  return r.sample;
}

}  // namespace voxref::ref
