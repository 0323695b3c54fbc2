// Time-varying volumes in an index and a refinement 3D texture (Binotto, Comba, Freitas 2003,
// section 5): the encoder and the exact decoder.
//
// Input: T time steps of a d^3 uint8 volume (d a power of two, 4..512; other sizes are padded
// explicitly with padToCube) and a transfer function. At subdivision level s each time step is
// cut into n = 2^s coarse cells per axis of r = d / 2^s voxels per axis (the paper's d_i and d_r,
// section 5.2). A homogeneous cell (all voxels the same scalar) stores its transfer-function
// colour in the index texture; any other cell stores, with alpha at its maximum (the paper's
// "alpha = 1" flag), the address of an r^3 block of colours in the refinement texture. Blocks are
// shared across cells and time steps: a hash of the block's scalars finds candidates and every
// hit is confirmed by comparing all voxels (section 5.1.2), so collisions never lose data.
//
// Layout (voxref's, documented in docs/timevarying.md; the paper's eq. 1 does not address many
// time steps consistently, see paperIndexOrigin): the index texture holds S^3 slots of n^3 texels,
// S the smallest power of two with S^3 >= T, slot of step t at (t mod S, (t / S) mod S, t / S^2);
// the refinement texture holds B^3 slots of r^3 texels, B the smallest power of two with
// B^3 >= blocks, block k at (k mod B, (k / B) mod B, k / B^2). Power-of-two slot counts make every
// normalized slot origin dyadic, so the only inexact address is the one the paper's unorm8 origins
// introduce (k / B stored as round(255 k / B) / 255).
//
// Index encodings (how a refinement address is stored):
//   normalized_rgba8   the paper: RGB = k / B per axis as unorm8, A = 255
//   normalized_rgba16  the same in unorm16 (A = 65535); colours stored as 257 * code8
//   normalized_float   the same as exact binary32 values (A = 1.0); colours as code8 / 255
//   block_rgba8        RGB = the integer block coordinates k (B <= 256), A = 255: for decoders that
//                      compute integer or texel-centre addresses
// The exact decoder uses integer addressing and reproduces the input after the transfer function
// bit for bit (unless the paper's alpha-one policy lets a homogeneous colour with alpha 255 be
// read as a flag: the flag collision of section 5.1; the corrected policy refines such cells).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "reference/common/volume.h"
#include "reference/timevarying/transfer_function.h"

