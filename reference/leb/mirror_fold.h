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
// differ from their image (at most one in kLebMirrorExceptionShare mirrored points). Gradients, when
// folded with the samples (3 int8 a point), mirror with a sign: a mirrored point's gradient is its
// image's with the component of each axis on which the point is mirrored negated (modulo 256), and
// a point whose gradient differs from that is an exception too (at most one in
// kLebMirrorGradientExceptionShare mirrored points then).
//
// Exactness: unfoldLebVolume(foldLebVolume(v)) == v bit for bit, gradients too, for any planes (the
// exceptions carry what the mirror does not); the search only decides what is worth folding.
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
// The same when the gradients are folded too: a point is an exception when its sample or its
// gradient differs, and central differences differ more often than the samples (at the volume's
// faces a one-sided difference faces a central one).
inline constexpr std::uint64_t kLebMirrorGradientExceptionShare = 16;

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
// The most exceptions a fold may have: floor(M / share), M the mirrored points, the share
// kLebMirrorGradientExceptionShare when the gradients are folded, else kLebMirrorExceptionShare.
std::uint64_t lebMirrorExceptionCap(const Dims3& dims, const LebMirrorPlanes& planes, bool gradients);
// Where c's image lies in the folded axis (c kept: its own place; mirrored: its image's).
int lebFoldedCoordinate(int c, std::int64_t s);
Dims3 lebFoldedDims(const Dims3& dims, const LebMirrorPlanes& planes);
// Points of the volume that are mirrored (the volume's points less the folded volume's).
std::uint64_t lebMirroredPoints(const Dims3& dims, const LebMirrorPlanes& planes);
// "x: c <-> 124 - c; z: c <-> 126 - c" (the mirrored axes), or "none".
std::string lebMirrorPlanesText(const LebMirrorPlanes& planes);
// Throws std::invalid_argument naming the axis for a sum that is not valid for its extent.
void requireLebMirrorPlanes(const Dims3& dims, const LebMirrorPlanes& planes);

// A mirrored point that differs from its image: its index in the volume (x fastest), (sample -
// image's sample) mod 2^sampleBits, and with folded gradients each component's (gradient - the
// image's as mirrored) mod 256 (lebMirrorComponentResidual; all 0 when no gradients are folded).
// Not all of them are 0.
struct LebMirrorException {
  std::uint64_t index = 0;
  std::uint32_t residual = 0;
  std::array<std::uint8_t, 3> gradient{};
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
// The same for a gradient component of a mirrored point: `flipped` when the point is mirrored on the
// component's axis, so that its image's component is negated (modulo 256: -(-128) is -128).
inline std::int8_t lebMirrorComponent(std::int8_t image, bool flipped, std::uint8_t residual) {
  const auto u = static_cast<std::uint8_t>(image);
  return static_cast<std::int8_t>(static_cast<std::uint8_t>((flipped ? 256 - u : u) + residual));
}
inline std::uint8_t lebMirrorComponentResidual(std::int8_t component, std::int8_t image, bool flipped) {
  const auto u = static_cast<std::uint8_t>(image);
  return static_cast<std::uint8_t>(static_cast<std::uint8_t>(component) - (flipped ? 256 - u : u));
}

// The planes worth folding: on each axis of extent at least 4, the sum whose paired slices' sample
// sums differ least (relatively) among those mirroring a quarter of the axis or more, kept when at
// most one mirrored point in 4 x kLebMirrorExceptionShare differs from its image in its sample and,
// with `gradients` (3 int8 a point; may be null), at most one in 2 x
// kLebMirrorGradientExceptionShare in its sample or its gradient; then, while the planes together
// exceed those shares, the axis with the most differing points is dropped. Deterministic (ties go
// to the sum that mirrors more, then the smaller). Costs a pass over the volume, and one more per
// candidate axis and per drop. A volume with no such plane gives no planes.
LebMirrorPlanes findLebMirrorPlanes(const std::uint8_t* samples, const std::int8_t* gradients, const Dims3& dims);
LebMirrorPlanes findLebMirrorPlanes(const std::uint16_t* samples, const std::int8_t* gradients, const Dims3& dims);

// Writes the kept samples into `folded` (lebFoldedDims, x fastest), and with `gradients` (3 int8 a
// point; null for none) their gradients into `foldedGradients`, and returns the exceptions,
// ascending. Throws std::invalid_argument as requireLebMirrorPlanes, and when there are more
// exceptions than lebMirrorExceptionCap allows (naming the count and the cap; it keeps no more than
// the cap while it counts them).
std::vector<LebMirrorException> foldLebVolume(const std::uint8_t* samples, const std::int8_t* gradients,
                                              const Dims3& dims, const LebMirrorPlanes& planes, std::uint8_t* folded,
                                              std::int8_t* foldedGradients);
std::vector<LebMirrorException> foldLebVolume(const std::uint16_t* samples, const std::int8_t* gradients,
                                              const Dims3& dims, const LebMirrorPlanes& planes, int sampleBits,
                                              std::uint16_t* folded, std::int8_t* foldedGradients);

// In place: `samples` holds the folded volume at its start (lebFoldedDims, x fastest) and gets the
// volume (dims), each mirrored point its image's sample plus its exception (mod 2^sampleBits); the
// same for `gradients` when given (3 int8 a point; a mirrored point takes its image's, mirrored:
// lebMirrorComponent). The folded volume is never larger, and a point's folded place never lies
// after its own, so a walk from the last point back overwrites nothing it still reads. `window`, if
// set, is called between slices (its fraction rising to 1). The exceptions must be ascending, each
// at a mirrored point (mirror_stream.cpp checks them when it reads them).
void unfoldLebVolume(std::uint8_t* samples, std::int8_t* gradients, const Dims3& dims, const LebMirrorPlanes& planes,
                     const std::vector<LebMirrorException>& exceptions, const LebWindow& window = {});
void unfoldLebVolume(std::uint16_t* samples, std::int8_t* gradients, const Dims3& dims, const LebMirrorPlanes& planes,
                     int sampleBits, const std::vector<LebMirrorException>& exceptions, const LebWindow& window = {});

}  // namespace voxref::ref
