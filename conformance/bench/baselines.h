// General-purpose compressors as baselines of the codecs' figures: the same bytes, the same run.
// Each baseline compresses, decompresses and checks that it got the bytes back (a baseline that
// lost data would make a ratio meaningless); a mismatch or a library error throws. Compression
// is timed once (zstd -19 and xz -9 are slow); decompression as measure() times (bench.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "conformance/bench/bench.h"

namespace voxref::conf {

struct BaselineResult {
  std::string codec;  // "zstd -19", "xz -6"
  std::size_t bytes = 0;
  Timing compress, decompress;
  double ratio(std::size_t raw) const { return static_cast<double>(raw) / static_cast<double>(bytes); }
};

// zstd at `level` (one frame, one thread: libzstd's single-threaded API).
BaselineResult zstdBaseline(std::string_view raw, int level);

// `raw` compressed by zstd at `level` (one frame, one thread), for a bench that times its decode
// taking turns with another decoder's (measureTakingTurns): the decoder zstdBaseline times. The
// constructor compresses (timed once), decodes and checks the round trip; decode() decompresses
// into the frame's own buffer and checks nothing, so that it times zstd alone. Throws
// std::runtime_error for a zstd error or a round trip that lost data.
class ZstdFrame {
 public:
  ZstdFrame(std::string_view raw, int level);
  void decode();
  std::size_t rawBytes() const { return back_.size(); }
  std::string_view decoded() const { return back_; }  // what the last decode gave
  std::size_t bytes() const { return packed_.size(); }
  const Timing& compressTime() const { return compress_; }

 private:
  std::string packed_, back_;
  Timing compress_;
};

// xz (liblzma's .xz container, CRC64) at `preset` (0..9).
BaselineResult xzBaseline(std::string_view raw, std::uint32_t preset);
// `coder` (one of the above at a level) applied to each piece of `pieceBytes` of `raw` (the last
// one shorter) on its own, as a coder that keeps random access at that granularity would be used:
// the pieces' bytes summed, each a whole frame or .xz stream with its container, and their times
// summed (median, min and max each; runs the fewest of any piece). Named "<coder> on pieces of N
// bytes".
BaselineResult piecewiseBaseline(std::string_view raw, std::size_t pieceBytes,
                                 const std::function<BaselineResult(std::string_view)>& coder);

}  // namespace voxref::conf
