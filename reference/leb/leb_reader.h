// Random access into an LEB stream: any point or any page, decompressing only the pages needed
// (Gregorski et al. 2004, section 3.1, the four steps of reconstructing P(i,j,k)).
//
// value(p) finds p's page by its hierarchical index, takes the page's deltas from the cache
// (decoding the page on a miss; a query for both channels that misses both pages decodes the two
// together, decodeChannelPagesPositions in leb_page.h), and adds them to the prediction from p's split edge, whose
// endpoint values are reconstructed the same way (recursively: the "reconstruction mask"; every
// endpoint is coarser, so the recursion ends at the root corners within 3k + 1 levels).
// Reconstructed values are memoised per grid point (the channels a query asked for: one entry
// holds a point's sample and its gradient, and a query for both walks the hierarchy once) in a
// direct-mapped table kept between queries: slot = the point's index in bricks of 4^3 points,
// modulo the table's size, so a point's split-edge endpoints and its grid neighbours share cache
// lines (a hashed table scatters them: the lookups of a hashed memo were most of the first mesh's
// cost over the uncompressed grid). A newer point replaces an older one in its slot, except one
// reconstructed in the same query: that one stays, and the newer goes to a small table of the
// query's own (emptied when the next query begins), so a point is still reconstructed at most
// once per query, whatever the table's size. Neighbouring queries share their coarse ancestors,
// so a query in a region already visited reconstructs little more than its own point.
// A stream of the context coder (FORMAT.md, "Context pages", "Context gradient pages") holds a
// page's samples and gradients rather than their deltas: a point inside the volume is read from its page, and decoding
// a page reads its points' corners outside it through the same memo and cache (they are coarser, so this recursion too
// ends within the grid's levels); a point of the padding takes its split edge's prediction, as in every stream.
// Bit-identical to decodeLeb. A stream that derives its gradients (FORMAT.md, header byte 23)
// gives a point's gradient from its six neighbours' samples, reconstructed (and memoised) the same
// way: seven samples instead of one gradient.
//
// Memory: the page cache's budget, plus the page being decoded (2^pageBits x components x 2 bytes,
// at most 6 MiB: pageBits <= 20 is checked by parseLebStream; a context gradient page also its
// recent vectors, 8 bytes a point and a hash entry a distinct vector), plus the memo: kMemoSlotBytes a
// slot, the power of two of slots at most cacheBudgetBytes / kMemoSlotBytes (at least
// kMinMemoSlots, and no more than the grid's bricks need), plus the query's own table (the
// points of one query that met a slot taken in the same query: at most its points and their
// coarser split-edge ancestors, and with derived gradients their six neighbours and theirs), plus reconstructPage's
// result, 2^pageBits x components x 4 bytes (at most 12 MiB). Nothing is allocated in proportion to the whole grid.
// Errors: StreamError for a corrupt page (when it is decoded), std::invalid_argument for a point outside the grid or a
// channel the stream lacks, and from the constructor for a grid past kMaxIndexedLebK (its memo keys are 32-bit linear
// indices). Not thread-safe: use one reader per thread (they can share the stream).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "reference/common/flat_u64_map.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_stream.h"
#include "reference/leb/page_cache.h"

namespace voxref::ref {

class LebReader {
 public:
  LebReader(std::shared_ptr<const LebStream> stream, std::size_t cacheBudgetBytes);

  const LebStream& stream() const { return *stream_; }
  // The data sample at p (a grid point; points of the padding give their predicted value).
  std::uint16_t sample(const GridPoint& p);
  // The quantized gradient at p.
  std::array<std::int8_t, 3> gradient(const GridPoint& p);
  // Both at once, as sample(p) and gradient(p) give them, in one walk of p's ancestors (what an
  // isosurface extraction asks for at every corner).
  struct SampleAndGradient {
    std::uint16_t sample = 0;
    std::array<std::int8_t, 3> gradient{};
  };
  SampleAndGradient sampleAndGradient(const GridPoint& p);
  // Every value of one page: 2^pageBits x components entries in hierarchical order (entries past
  // the grid's last point are 0).
  std::vector<std::int32_t> reconstructPage(LebChannelKind kind, std::uint64_t page);

  const PageCache::Stats& cacheStats() const { return cache_.stats(); }
  std::uint64_t pointsReconstructed() const { return reconstructed_; }

  // A point's memo entry: the sample (slot 0) and the gradient (slots 1-3), and which of the two
  // channels are known (bit 0 data, bit 1 gradients).
  struct Known {
    std::array<std::int32_t, 4> v{};
    unsigned channels = 0;
  };
  // A slot of the memo's direct-mapped table.
  static constexpr std::size_t kMemoSlotBytes = 16;
  static constexpr std::size_t kMinMemoSlots = 4096;

 private:
  // Starts a query: a new query number, and the previous query's own table emptied.
  void beginQuery();
  // The channels of `want` (and any the memo already knows) at p.
  Known valueAt(unsigned want, const GridPoint& p);
  const LebChannel& channel(LebChannelKind kind) const;
  void requireGradients() const;  // throws std::invalid_argument unless the stream has gradients
  // The gradient of p into have.v[1..3] for a stream that derives its gradients: from the
  // neighbours' samples (gradients.h, centralGradientAt) inside the volume, else the prediction.
  void deriveGradient(const GridPoint& p, bool inside, const std::array<std::int32_t, 4>& pred, Known& have);
  static unsigned channelBit(LebChannelKind kind) { return kind == LebChannelKind::Data ? 1u : 2u; }
  // Whether the stream's pages hold values (the context coder) rather than deltas.
  bool contextPages() const { return stream_->coder == LebCoder::Context; }
  // A context stream's page of channel c: its samples, or its gradients' three int8, at their
  // places (DecodedPage::values, 2^pageBits x components values, 0 for the padding), its points'
  // corners outside the page reconstructed through valueAt.
  DecodedPage decodeContextPage(const LebChannel& c, std::uint64_t page);

  // A memo slot: the point's linear index (all ones: empty), the query that wrote it, the data
  // value and the gradient's components (a gradient is 8 bits: gradients.h), the known channels.
  struct MemoSlot {
    std::uint32_t key = ~std::uint32_t{0};
    std::uint32_t query = 0;
    std::int32_t data = 0;
    std::array<std::int8_t, 3> gradient{};
    std::uint8_t channels = 0;
  };
  static_assert(sizeof(MemoSlot) == kMemoSlotBytes);
  MemoSlot& memoSlot(const GridPoint& p);

  std::shared_ptr<const LebStream> stream_;
  HzOrder order_;
  PageCache cache_;
  std::vector<MemoSlot> memo_;
  std::uint64_t memoMask_ = 0, bricksPerAxis_ = 0;
  std::uint32_t query_ = 0;
  FlatU64Map<Known> queryOwn_;  // this query's points whose slot another of its points holds
  std::uint64_t reconstructed_ = 0;
};

}  // namespace voxref::ref
