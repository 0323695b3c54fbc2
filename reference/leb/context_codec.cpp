#include "reference/leb/context_codec.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "reference/common/crc32.h"
#include "reference/common/parallel.h"
#include "reference/leb/context_gradient_coder.h"
#include "reference/leb/context_value_coder.h"
#include "reference/leb/leb_page.h"

namespace voxref::ref {
namespace {

// Pages a batch: what the encoder holds coded at once, and what a decoder's window lets through
// between two looks.
int batchPages(int threads) { return 4 * workerCount(threads); }

// A gradient of the volume, as the gradient coder takes it.
std::array<std::int8_t, 3> gradientAt(const std::int8_t* gradients, const GridPoint& q, const Dims3& dims) {
  const std::int8_t* g = gradients + 3 * volumeIndex(q, dims);
  return {g[0], g[1], g[2]};
}

}  // namespace

LebProgress lebProgressPart(const LebProgress& whole, double base, double span) {
  if (!whole) return {};
  return [whole, base, span](double done) { whole(base + span * done); };
}

std::vector<std::uint32_t> contextStoredPages(const HzOrder& order, const Dims3& dims, int pageBits) {
  std::vector<std::uint32_t> pages;
  order.forEachInside(dims, 0, order.size(), [&](std::uint64_t h, const GridPoint&, int, int, unsigned) {
    const auto page = static_cast<std::uint32_t>(h >> pageBits);
    if (pages.empty() || pages.back() != page) pages.push_back(page);
  });
  return pages;
}

std::uint64_t encodeContextChannel(const HzOrder& order, const LebVolumeIn& v, LebChannelKind kind,
                                   const std::vector<std::uint32_t>& stored, int pageBits, int threads,
                                   const LebProgress& progress, const LebStreamWrite& write, std::uint64_t offset) {
  const bool data = kind == LebChannelKind::Data;
  LebChannelTable table{kind, data ? 1 : 3, data ? v.sampleBits : 8, !data, {}, stored, {}, {}, LebCoder::Context};
  const std::uint64_t descriptorAt = offset;
  offset += lebDescriptorSize(table.valueBits, table.storedPage.size(), LebCoder::Context);
  const int count = static_cast<int>(table.storedPage.size()), batch = batchPages(threads);
  std::vector<std::string> coded;
  for (int first = 0; first < count; first += batch) {
    const int end = std::min(count, first + batch);
    coded.assign(static_cast<std::size_t>(end - first), {});
    parallelFor(end - first, threads, [&](int i) {
      const std::uint64_t page = table.storedPage[static_cast<std::size_t>(first + i)];
      if (!data) {
        coded[static_cast<std::size_t>(i)] = encodeContextGradientPage(
            order, v.dims, pageBits, page, [&](const GridPoint& q) { return gradientAt(v.gradients, q, v.dims); });
        return;
      }
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

namespace {

// One channel of a version 4 stream: its page table checked, then its pages decoded in waves, each
// page by decodePage(j) (the j-th stored page).
template <class DecodePage>
void decodeContextChannel(const LebStream& s, const HzOrder& order, const LebChannel& c, int threads,
                          const LebProgress& progress, DecodePage&& decodePage) {
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

}  // namespace

void decodeContextChannels(const LebStream& s, const HzOrder& order, const LebVolumeOut& out, int threads,
                           const LebProgress& progress) {
  const int pb = s.pageBits;
  // The work of a channel is in proportion to its components (1 and 3).
  const double total = s.channels.size() > 1 ? 4.0 : 1.0;
  const LebChannel& data = s.channels.at(0);
  decodeContextChannel(s, order, data, threads, lebProgressPart(progress, 0.0, 1.0 / total), [&](std::size_t j) {
    const StoredPage page = storedPage(s, data, data.storedPage[j]);
    ContextPageReader reader(page.bytes, data.valueBits, pb, data.storedPage[j], page.offset, page.name);
    withLebSamples(out, [&](auto* samples) {
      using T = std::remove_pointer_t<decltype(samples)>;
      reader.decode(
          order, s.dims, [&](const GridPoint& q) { return static_cast<std::int32_t>(samples[volumeIndex(q, s.dims)]); },
          [&](std::uint64_t, const GridPoint& p, std::int32_t value) {
            samples[volumeIndex(p, s.dims)] = static_cast<T>(value);
          });
    });
  });
  if (s.channels.size() < 2) return;
  const LebChannel& gradients = s.channels[1];
  decodeContextChannel(
      s, order, gradients, threads, lebProgressPart(progress, 1.0 / total, 3.0 / total), [&](std::size_t j) {
        const StoredPage page = storedPage(s, gradients, gradients.storedPage[j]);
        ContextGradientPageReader reader(page.bytes, pb, gradients.storedPage[j], page.offset, page.name);
        reader.decode(
            order, s.dims, [&](const GridPoint& q) { return gradientAt(out.gradients, q, s.dims); },
            [&](std::uint64_t, const GridPoint& p, const std::array<std::int8_t, 3>& g) {
              std::int8_t* to = out.gradients + 3 * volumeIndex(p, s.dims);
              to[0] = g[0];
              to[1] = g[1];
              to[2] = g[2];
            });
      });
}

}  // namespace voxref::ref
