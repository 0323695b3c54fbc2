// Random access into a mirrored LEB stream (mirror_stream.h; FORMAT.md beside this file, "Mirrored
// streams"): a point of the volume reads its image from the folded stream, through a LebReader and
// its page cache, and adds its exception if it has one (a binary search of the stream's
// exceptions). One page chain a point, as in the folded stream: the mirror costs a table lookup.
//
// Bit-identical to decodeMirroredLeb. Only points inside the volume are answered: the folded
// stream's padding belongs to its own grid, not to the volume's. A stored gradient reads its
// image's from the folded stream and mirrors it. Memory: the LebReader's (its cache
// budget and memo). Errors: std::invalid_argument for a point outside the volume, or a gradient of a
// stream that has none; StreamError (offsets in the folded stream) for a corrupt page. Not
// thread-safe: one reader per thread (they can share the stream).
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "reference/leb/leb_reader.h"
#include "reference/leb/mirror_stream.h"

namespace voxref::ref {

class MirroredLebReader {
 public:
  MirroredLebReader(std::shared_ptr<const MirroredLebStream> stream, std::size_t cacheBudgetBytes);

  const MirroredLebStream& stream() const { return *stream_; }
  // The sample at p, a point of the volume.
  std::uint16_t sample(const GridPoint& p);
  // The gradient at p: a stored one is its image's, mirrored, plus its exception's residuals; a
  // derived one quantizedGradients' central differences (gradients.h) of the samples this reader
  // gives.
  std::array<std::int8_t, 3> gradient(const GridPoint& p);
  // The reader of the folded stream (its cache's statistics).
  const LebReader& folded() const { return folded_; }

 private:
  // p's exception (a binary search of the stream's), or null; throws for a point outside the volume.
  const LebMirrorException* exceptionAt(const GridPoint& p) const;
  // Where p's image lies in the folded stream.
  GridPoint foldedPoint(const GridPoint& p) const;

  std::shared_ptr<const MirroredLebStream> stream_;
  LebReader folded_;
};

}  // namespace voxref::ref
