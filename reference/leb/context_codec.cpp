#include "reference/leb/context_codec.h"

#include <algorithm>
#include <string>
#include <vector>

#include "reference/common/crc32.h"
#include "reference/common/parallel.h"
#include "reference/leb/context_value_coder.h"
#include "reference/leb/leb_page.h"

namespace voxref::ref {
namespace {

// Pages a batch: what the encoder holds coded at once, and what a decoder's window lets through
// between two looks.
int batchPages(int threads) { return 4 * workerCount(threads); }

// The stored pages of a volume: those holding one of its points, ascending (one walk of its
// points: forEachInside skips the padding whole, so a 1025x1x1 volume costs its 1025 points).
std::vector<std::uint32_t> pagesWithPoints(const HzOrder& order, const Dims3& dims, int pageBits) {
  std::vector<std::uint32_t> pages;
  order.forEachInside(dims, 0, order.size(), [&](std::uint64_t h, const GridPoint&, int, int, unsigned) {
    const auto page = static_cast<std::uint32_t>(h >> pageBits);
    if (pages.empty() || pages.back() != page) pages.push_back(page);
  });
  return pages;
}

}  // namespace

std::uint64_t encodeContextChannel(const HzOrder& order, const LebVolumeIn& v, int pageBits, int threads,
                                   const LebProgress& progress, const LebStreamWrite& write, std::uint64_t offset) {
  LebChannelTable table{
      LebChannelKind::Data, 1, v.sampleBits, false, {}, pagesWithPoints(order, v.dims, pageBits), {}, {},
      LebCoder::Context};
  const std::uint64_t descriptorAt = offset;
  offset += lebDescriptorSize(v.sampleBits, table.storedPage.size(), LebCoder::Context);
  const int count = static_cast<int>(table.storedPage.size()), batch = batchPages(threads);
  std::vector<std::string> coded;
  for (int first = 0; first < count; first += batch) {
    const int end = std::min(count, first + batch);
    coded.assign(static_cast<std::size_t>(end - first), {});
    parallelFor(end - first, threads, [&](int i) {
      const std::uint64_t page = table.storedPage[static_cast<std::size_t>(first + i)];
      withLebSamples(v, [&](const auto* samples) {
        coded[static_cast<std::size_t>(i)] = encodeContextPage(
            order, v.dims, v.sampleBits, pageBits, page,
            [&](const GridPoint& q) { return static_cast<std::int32_t>(samples[volumeIndex(q, v.dims)]); });
      });
    });
    for (const std::string& bytes : coded) {
      write(offset, bytes);
      offset += bytes.size();
      table.pageLength.push_back(static_cast<std::uint32_t>(bytes.size()));
      table.pageCrc.push_back(crc32(bytes));
    }
    if (progress) progress(static_cast<double>(end) / static_cast<double>(count));
  }
  write(descriptorAt, lebDescriptorBytes(lebPageCount(order.grid(), pageBits), table));
  return offset;
}

// FORMAT.md, "Context pages": a point of scale h reads corners of scale 2h and more, which precede
// the first level of scale h (the levels of a scale are three consecutive ones).
std::uint64_t contextPagesNeededBelow(const HzOrder& order, int pageBits, std::uint64_t page) {
  const std::uint64_t last = std::min(order.size(), (page + 1) << pageBits) - 1;
  int level = -1;
  while (level + 1 < order.grid().levelCount() && order.levelBegin(level + 1) <= last) ++level;
  if (level < 0) return 0;
  const std::uint64_t coarser = order.levelBegin(level - level % 3);  // the indices its corners lie below
  return std::min(page, ((coarser - 1) >> pageBits) + 1);
}

void decodeContextChannel(const LebStream& s, const HzOrder& order, const LebVolumeOut& out, int threads,
                          const LebProgress& progress) {
  const LebChannel& c = s.channels.at(0);
  const int pb = s.pageBits;
  const std::vector<std::uint32_t>& stored = c.storedPage;
  // The page table against the extents: exactly the pages that hold points of the volume, in
  // page order (no point in the runs of pages between the stored ones, one in each stored page;
  // countInside walks only what a range does not hold whole, and skips the padding).
  for (std::size_t j = 0, from = 0; j <= stored.size(); ++j) {
    const std::uint64_t to = j < stored.size() ? stored[j] : s.pageCount();
    if (order.countInside(s.dims, from << pb, to << pb) != 0)
      for (std::uint64_t page = from; page < to; ++page)
        if (insidePointsOfPage(order, s.dims, pb, page) != 0) throw pageNotStored(c, page);
    if (j < stored.size() && insidePointsOfPage(order, s.dims, pb, to) == 0) throw pageWithoutPoints(c, to);
    from = to + 1;
  }
  std::vector<std::uint64_t> needed(stored.size());
  for (std::size_t j = 0; j < stored.size(); ++j) needed[j] = contextPagesNeededBelow(order, pb, stored[j]);
  const auto decodePage = [&](std::size_t j) {
    const StoredPage page = storedPage(s, c, stored[j]);
    ContextPageReader reader(page.bytes, c.valueBits, pb, stored[j], page.offset, page.name);
    withLebSamples(out, [&](auto* samples) {
      using T = std::remove_pointer_t<decltype(samples)>;
      reader.decode(
          order, s.dims, [&](const GridPoint& q) { return static_cast<std::int32_t>(samples[volumeIndex(q, s.dims)]); },
          [&](std::uint64_t, const GridPoint& p, std::int32_t value) {
            samples[volumeIndex(p, s.dims)] = static_cast<T>(value);
          });
    });
  };
  // Waves: from the first page not yet decoded, every following page whose corners lie below it.
  const int batch = progress ? batchPages(threads) : static_cast<int>(stored.size());
  for (std::size_t first = 0; first < stored.size();) {
    std::size_t end = first + 1;
    while (end < stored.size() && needed[end] <= stored[first]) ++end;
    for (std::size_t at = first; at < end; at += static_cast<std::size_t>(batch)) {
      const std::size_t stop = std::min(end, at + static_cast<std::size_t>(batch));
      parallelFor(static_cast<int>(stop - at), threads, [&](int i) { decodePage(at + static_cast<std::size_t>(i)); });
      if (progress) progress(static_cast<double>(stop) / static_cast<double>(stored.size()));
    }
    first = end;
  }
}

}  // namespace voxref::ref