namespace voxref::ref {

enum class IndexEncoding { NormalizedRgba8, NormalizedRgba16, NormalizedFloat, BlockRgba8 };
std::string_view name(IndexEncoding e);
std::optional<IndexEncoding> parseIndexEncoding(std::string_view s);

enum class AlphaOnePolicy {
  Paper,   // a homogeneous colour with alpha 255 is stored as it is: it reads as a refinement flag
  Refine,  // such a cell is stored as a (uniform) refinement block: lossless
};

// The input: `steps` time steps of side^3 voxels (x fastest), with the original extents.
struct TimeSeries {
  int side = 0;
  Dims3 original{0, 0, 0};
  std::vector<std::vector<std::uint8_t>> steps;
};

// Pads volumes of equal extents (each at most 512) into the smallest power-of-two cube (at least
// 4), filling with `padValue`. Throws std::invalid_argument for differing or oversized extents.
TimeSeries padToCube(const std::vector<Volume<std::uint8_t>>& volumes, std::uint8_t padValue = 0);

struct TimeVaryingOptions {
  int level = 4;  // s: 2^s coarse cells per axis, 1 <= s <= log2(side) - 1
  IndexEncoding encoding = IndexEncoding::NormalizedRgba8;
  AlphaOnePolicy alphaOne = AlphaOnePolicy::Refine;
  int hashBits = 64;            // truncate the block hash (tests force collisions with few bits)
  int maxTextureExtent = 2048;  // GL 4.5's guaranteed GL_MAX_3D_TEXTURE_SIZE
  // The paper's layout (section 5.2): both textures are side^3, so S = r index slots and B = n
  // block slots per axis; the appendix shader assumes it. CapacityError when T > r^3 or the blocks
  // exceed n^3.
  bool paperLayout = false;
};

struct TimeVaryingLayout {
  int side = 0, timeSteps = 0, level = 0;
  int cells = 0;       // n = 2^s coarse cells per axis
  int blockSide = 0;   // r = side / n voxels per axis of a block
  int indexSlots = 0;  // S per axis
  int blockSlots = 0;  // B per axis
  Dims3 original{0, 0, 0};
};

struct IndexTexture {
  IndexEncoding encoding = IndexEncoding::NormalizedRgba8;
  Dims3 dims{0, 0, 0};
  std::vector<std::uint32_t> texels;  // 4 channels per texel: unorm codes, or binary32 bits
};

struct RefinementTexture {
  Dims3 dims{0, 0, 0};
  std::vector<std::uint8_t> texels;  // RGBA8
};

struct EncodeStats {
  std::size_t homogeneousCells = 0, refinedCells = 0;
  std::size_t distinctBlocks = 0;
  std::size_t hashHits = 0;         // hash hits confirmed equal by the full comparison (shared blocks)
  std::size_t hashCollisions = 0;   // hash hits whose blocks differed
  std::size_t alphaOneCells = 0;    // homogeneous cells whose colour has alpha 255
  std::size_t indexBytes = 0;       // T n^3 texels (the paper counts only the used slots)
  std::size_t refinementBytes = 0;  // blocks * r^3 * 4
  std::size_t indexBytesAllocated = 0, refinementBytesAllocated = 0;
  std::size_t inputVoxels = 0;  // T X Y Z of the original extents: ratios exclude the padding
  double ratioAgainst4Bytes() const {
    return 4.0 * static_cast<double>(inputVoxels) / static_cast<double>(indexBytes + refinementBytes);
  }
  double ratioAgainst1Byte() const {
    return static_cast<double>(inputVoxels) / static_cast<double>(indexBytes + refinementBytes);
  }
};

struct TimeVaryingTextures {
  TimeVaryingLayout layout;
  AlphaOnePolicy alphaOne = AlphaOnePolicy::Refine;  // how the encoder stored alpha-one colours
  IndexTexture index;
  RefinementTexture refinement;
  EncodeStats stats;
};

// Thrown when a texture would exceed maxTextureExtent (or block_rgba8's 256 slots per axis): a
// clear error instead of a corrupt texture. The message names the texture and both sizes.
class CapacityError : public std::length_error {
 public:
  using std::length_error::length_error;
};

// Throws std::invalid_argument for a level outside 1..log2(side)-1 or an empty series, and
// CapacityError as above.
TimeVaryingTextures encodeTimeVarying(const TimeSeries& series, const TransferFunction& tf,
                                      const TimeVaryingOptions& options);

// `--level auto`: encodes at every level and returns the one with the fewest allocated texture
// bytes (index + refinement textures as stored, unused slots included), which is the smallest
// .vxtv file (its other sections do not depend on the level); ties go to the lower level. Levels
// that exceed a capacity are skipped.
TimeVaryingTextures encodeTimeVaryingAutoLevel(const TimeSeries& series, const TransferFunction& tf,
                                               TimeVaryingOptions options);

// Slot positions (in slots) of time step t and of block k.
std::array<int, 3> indexSlot(const TimeVaryingLayout& layout, int t);
std::array<int, 3> blockSlot(const TimeVaryingLayout& layout, int k);

// Equation (1) of the paper, literally: origin = ((t mod d_i) d_r, (t div d_i) d_r, (t mod d_i^2) d_r).
// Kept to show in tests that it sends different time steps to the same or to out-of-range slots.
std::array<int, 3> paperIndexOrigin(int t, int di, int dr);

// True when the index texel at `texel` (4 channels) carries the refinement flag (alpha at maximum).
bool isRefinementFlag(IndexEncoding encoding, const std::uint32_t* texel);
// The block slot coordinates an index texel addresses (integer rounding of the stored origin).
std::array<int, 3> blockOfIndexTexel(const TimeVaryingLayout& layout, IndexEncoding encoding,
                                     const std::uint32_t* texel);
// The RGBA8 colour an index texel stores for a homogeneous cell.
Rgba8 colourOfIndexTexel(IndexEncoding encoding, const std::uint32_t* texel);

// Where the exact decoder reads voxel (x, y, z) of step t: the index texel, and the refinement
// texel when the cell is refined. Integer addressing. Throws std::out_of_range for coordinates or
// an address outside the textures.
struct VoxelAddress {
  std::array<int, 3> indexTexel{};
  bool refined = false;
  std::array<int, 3> refinementTexel{};
};
VoxelAddress addressOfVoxel(const TimeVaryingTextures& textures, int t, int x, int y, int z);

// Exact decoder, integer addressing: the colour of voxel (x, y, z) of step t (coordinates in the
// padded cube). Under the refine policy this is the input after the transfer function. Under the
// paper's policy a flagged texel that stores a colour is read as an address, as the paper's
// decoder reads it (the flag collision of section 5.1): where that address lies past the
// refinement texture, the last texel on that axis is read (CLAMP_TO_EDGE, the wrap of every
// decoder; GL 4.6 section 8.14.2), and a block slot that holds no block reads as stored (zero).
// So every file the encoder writes decodes (reference/timevarying/FORMAT.md).
// Throws std::out_of_range for coordinates outside the series, or for an address outside the
// textures under the refine policy (a corrupt texture).
Rgba8 decodeVoxel(const TimeVaryingTextures& textures, int t, int x, int y, int z);
// A whole step in its original extents, RGBA8 per voxel, x fastest.
std::vector<Rgba8> decodeStep(const TimeVaryingTextures& textures, int t);

}  // namespace voxref::ref
