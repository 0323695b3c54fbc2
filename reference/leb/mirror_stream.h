// Mirrored LEB streams (`VXLM`; FORMAT.md beside this file, "Mirrored streams"): a volume that is
// its own mirror image on some axes (mirror_fold.h) stored as the LEB stream of its folded volume,
// behind a header naming the planes and the exceptions (the mirrored points that differ from
// their image). The fold is a property of the volume, not of a coder: the folded stream is any
// version 2, 3 or 4 stream of the data channel alone, read by parseLebStream as any other. The
// gradients are none, or derived from the unfolded samples (a stored gradient is not mirrored: its
// component across the plane changes sign).
//
// parseMirroredLebStream is safe on untrusted bytes: it checks the header (its CRC-32, every
// field), the exceptions (their CRC-32, then each: inside the volume, ascending, at a mirrored
// point, a canonical non-zero residual, the count within one in kLebMirrorExceptionShare mirrored
// points, the bytes exactly those the count takes) and the folded stream (parseLebStream, its
// extents the folded extents) before it keeps anything. Errors are StreamError naming the offset
// in the whole stream, the folded stream's too.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_stream.h"
#include "reference/leb/mirror_fold.h"

namespace voxref::ref {

inline constexpr std::size_t kLebMirrorHeaderBytes = 76;
inline constexpr int kLebMirrorVersion = 1;

// What the header says of the volume.
struct LebMirrorHeader {
  Dims3 dims{0, 0, 0};  // the volume's extents (unfolded)
  int sampleBits = 8;
  LebMirrorPlanes planes;
  bool derivedGradients = false;  // header byte 7: the gradients are quantizedGradients of the unfolded samples
};

struct MirroredLebStream {
  LebMirrorHeader header;
  std::vector<LebMirrorException> exceptions;  // ascending
  LebStream inner;                             // the folded volume's stream (data channel alone)
  std::size_t innerOffset = 0;                 // where it starts in the whole stream
  std::uint64_t streamBytes = 0;               // the whole stream's length
  std::uint64_t exceptionBytes = 0;            // the coded exceptions' length
};

// Whether `bytes` begins as a mirrored stream does (its magic).
bool isMirroredLebStream(std::string_view bytes);

// The whole stream of the folded volume `folded` (lebFoldedDims of header.dims, made by
// foldLebVolume with its exceptions): the header and the exceptions, then encodeLebTo of the
// folded volume, through `write` as encodeLebTo hands its bytes (each byte once, the header last).
// Returns the stream's size. options.gradients with options.deriveGradients sets header byte 7;
// the folded stream is always the data alone. Throws std::invalid_argument for gradients asked to
// be stored, no plane, a plane not valid for the extents, extents or exceptions that do not match,
// and as encodeLebTo.
std::uint64_t encodeMirroredLebTo(const LebVolumeIn& folded, const LebMirrorHeader& header,
                                  const std::vector<LebMirrorException>& exceptions, const LebEncodeOptions& options,
                                  const LebStreamWrite& write);
// The same in memory, folding the volume first.
std::string encodeMirroredLeb(const Volume<std::uint16_t>& volume, int sampleBits, const LebMirrorPlanes& planes,
                              const LebEncodeOptions& options);

// Throws StreamError. Takes the bytes by value: the stream keeps them.
MirroredLebStream parseMirroredLebStream(std::string bytes);
// The same over bytes that `owner` keeps alive (a file mapping): nothing is copied.
MirroredLebStream parseMirroredLebStream(std::string_view bytes, std::shared_ptr<const void> owner);

// Decodes into `out` (out.dims the volume's extents, its samples array as decodeLebInto's; its
// gradients set only when the stream derives them and they are wanted): the folded volume into the
// start of the samples array, then unfolded in place (unfoldLebVolume), then the gradients.
// `window` is called between batches as decodeLebInto calls it. Throws StreamError (offsets in the
// whole stream) for a corrupt folded stream, std::invalid_argument for an `out` that does not fit.
// Memory beside `out`: what decodeLebInto takes for the folded stream.
void decodeMirroredLebInto(const MirroredLebStream& stream, const LebVolumeOut& out, int threads = 0,
                           const LebWindow& window = {});
// decodeMirroredLebInto into a volume of its own (and the gradients, when the stream derives them).
LebDecoded decodeMirroredLeb(const MirroredLebStream& stream, int threads = 0);
// What decodeMirroredLeb allocates: the volume at 2 bytes a sample, its gradients (3 bytes a
// sample) when derived, and the folded stream's shells of padding.
std::uint64_t mirroredLebDecodeMemoryBytes(const MirroredLebStream& stream);

}  // namespace voxref::ref
