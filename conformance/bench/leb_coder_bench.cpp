#include "conformance/bench/leb_coder_bench.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include "conformance/bench/baselines.h"
#include "conformance/framework/progress.h"
#include "reference/leb/adaptive_delta_coder.h"
#include "reference/leb/gradients.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_page.h"
#include "reference/leb/mirror_stream.h"

namespace voxref::conf {
namespace {

// One channel's deltas cut into the stream's stored pages (reference/leb/FORMAT.md, "Concepts").
struct ChannelPages {
  ref::LebChannelKind kind = ref::LebChannelKind::Data;
  int components = 1, valueBits = 8;
  std::vector<std::int32_t> deltas;
  std::vector<std::span<const std::int32_t>> pages;
};

ChannelPages channelPages(const LebDataset& d, ref::LebChannelKind kind, int pageBits) {
  ChannelPages c;
  c.kind = kind;
  const bool data = kind == ref::LebChannelKind::Data;
  c.components = data ? 1 : 3;
  c.valueBits = data ? d.bits : 8;
  c.deltas = ref::lebDeltas(d.volume, d.bits, kind);
  const ref::LebGrid grid = ref::lebGridCovering(d.volume.dims());
  const ref::HzOrder order(grid);
  std::size_t at = 0;
  for (std::uint64_t p = 0; p < ref::lebPageCount(grid, pageBits); ++p) {
    const std::size_t n = ref::insidePointsOfPage(order, d.volume.dims(), pageBits, p) * c.components;
    if (n == 0) continue;
    c.pages.emplace_back(c.deltas.data() + at, n);
    at += n;
  }
  if (at != c.deltas.size()) throw std::logic_error("leb.coder: the pages do not hold the channel's deltas");
  return c;
}

// What one coder made of one channel.
struct CoderFigure {
  std::string coder;
  double bytes = 0.0;
  Timing decode;
};

// The coders of a channel's rows, in the table's order.
enum CoderRow : std::size_t {
  kLead1,         // the paper's lead-1 Huffman, pages of 2^12
  kAdaptive12,    // voxref's adaptive coder, pages of 2^12
  kAdaptive16,    // the same, pages of 2^16
  kZstd,          // zstd -19 on the whole raw channel (the gradients' goal)
  kXz,            // xz -9 on the whole raw channel (the data's goal)
  kGoalOnPieces,  // the channel's goal coder on pieces of 2^16 samples (an anchor)
  kContext16,     // voxref's context coder of the samples and of the gradients, pages of 2^16
  kContext18,     // the same, pages of 2^18
  kCoderRows
};
bool contextRow(std::size_t row) { return row == kContext16 || row == kContext18; }

// The stream's bytes of an adaptive channel besides its pages: its descriptor (no code table; 12
// bytes a stored page) and, with the data channel, the header.
double tableBytes(const ChannelPages& c) {
  return static_cast<double>(ref::lebDescriptorSize(c.valueBits, c.pages.size(), ref::LebCoder::Adaptive)) +
         (c.kind == ref::LebChannelKind::Data ? static_cast<double>(ref::kLebHeaderBytes) : 0.0);
}

CoderFigure adaptive(const ChannelPages& c, int pageBits, int runs) {
  std::vector<std::string> coded(c.pages.size());
  double bytes = tableBytes(c);
  for (std::size_t i = 0; i < c.pages.size(); ++i) {
    coded[i] = ref::encodeAdaptivePage(c.pages[i], c.valueBits, c.components);
    bytes += static_cast<double>(coded[i].size());
  }
  std::vector<std::int32_t> out;
  auto decodeAll = [&](bool check) {
    for (std::size_t i = 0; i < c.pages.size(); ++i) {
      out.resize(c.pages[i].size());
      ref::AdaptivePageReader r(coded[i], c.valueBits, c.components, 0, "page " + std::to_string(i));
      r.read(out);
      r.finish();
      if (check && !std::equal(out.begin(), out.end(), c.pages[i].begin()))
        throw std::runtime_error("leb.coder: an adaptive page did not decode to its deltas");
    }
  };
  decodeAll(true);
  return {"adaptive (pages of 2^" + std::to_string(pageBits) + ")", bytes, measure([&] { decodeAll(false); }, runs)};
}

// The paper's code: the stream's own channel (pages of 2^12), its pages decoded by the lead-1
// decoder alone.
CoderFigure lead1(const ref::LebStream& s, const ChannelPages& c, int runs) {
  const ref::LebChannel* ch = s.channel(c.kind);
  const ref::LebStats st = ref::lebStats(s);
  double bytes = 0.0;
  for (const ref::LebChannelStats& cs : st.channels)
    if (cs.kind == c.kind) bytes = static_cast<double>(cs.compressedBytes());
  if (c.kind == ref::LebChannelKind::Data) bytes += static_cast<double>(st.headerBytes);
  if (ch->storedPage.size() != c.pages.size()) throw std::logic_error("leb.coder: the stream stores other pages");
  std::vector<std::int32_t> out;
  auto decodeAll = [&](bool check) {
    for (std::size_t i = 0; i < c.pages.size(); ++i) {
      out.resize(c.pages[i].size());
      ch->decoder->decodePage(s.page(*ch, i), out, 0, "page");
      if (check && !std::equal(out.begin(), out.end(), c.pages[i].begin()))
        throw std::runtime_error("leb.coder: a lead-1 page did not decode to its deltas");
    }
  };
  decodeAll(true);
  return {"LEB lead-1 (the paper's; pages of 2^12)", bytes, measure([&] { decodeAll(false); }, runs)};
}

// The context coder's streams (reference/leb/FORMAT.md, "Context pages" and "Context gradient
// pages"), one thread, every stream checked bit for bit in the run.
ref::LebEncodeOptions contextOptions(int pageBits, int threads, bool gradients) {
  ref::LebEncodeOptions o;
  o.pageBits = pageBits;
  o.coder = ref::LebCoder::Context;
  o.gradients = gradients;
  o.threads = threads;
  return o;
}
std::string contextPages(int pageBits) { return "pages of 2^" + std::to_string(pageBits); }

// The stream of the samples alone: its bytes (the header, the data's descriptor and pages: those
// of a stream with gradients too) and its whole decode.
CoderFigure contextSamples(const LebDataset& d, int pageBits, int threads, int runs) {
  const ref::LebStream alone =
      ref::parseLebStream(ref::encodeLeb(d.volume, d.bits, contextOptions(pageBits, threads, false)));
  if (ref::decodeLeb(alone, 1).data.data() != d.volume.data())
    throw std::runtime_error("leb.coder: a context stream did not decode to its samples");
  return {"context (voxref's: samples from their corners' values; " + contextPages(pageBits) +
              ", the whole volume decoded)",
          static_cast<double>(alone.bytes.size()), measure([&] { (void)ref::decodeLeb(alone, 1); }, runs)};
}

// A whole decode's timing less a part's measured beside it (the rest's median, and its bounds).
Timing lessTiming(const Timing& whole, const Timing& part) {
  Timing rest = whole;
  rest.median = std::max(whole.median - part.median, 1e-9);
  rest.min = std::max(whole.min - part.max, 1e-9);
  rest.max = std::max(whole.max - part.min, 1e-9);
  return rest;
}

// Two decodes' timings added (both channels' decodes, each measured on its own).
Timing sumTiming(const Timing& a, const Timing& b) {
  return {a.median + b.median, a.min + b.min, a.max + b.max, std::min(a.runs, b.runs), false};
}

// The gradients' figure of the stream of the samples and the stored `gradients` (3 int8 a
// sample): their descriptor and pages, and their decode, the whole stream's less `samples`
// (contextSamples' decode at the same page size, measured before it in the same run).
CoderFigure contextGradients(const LebDataset& d, const std::vector<std::int8_t>& gradients, int pageBits, int threads,
                             int runs, const Timing& samples) {
  const ref::LebStream both = ref::parseLebStream(
      ref::encodeLeb(ref::LebVolumeIn{d.volume.dims(), d.bits, nullptr, d.volume.data().data(), gradients.data()},
                     contextOptions(pageBits, threads, true)));
  const ref::LebDecoded back = ref::decodeLeb(both, 1);
  if (back.data.data() != d.volume.data() || back.gradients != gradients)
    throw std::runtime_error("leb.coder: a context stream did not decode to its samples and gradients");
  const Timing rest = lessTiming(measure([&] { (void)ref::decodeLeb(both, 1); }, runs), samples);
  const ref::LebChannel& g = both.channels[1];
  return {"context (voxref's: vectors from their corners' and the page's repeats, gz from the unit sphere; " +
              contextPages(pageBits) + ", the whole volume decoded: the stream's decode less the samples')",
          static_cast<double>(g.descriptorBytes + g.pageOffset.back()), rest};
}

// The context coder's stream of the samples folded across the volume's mirror planes
// (reference/leb/FORMAT.md, "Mirrored streams"; findLebMirrorPlanes), pages of 2^pageBits, and with
// `gradients` (3 int8 a sample; null for none) those stored folded with them: the whole stream's
// bytes and its whole decode, checked in the run. Empty when the volume has no plane.
std::optional<CoderFigure> contextMirrored(const LebDataset& d, const ref::LebMirrorPlanes& planes, int pageBits,
                                           int threads, int runs, const std::vector<std::int8_t>* gradients = nullptr) {
  if (!planes.any()) return std::nullopt;
  const ref::MirroredLebStream m = ref::parseMirroredLebStream(
      ref::encodeMirroredLeb(d.volume, d.bits, planes, contextOptions(pageBits, threads, gradients != nullptr),
                             gradients ? *gradients : std::vector<std::int8_t>{}));
  const ref::LebDecoded back = ref::decodeMirroredLeb(m, 1);
  if (back.data.data() != d.volume.data() || (gradients && back.gradients != *gradients))
    throw std::runtime_error("leb.coder: a mirrored stream did not decode to its samples" +
                             std::string(gradients ? " and gradients" : ""));
  return CoderFigure{"context, mirrored" + std::string(gradients ? ", gradients folded with the samples" : "") + " (" +
                         ref::lebMirrorPlanesText(planes) + "; " + std::to_string(m.exceptions.size()) +
                         " points off their image" + (gradients ? " in sample or gradient" : "") + "; " +
                         contextPages(pageBits) + ", the whole volume decoded and unfolded)",
                     static_cast<double>(m.streamBytes), measure([&] { (void)ref::decodeMirroredLeb(m, 1); }, runs)};
}

// The gradients' figure of that stream: its bytes and decode less those of the mirrored stream of
// the samples alone across the same planes (`samples`, measured before it in the same run), what
// storing the gradients adds, their exceptions included.
CoderFigure gradientsPart(const CoderFigure& whole, const CoderFigure& samples) {
  return {whole.coder + "; the bytes and decode time it adds to the samples' mirrored stream",
          whole.bytes - samples.bytes, lessTiming(whole.decode, samples.decode)};
}

CoderFigure baseline(const BaselineResult& b) {
  return {b.codec + " (whole channel, no random access)", static_cast<double>(b.bytes), b.decompress};
}

// The pages of the adaptive coder's larger size hold up to 2^16 points; the general-purpose
// coders' pieces hold as many samples (anchor rows: random access at about the same granularity).
constexpr int kPieceSampleBits = 16;

// The coder a channel's goal names (issue 18, goal 5): xz -9 for the data, zstd -19 for the
// gradients.
std::string goalCoderName(bool data) { return data ? "xz -9" : "zstd -19"; }
BaselineResult goalCoder(std::string_view raw, bool data) { return data ? xzBaseline(raw, 9) : zstdBaseline(raw, 19); }

// The channel's goal coder on pieces of 2^16 samples of the raw channel, each on its own.
CoderFigure piecewise(const std::string& raw, bool data, int bytesPerSample) {
  const std::size_t pieceBytes = static_cast<std::size_t>(bytesPerSample) << kPieceSampleBits;
  const BaselineResult b =
      piecewiseBaseline(raw, pieceBytes, [&](std::string_view piece) { return goalCoder(piece, data); });
  return {goalCoderName(data) + " on pieces of 2^" + std::to_string(kPieceSampleBits) + " samples (" +
              std::to_string(pieceBytes) + " bytes), each on its own: random access as the adaptive 2^16 pages",
          static_cast<double>(b.bytes), b.decompress};
}

// Order-0 entropy of the points' gradients taken as 3-byte symbols, in bytes: what a coder of
// independent gradient vectors with their exact frequencies would need (an anchor, not a coder).
double tripleEntropyBytes(const std::string& gradients) {
  std::unordered_map<std::uint32_t, std::uint64_t> counts;
  for (std::size_t i = 0; i + 2 < gradients.size(); i += 3)
    ++counts[static_cast<std::uint8_t>(gradients[i]) |
             (static_cast<std::uint32_t>(static_cast<std::uint8_t>(gradients[i + 1])) << 8) |
             (static_cast<std::uint32_t>(static_cast<std::uint8_t>(gradients[i + 2])) << 16)];
  const double n = static_cast<double>(gradients.size() / 3);
  double bits = 0.0;
  for (const auto& [symbol, count] : counts)
    bits -= static_cast<double>(count) * std::log2(static_cast<double>(count) / n);
  return bits / 8.0;
}

struct ChannelFigures {
  ref::LebChannelKind kind;
  double rawBytes = 0.0;
  std::array<CoderFigure, kCoderRows> coders;  // by CoderRow
  double tripleEntropy = 0.0;                  // gradients only
  Timing derive;                               // gradients only: quantizedGradients of the samples, one thread
  double repeatedRows = 0.0;                   // repeatedRowShare of the channel's x-rows
  std::vector<CoderFigure> mirrored;           // contextMirrored (data), gradientsPart, at 2^16 and 2^18, if a plane
  std::vector<CoderFigure> mirroredWhole;      // gradients: contextMirrored with them, whole, as `mirrored`
};

std::vector<ChannelFigures> measureDataset(const BenchOptions& o, const LebDataset& d) {
  const int runs = o.quick ? 1 : 3;
  ref::LebEncodeOptions options;
  options.threads = o.threads;
  const ref::LebStream s = ref::parseLebStream(ref::encodeLeb(d.volume, d.bits, options));
  const std::vector<std::int8_t> gradients = ref::quantizedGradients(d.volume);
  const std::array<CoderFigure, 2> samples{contextSamples(d, 16, o.threads, runs),
                                           contextSamples(d, 18, o.threads, runs)};
  std::vector<ChannelFigures> figures;
  for (const ref::LebChannelKind kind : {ref::LebChannelKind::Data, ref::LebChannelKind::Gradients}) {
    const bool data = kind == ref::LebChannelKind::Data;
    const std::string raw = data ? dataBytes(d.volume, d.bits) : gradientBytes(d.volume);
    ChannelFigures f{kind, static_cast<double>(raw.size()), {}, 0.0, {}, 0.0, {}, {}};
    const ChannelPages p12 = channelPages(d, kind, 12);
    f.coders[kLead1] = lead1(s, p12, runs);
    f.coders[kAdaptive12] = adaptive(p12, 12, runs);
    f.coders[kAdaptive16] = adaptive(channelPages(d, kind, 16), 16, runs);
    f.coders[kZstd] = baseline(zstdBaseline(raw, 19));
    f.coders[kXz] = baseline(xzBaseline(raw, 9));
    f.coders[kGoalOnPieces] = piecewise(raw, data, data ? d.bits / 8 : 3);
    if (!data) {
      f.tripleEntropy = tripleEntropyBytes(raw);
      f.derive = measure([&] { (void)ref::quantizedGradients(d.volume); }, runs);
    }
    for (const auto& [row, pageBits, at] : {std::tuple{kContext16, 16, 0}, std::tuple{kContext18, 18, 1}})
      f.coders[row] =
          data ? samples[at] : contextGradients(d, gradients, pageBits, o.threads, runs, samples[at].decode);
    // Folded with the samples, the gradients take part in the search for planes.
    const ref::LebMirrorPlanes planes =
        ref::findLebMirrorPlanes(d.volume.data().data(), data ? nullptr : gradients.data(), d.volume.dims());
    for (const int pageBits : {16, 18}) {
      std::optional<CoderFigure> m = contextMirrored(d, planes, pageBits, o.threads, runs);
      if (m && !data) {
        f.mirroredWhole.push_back(*contextMirrored(d, planes, pageBits, o.threads, runs, &gradients));
        m = gradientsPart(f.mirroredWhole.back(), *m);
      }
      if (m) f.mirrored.push_back(std::move(*m));
    }
    f.repeatedRows = repeatedRowShare(raw, raw.size() / (static_cast<std::size_t>(d.volume.dims()[1]) *
                                                         static_cast<std::size_t>(d.volume.dims()[2])));
    figures.push_back(std::move(f));
  }
  return figures;
}

std::string ratioText(double r) { return formatNumber("%.3f:1", r); }

// The paper's Table 1 conditions for the gradients (diffused before they are quantized;
// kPaperDiffusionSteps): zstd -19, xz -9 and the context coder (pages of 2^16) on the same bytes.
struct DiffusedFigures {
  int steps = 0;
  double rawBytes = 0.0;
  CoderFigure zstd, xz, context;
};
// `samples`: the context coder's decode of the samples alone, pages of 2^16 (contextSamples).
std::vector<DiffusedFigures> measureDiffused(const BenchOptions& o, const LebDataset& d, const Timing& samples) {
  const int runs = o.quick ? 1 : 3;
  std::vector<DiffusedFigures> out;
  for (const int steps : kPaperDiffusionSteps) {
    const std::vector<std::int8_t> g = ref::diffusedQuantizedGradients(d.volume, steps);
    const std::string raw(reinterpret_cast<const char*>(g.data()), g.size());
    out.push_back({steps, static_cast<double>(raw.size()), baseline(zstdBaseline(raw, 19)),
                   baseline(xzBaseline(raw, 9)), contextGradients(d, g, 16, o.threads, runs, samples)});
  }
  return out;
}

}  // namespace

BenchTable lebCoderBench(const BenchOptions& o) {
  BenchTable t;
  t.id = kLebCoderBenchId;
  t.title =
      "LEB entropy stage: voxref's adaptive and context coders against lead-1 Huffman, zstd -19 and xz -9 (issue 18, "
      "goal 5)";
  t.columns = {"volume",
               "channel",
               "coder",
               "ratio",
               "decode MB/s (1 thread)",
               "goal: voxref's coder beats xz -9 (data), zstd -19 (gradients)"};
  t.data["rows"] = nlohmann::json::array();
  const std::vector<LebDataset> sets = folderLebDatasets(o);
  Progress progress("voxref bench leb.coder", static_cast<long>(sets.size()));
  long done = 0;
  for (const LebDataset& d : sets) {
    progress.update(done++, d.name);
    if (!d.missing.empty()) {
      t.rows.push_back({d.name, "", "not run: " + d.missing, "", "", ""});
      continue;
    }
    const std::vector<ChannelFigures> figures = measureDataset(o, d);
    for (const ChannelFigures& f : figures) {
      const bool data = f.kind == ref::LebChannelKind::Data;
      const std::string channel = data ? "data" : "gradients";
      const CoderFigure& goal = f.coders[data ? kXz : kZstd];  // the channel's goal coder (goalCoderName)
      nlohmann::json row = {
          {"volume", d.name}, {"channel", channel}, {"raw_bytes", f.rawBytes}, {"coders", nlohmann::json::array()}};
      for (std::size_t i = 0; i < f.coders.size(); ++i) {
        const CoderFigure& c = f.coders[i];
        std::string verdict;
        if (i == kAdaptive12 || i == kAdaptive16 || contextRow(i)) {
          const double against = goal.bytes / c.bytes;  // the coder's ratio over the goal's
          verdict = formatNumber("%.2f", against) + " of " + goalCoderName(data) +
                    "'s ratio: " + (against > 1.0 ? "beats it" : "below it");
        } else if (i == kGoalOnPieces) {  // an anchor, not the goal: the adaptive 2^16 pages against it
          verdict = "anchor: adaptive 2^16 at " + formatNumber("%.2f", c.bytes / f.coders[kAdaptive16].bytes) +
                    " of its ratio";
        }
        t.rows.push_back({d.name, channel, c.coder, ratioText(f.rawBytes / c.bytes),
                          formatNumber("%.1f", f.rawBytes / 1e6 / c.decode.median), verdict});
        row["coders"].push_back(
            {{"coder", c.coder}, {"bytes", c.bytes}, {"ratio", f.rawBytes / c.bytes}, {"decode", toJson(c.decode)}});
      }
      if (f.mirrored.empty())
        t.rows.push_back({d.name, channel,
                          std::string("context, mirrored: no mirror plane found (the volume is not its own mirror "
                                      "image on any axis") +
                              (data ? "" : " in its samples and gradients") + "), so no folded stream",
                          "-", "-", ""});
      for (const CoderFigure& c : f.mirrored) {
        const double against = goal.bytes / c.bytes;
        t.rows.push_back({d.name, channel, c.coder, ratioText(f.rawBytes / c.bytes),
                          formatNumber("%.1f", f.rawBytes / 1e6 / c.decode.median),
                          formatNumber("%.2f", against) + " of " + goalCoderName(data) +
                              "'s ratio: " + (against > 1.0 ? "beats it" : "below it")});
        row["coders"].push_back({{"coder", c.coder},
                                 {"bytes", c.bytes},
                                 {"ratio", f.rawBytes / c.bytes},
                                 {"decode", toJson(c.decode)},
                                 {"mirrored", true}});
      }
      t.rows.push_back({d.name, channel,
                        "anchor: share of the x-rows (not one value repeated) that repeat an earlier row exactly",
                        formatNumber("%.1f %%", 100.0 * f.repeatedRows), "-", ""});
      row["repeated_row_share"] = f.repeatedRows;
      if (!data) {
        t.rows.push_back({d.name, channel,
                          "anchor: order-0 entropy of the gradient vectors (3-byte symbols; not a coder)",
                          ratioText(f.rawBytes / f.tripleEntropy), "-", ""});
        row["triple_entropy_bytes"] = f.tripleEntropy;
        t.rows.push_back({d.name, channel,
                          "derived from the data (--derive-gradients; not an entropy stage: the decoder computes "
                          "them from the samples)",
                          "none stored", formatNumber("%.1f", f.rawBytes / 1e6 / f.derive.median),
                          "no coder: nothing to compare"});
        row["derive"] = toJson(f.derive);
      }
      t.data["rows"].push_back(row);
    }
    for (const DiffusedFigures& f : measureDiffused(o, d, figures[0].coders[kContext16].decode)) {
      const std::string channel =
          "gradients diffused " + std::to_string(f.steps) + " steps (the paper's Table 1 conditions; not derivable)";
      nlohmann::json row = {{"volume", d.name},
                            {"channel", channel},
                            {"diffusion_steps", f.steps},
                            {"raw_bytes", f.rawBytes},
                            {"coders", nlohmann::json::array()}};
      for (const CoderFigure* c : {&f.zstd, &f.xz, &f.context}) {
        const double against = f.zstd.bytes / c->bytes;
        t.rows.push_back({d.name, channel, c->coder, ratioText(f.rawBytes / c->bytes),
                          formatNumber("%.1f", f.rawBytes / 1e6 / c->decode.median),
                          c == &f.context ? formatNumber("%.2f", against) +
                                                " of zstd -19's ratio: " + (against > 1.0 ? "beats it" : "below it")
                                          : ""});
        row["coders"].push_back({{"coder", c->coder},
                                 {"bytes", c->bytes},
                                 {"ratio", f.rawBytes / c->bytes},
                                 {"decode", toJson(c->decode)}});
      }
      t.data["rows"].push_back(row);
    }
  }
  progress.finish();
  t.notes =
      "Ratio: the channel's raw bytes (samples at 1 byte; 3 bytes of quantized gradient a sample) over the coded "
      "bytes. "
      "LEB and adaptive rows count the stream's page table (12 bytes a stored page), the descriptor and, for the data, "
      "the header; the lead-1 rows also its code table. Both code the same deltas (the paper's split-edge prediction, "
      "pages coded on their own, so random access stays); the adaptive coder's contexts are the page's previous two "
      "deltas, its models restart with every page (reference/leb/FORMAT.md, 'Adaptive pages'). The context coder's "
      "rows are one stream of the samples and the gradients ('Context pages', 'Context gradient pages'): each point "
      "predicted from all its corners, with contexts from their range and from its page's neighbours of its class, "
      "so a page decodes with its corners' values, which random access reads anyway; a gradient's gz is coded from "
      "the unit sphere given gx and gy, and a vector that repeats one of its corners' or of its page's is coded by "
      "where it was seen (each page codes its gradients both with and without these repeats and keeps the "
      "shorter). The data row counts the header, the data's descriptor and pages, the "
      "gradients row the gradients' descriptor and pages; the data's decode figure is the whole volume's samples "
      "(the stream of the samples alone), the gradients' the whole stream's decode less that (medians of the same "
      "run). The rows 'gradients diffused N steps' code the paper's Table 1 gradients (diffused before "
      "quantizing: reference/leb/gradients.h), which no decoder can derive from the samples. zstd and xz compress "
      "the raw channel whole (zstd -19, xz -9; no random access); the anchor 'on pieces' gives the goal's coder the "
      "adaptive 2^16 coder's random access: the raw channel cut into pieces of 2^16 samples (four slices of the "
      "hydrogen atom, one of the engine), each compressed on its own with its frame or .xz container, so that it "
      "says how much of a coder's lead is the price of random access. Decode MB/s: raw bytes per second of decoding "
      "every page (or the whole channel), one thread. The gradient anchor is the order-0 entropy of the gradient "
      "vectors: coding each point's three components as one symbol, with no prediction, would reach it. The row anchor "
      "counts the x-rows that repeat an earlier row byte for byte (rows of one value repeated left out): zstd and xz "
      "copy such a row from any distance, while the split-edge prediction sees only the neighbours of a point, and "
      "a page coded on its own cannot refer to rows in other pages. Where it is high (the data of the "
      "mirror-symmetric hydrogen atom and nucleon), the general-purpose coders' lead comes from these repeats; a "
      "mirror flips the sign of a gradient component, so gradient rows rarely repeat exactly, and the anchor does not "
      "account for zstd's lead on the hydrogen atom's gradients (long partial matches). The rows 'context, mirrored' "
      "store such a volume folded (reference/leb/FORMAT.md, 'Mirrored streams'): the planes findLebMirrorPlanes "
      "finds, one side of each as a context stream, the other side as its images, and the points off their image as "
      "exceptions; the ratio counts the whole stream (its header, the exceptions and the folded stream), the decode "
      "figure the whole volume decoded and unfolded. Its gradients row stores the gradients folded with the samples "
      "(a mirrored point's gradient is its image's with the component across each of its planes negated; the points "
      "off that are exceptions too, and the planes are searched with the gradients, so they may be fewer than the "
      "data's): it counts the bytes the gradients add to the mirrored stream of the samples alone across the same "
      "planes, exceptions included, and the decode time they add.";
  return t;
}

StudyGroup lebCoderStudyGroup(const BenchOptions& o, const LebDataset& d) {
  StudyGroup g{"entropy stage (" + d.name + ")",
               "none: every coder decodes bit for bit (checked in the run)",
               "decoding the whole volume's deltas (data and gradients), one thread; zstd and xz: the raw bytes; "
               "the context coder: the whole volume's samples and gradients",
               "the coded bytes (data + gradients)",
               true,
               {},
               "The adaptive and context coders and lead-1 keep page random access; zstd and xz do not, except on "
               "pieces of 2^16 samples (the data's by xz -9, the gradients' by zstd -19). A volume that is its own "
               "mirror image also has the mirrored context streams (reference/leb/FORMAT.md, 'Mirrored streams'), "
               "gradients folded with the samples, which keep page random access too."};
  const std::vector<ChannelFigures> f = measureDataset(o, d);
  for (std::size_t i = 0; i < f[0].coders.size(); ++i) {
    StudyVariant v;
    // Each coder codes both channels, except on pieces: the data's goal coder and the gradients'.
    v.name = i != kGoalOnPieces
                 ? f[0].coders[i].coder
                 : goalCoderName(true) + " (data), " + goalCoderName(false) + " (gradients), on pieces of 2^" +
                       std::to_string(kPieceSampleBits) + " samples each on its own";
    if (contextRow(i)) v.name += "; its gradients' pages beside";  // both channels, as every other variant
    v.error = 0.0;
    v.time = sumTiming(f[0].coders[i].decode, f[1].coders[i].decode);
    v.memoryBytes = f[0].coders[i].bytes + f[1].coders[i].bytes;
    v.figures = {{"lossless", true}, {"ratio", (f[0].rawBytes + f[1].rawBytes) / v.memoryBytes}};
    g.variants.push_back(v);
  }
  // The mirrored streams that store the gradients folded with the samples, whole.
  for (const CoderFigure& whole : f[1].mirroredWhole) {
    StudyVariant v;
    v.name = whole.coder;
    v.error = 0.0;
    v.time = whole.decode;
    v.memoryBytes = whole.bytes;
    v.figures = {{"lossless", true}, {"ratio", (f[0].rawBytes + f[1].rawBytes) / v.memoryBytes}};
    g.variants.push_back(v);
  }
  return g;
}

}  // namespace voxref::conf
