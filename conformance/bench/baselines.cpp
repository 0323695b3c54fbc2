#include "conformance/bench/baselines.h"

#include <lzma.h>
#include <zstd.h>

#include <algorithm>
#include <stdexcept>

namespace voxref::conf {

ZstdFrame::ZstdFrame(std::string_view raw, int level) : packed_(ZSTD_compressBound(raw.size()), '\0'), back_(raw) {
  std::size_t size = 0;
  compress_ = measureOnce([&] { size = ZSTD_compress(packed_.data(), packed_.size(), raw.data(), raw.size(), level); });
  if (ZSTD_isError(size)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(size));
  packed_.resize(size);
  std::fill(back_.begin(), back_.end(), '\0');
  const std::size_t got = ZSTD_decompress(back_.data(), back_.size(), packed_.data(), packed_.size());
  if (ZSTD_isError(got) || got != raw.size() || back_ != raw)
    throw std::runtime_error("zstd: the round trip lost data");
}

void ZstdFrame::decode() {
  const std::size_t got = ZSTD_decompress(back_.data(), back_.size(), packed_.data(), packed_.size());
  if (ZSTD_isError(got)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(got));
}

BaselineResult zstdBaseline(std::string_view raw, int level) {
  ZstdFrame frame(raw, level);
  BaselineResult r{"zstd -" + std::to_string(level), frame.bytes(), frame.compressTime(), {}};
  r.decompress = measure([&] { frame.decode(); });
  return r;
}

BaselineResult xzBaseline(std::string_view raw, std::uint32_t preset) {
  BaselineResult r{"xz -" + std::to_string(preset), 0, {}, {}};
  std::string packed(lzma_stream_buffer_bound(raw.size()), '\0');
  std::size_t size = 0;
  lzma_ret ret = LZMA_OK;
  r.compress = measureOnce([&] {
    ret = lzma_easy_buffer_encode(preset, LZMA_CHECK_CRC64, nullptr, reinterpret_cast<const std::uint8_t*>(raw.data()),
                                  raw.size(), reinterpret_cast<std::uint8_t*>(packed.data()), &size, packed.size());
  });
  if (ret != LZMA_OK)
    throw std::runtime_error("xz: compression failed (" + std::to_string(static_cast<int>(ret)) + ")");
  r.bytes = size;
  std::string back(raw.size(), '\0');
  std::size_t inPos = 0, outPos = 0;
  std::uint64_t memlimit = UINT64_MAX;
  r.decompress = measure([&] {
    inPos = 0;
    outPos = 0;
    ret = lzma_stream_buffer_decode(&memlimit, 0, nullptr, reinterpret_cast<const std::uint8_t*>(packed.data()), &inPos,
                                    size, reinterpret_cast<std::uint8_t*>(back.data()), &outPos, back.size());
  });
  if (ret != LZMA_OK || outPos != raw.size() || back != raw) throw std::runtime_error("xz: the round trip lost data");
  return r;
}

BaselineResult piecewiseBaseline(std::string_view raw, std::size_t pieceBytes,
                                 const std::function<BaselineResult(std::string_view)>& coder) {
  if (pieceBytes == 0 || raw.empty()) throw std::invalid_argument("piecewiseBaseline: no pieces");
  BaselineResult r;
  auto add = [](Timing& sum, const Timing& t) {
    sum.runs = sum.runs == 0 ? t.runs : std::min(sum.runs, t.runs);
    sum.median += t.median;
    sum.min += t.min;
    sum.max += t.max;
  };
  for (std::size_t at = 0; at < raw.size(); at += pieceBytes) {
    const BaselineResult piece = coder(raw.substr(at, pieceBytes));
    if (r.codec.empty()) r.codec = piece.codec + " on pieces of " + std::to_string(pieceBytes) + " bytes";
    r.bytes += piece.bytes;
    add(r.compress, piece.compress);
    add(r.decompress, piece.decompress);
  }
  return r;
}

}  // namespace voxref::conf
