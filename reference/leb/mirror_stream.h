// Mirrored LEB streams (`VXLM`; FORMAT.md beside this file, "Mirrored streams"): a volume that is
// its own mirror image on some axes (mirror_fold.h) stored as the LEB stream of its folded volume,
// behind a header naming the planes and the exceptions (the mirrored points that differ from
// their image). The fold is a property of the volume, not of a coder: the folded stream is any
// version 2, 3 or 4 stream, read by parseLebStream as any other. The gradients are none, derived
// from the unfolded samples, or stored: folded with the samples (the folded stream's gradients
// channel), a mirrored point's gradient its image's with the component across each of its planes
// negated (mirror_fold.h), and the points off that among the exceptions.
//
// parseMirroredLebStream is safe on untrusted bytes: it checks the header (its CRC-32, every
// field), the exceptions (their CRC-32, then each: inside the volume, ascending, at a mirrored
// point, canonical residuals not all 0, the count within lebMirrorExceptionCap, the bytes exactly
// those the count takes) and the folded stream (parseLebStream, its
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

// Header byte 7: the volume's gradients.
enum class LebMirrorGradients : std::uint8_t {
  None = 0,
  Derived = 1,  // quantizedGradients of the unfolded samples, computed when decoded
  Stored = 2,   // the folded stream's gradients channel, unfolded with the samples
};

// What the header says of the volume.
struct LebMirrorHeader {
  Dims3 dims{0, 0, 0};  // the volume's extents (unfolded)
  int sampleBits = 8;
  LebMirrorPlanes planes;
  LebMirrorGradients gradients = LebMirrorGradients::None;
  bool hasGradients() const { return gradients != LebMirrorGradients::None; }
  bool storedGradients() const { return gradients == LebMirrorGradients::Stored; }
};

struct MirroredLebStream {
  LebMirrorHeader header;
  std::vector<LebMirrorException> exceptions;  // ascending
  LebStream inner;                             // the folded volume's stream (with the gradients when stored)
  std::size_t innerOffset = 0;                 // where it starts in the whole stream
  std::uint64_t streamBytes = 0;               // the whole stream's length
  std::uint64_t exceptionBytes = 0;            // the coded exceptions' length
};

// Whether `bytes` begins as a mirrored stream does (its magic).
bool isMirroredLebStream(std::string_view bytes);

// The whole stream of the folded volume `folded` (lebFoldedDims of header.dims, made by
// foldLebVolume with its exceptions, and its gradients folded too when they are stored): the header
// and the exceptions, then encodeLebTo of the folded volume, through `write` as encodeLebTo hands
// its bytes (each byte once, the header last). Returns the stream's size. The options set header
// byte 7 (header.gradients is not read): no gradients, derived, or stored (folded.gradients then
// holds them). Throws std::invalid_argument for no plane, a plane not valid for the extents,
// extents or exceptions that do not match, and as encodeLebTo.
std::uint64_t encodeMirroredLebTo(const LebVolumeIn& folded, const LebMirrorHeader& header,
                                  const std::vector<LebMirrorException>& exceptions, const LebEncodeOptions& options,
                                  const LebStreamWrite& write);
// The same in memory, folding the volume first, and `gradients` (3 int8 a sample) when the options
// store them (quantizedGradients of the volume when empty).
std::string encodeMirroredLeb(const Volume<std::uint16_t>& volume, int sampleBits, const LebMirrorPlanes& planes,
                              const LebEncodeOptions& options, const std::vector<std::int8_t>& gradients = {});

// Throws StreamError. Takes the bytes by value: the stream keeps them.
MirroredLebStream parseMirroredLebStream(std::string bytes);
// The same over bytes that `owner` keeps alive (a file mapping): nothing is copied.
MirroredLebStream parseMirroredLebStream(std::string_view bytes, std::shared_ptr<const void> owner);

// Decodes into `out` (out.dims the volume's extents, its samples array as decodeLebInto's; its
// gradients set when the stream stores them, and when it derives them and they are wanted, as
// decodeLebInto's): the folded volume into the
// start of the samples array (and of the gradients', when stored), then unfolded in place
// (unfoldLebVolume), or then the gradients derived.
// `window` is called between batches as decodeLebInto calls it. Throws StreamError (offsets in the
// whole stream) for a corrupt folded stream, std::invalid_argument for an `out` that does not fit.
// Memory beside `out`: what decodeLebInto takes for the folded stream.
void decodeMirroredLebInto(const MirroredLebStream& stream, const LebVolumeOut& out, int threads = 0,
                           const LebWindow& window = {});
// decodeMirroredLebInto into a volume of its own (and the gradients, when the stream has them).
LebDecoded decodeMirroredLeb(const MirroredLebStream& stream, int threads = 0);
// What decodeMirroredLeb allocates: the volume at 2 bytes a sample, its gradients (3 bytes a
// sample) when it has them, and the folded stream's shells of padding.
std::uint64_t mirroredLebDecodeMemoryBytes(const MirroredLebStream& stream);

}  // namespace voxref::ref
