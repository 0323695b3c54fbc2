// Random access into mirrored LEB streams (mirror_reader.h).
#include "reference/leb/mirror_reader.h"

#include <algorithm>
#include <stdexcept>

#include "reference/leb/gradients.h"

namespace voxref::ref {

MirroredLebReader::MirroredLebReader(std::shared_ptr<const MirroredLebStream> stream, std::size_t cacheBudgetBytes)
    : stream_(std::move(stream)),
      folded_(std::shared_ptr<const LebStream>(stream_, &stream_->inner), cacheBudgetBytes) {}

const LebMirrorException* MirroredLebReader::exceptionAt(const GridPoint& p) const {
  const LebMirrorHeader& h = stream_->header;
  for (int a = 0; a < 3; ++a)
    if (p[a] < 0 || p[a] >= h.dims[a])
      throw std::invalid_argument("MirroredLebReader: point " + pointText(p) + " lies outside the volume " +
                                  dimsText(h.dims) + " (a mirrored stream answers the volume's points only)");
  const std::int64_t* sum = h.planes.sum.data();
  // Only a mirrored point can be an exception.
  const bool mirrored =
      lebMirroredCoordinate(p[0], sum[0]) || lebMirroredCoordinate(p[1], sum[1]) || lebMirroredCoordinate(p[2], sum[2]);
  if (!mirrored || stream_->exceptions.empty()) return nullptr;
  const std::uint64_t index =
      static_cast<std::uint64_t>(p[0]) +
      static_cast<std::uint64_t>(h.dims[0]) *
          (static_cast<std::uint64_t>(p[1]) + static_cast<std::uint64_t>(h.dims[1]) * static_cast<std::uint64_t>(p[2]));
  const auto& e = stream_->exceptions;
  const auto it = std::lower_bound(e.begin(), e.end(), index,
                                   [](const LebMirrorException& x, std::uint64_t i) { return x.index < i; });
  return it == e.end() || it->index != index ? nullptr : &*it;
}

GridPoint MirroredLebReader::foldedPoint(const GridPoint& p) const {
  const std::int64_t* sum = stream_->header.planes.sum.data();
  return {lebFoldedCoordinate(p[0], sum[0]), lebFoldedCoordinate(p[1], sum[1]), lebFoldedCoordinate(p[2], sum[2])};
}

std::uint16_t MirroredLebReader::sample(const GridPoint& p) {
  const LebMirrorException* e = exceptionAt(p);
  const std::uint32_t v = folded_.sample(foldedPoint(p));
  return static_cast<std::uint16_t>(e ? lebMirrorSample(v, e->residual, stream_->header.sampleBits) : v);
}

std::array<std::int8_t, 3> MirroredLebReader::gradient(const GridPoint& p) {
  const LebMirrorHeader& h = stream_->header;
  if (!h.hasGradients())
    throw std::invalid_argument("MirroredLebReader: the stream has no gradients (encoded without them)");
  std::array<std::int8_t, 3> g{};
  if (h.storedGradients()) {  // the image's, mirrored (mirror_fold.h), and the exception's residuals
    const LebMirrorException* e = exceptionAt(p);
    const std::array<std::int8_t, 3> image = folded_.gradient(foldedPoint(p));
    for (int a = 0; a < 3; ++a)
      g[a] = lebMirrorComponent(image[a], lebMirroredCoordinate(p[a], h.planes.sum[a]), e ? e->gradient[a] : 0);
    return g;
  }
  quantizeGradient(centralGradientAt(
                       [&](int x, int y, int z) {
                         return sample(GridPoint{x, y, z});
                       },
                       h.dims, p[0], p[1], p[2]),
                   g.data());
  return g;
}

}  // namespace voxref::ref
