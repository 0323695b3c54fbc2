// Mirror planes of a volume and the fold that stores one side of each (FORMAT.md beside this file,
// "Mirrored streams"): the geometry, the search for planes, and the fold and unfold of the samples.
//
// A mirror on axis a with sum s pairs the coordinates c and s - c. A coordinate c is *mirrored*
// when s/2 < c <= s (its image s - c lies below it, inside the volume); every other coordinate is
// *kept*. A point is mirrored when any of its coordinates is; its image takes the image of each
// mirrored coordinate, and is kept. The *folded volume* holds the kept points alone, in the order
// of the volume (x fastest): on a mirrored axis of extent n the kept coordinates [0, floor(s/2)]
// and [s + 1, n - 1] follow one another, floor(s/2) + 1 + max(0, n - 1 - s) of them. A mirrored
// point's sample is its image's plus an *exception*, a residual stored for the few points that
// differ from their image (at most one in kLebMirrorExceptionShare mirrored points).
//
// Exactness: unfoldLebVolume(foldLebVolume(v)) == v bit for bit, for any planes (the exceptions
// carry what the mirror does not); the search only decides what is worth folding.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "reference/common/volume.h"
#include "reference/leb/leb_codec.h"

namespace voxref::ref {

inline constexpr std::int64_t kNoLebMirror = -1;
// A volume's folds: per axis the sum s of its mirror (1 <= s <= 2n - 3 for extent n, so that one
// coordinate at least is mirrored), or kNoLebMirror.
struct LebMirrorPlanes {
  std::array<std::int64_t, 3> sum{kNoLebMirror, kNoLebMirror, kNoLebMirror};
  bool any() const { return sum[0] != kNoLebMirror || sum[1] != kNoLebMirror || sum[2] != kNoLebMirror; }
  bool operator==(const LebMirrorPlanes&) const = default;
};
// At most one exception in this many mirrored points (a format invariant: it bounds what a decoder
// holds, FORMAT.md "Mirrored streams"). The search folds only planes well within it.
inline constexpr std::uint64_t kLebMirrorExceptionShare = 256;

// Whether sum s is a mirror of an axis of extent n (some coordinate is mirrored).
inline bool lebMirrorSumValid(std::int64_t s, int n) { return s >= 1 && s <= 2 * std::int64_t{n} - 3; }
// Whether coordinate c is mirrored by sum s (kNoLebMirror mirrors none).
inline bool lebMirroredCoordinate(int c, std::int64_t s) {
  return s != kNoLebMirror && 2 * std::int64_t{c} > s && c <= s;
}
// The image of c: s - c for a mirrored coordinate, c otherwise.
inline int lebMirrorImage(int c, std::int64_t s) { return lebMirroredCoordinate(c, s) ? static_cast<int>(s - c) : c; }
// The folded extent of an axis of extent n.
int lebFoldedExtent(int n, std::int64_t s);
// Where c's image lies in the folded axis (c kept: its own place; mirrored: its image's).
int lebFoldedCoordinate(int c, std::int64_t s);
Dims3 lebFoldedDims(const Dims3& dims, const LebMirrorPlanes& planes);
// Points of the volume that are mirrored (the volume's points less the folded volume's).
std::uint64_t lebMirroredPoints(const Dims3& dims, const LebMirrorPlanes& planes);
// "x: c <-> 124 - c; z: c <-> 126 - c" (the mirrored axes), or "none".
std::string lebMirrorPlanesText(const LebMirrorPlanes& planes);
// Throws std::invalid_argument naming the axis for a sum that is not valid for its extent.
void requireLebMirrorPlanes(const Dims3& dims, const LebMirrorPlanes& planes);

// A mirrored point whose sample differs from its image's: its index in the volume (x fastest) and
// (sample - image's sample) mod 2^sampleBits, never 0.
struct LebMirrorException {
  std::uint64_t index = 0;
  std::uint32_t residual = 0;
  bool operator==(const LebMirrorException&) const = default;
};

// A mirrored point's sample from its image's and its residual, and the residual from both
// (modulo 2^sampleBits; the residual is 0 for a point that is not an exception).
inline std::uint32_t lebMirrorSample(std::uint32_t image, std::uint32_t residual, int sampleBits) {
  return (image + residual) & ((1u << sampleBits) - 1);
}
inline std::uint32_t lebMirrorResidual(std::uint32_t sample, std::uint32_t image, int sampleBits) {
  return (sample - image) & ((1u << sampleBits) - 1);
}

// The planes worth folding: on each axis of extent at least 4, the sum whose paired slices' sample
// sums differ least (relatively) among those mirroring a quarter of the axis or more, kept when at
// most one mirrored point in 4 x kLebMirrorExceptionShare differs from its image; then, while the
// planes together exceed that share, the axis with the most such points is dropped. Deterministic
// (ties go to the sum that mirrors more, then the smaller). Costs a pass over the volume, and one
// more per candidate axis and per drop. A volume with no such plane gives no planes.
LebMirrorPlanes findLebMirrorPlanes(const std::uint8_t* samples, const Dims3& dims);
LebMirrorPlanes findLebMirrorPlanes(const std::uint16_t* samples, const Dims3& dims);

// Writes the kept samples into `folded` (lebFoldedDims, x fastest) and returns the exceptions,
// ascending. Throws std::invalid_argument as requireLebMirrorPlanes, and when there are more
// exceptions than the share allows (naming the count and the cap).
std::vector<LebMirrorException> foldLebVolume(const std::uint8_t* samples, const Dims3& dims,
                                              const LebMirrorPlanes& planes, std::uint8_t* folded);
std::vector<LebMirrorException> foldLebVolume(const std::uint16_t* samples, const Dims3& dims,
                                              const LebMirrorPlanes& planes, int sampleBits, std::uint16_t* folded);

// In place: `samples` holds the folded volume at its start (lebFoldedDims, x fastest) and gets the
// volume (dims), each mirrored point its image's sample plus its exception (mod 2^sampleBits). The
// folded volume is never larger, and a point's folded place never lies after its own, so a walk
// from the last point back overwrites nothing it still reads. `window`, if set, is called between
// slices (its fraction rising to 1). The exceptions must be ascending, each at a mirrored point
// (mirror_stream.cpp checks them when it reads them).
void unfoldLebVolume(std::uint8_t* samples, const Dims3& dims, const LebMirrorPlanes& planes,
                     const std::vector<LebMirrorException>& exceptions, const LebWindow& window = {});
void unfoldLebVolume(std::uint16_t* samples, const Dims3& dims, const LebMirrorPlanes& planes, int sampleBits,
                     const std::vector<LebMirrorException>& exceptions, const LebWindow& window = {});

}  // namespace voxref::ref
