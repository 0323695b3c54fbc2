// voxref encode | decode | info --codec leb: lossless LEB compression (Gregorski et al. 2004) of
// the user's raw volumes.
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <variant>

#include "conformance/cli/codecs.h"
#include "conformance/framework/exit_status.h"
#include "conformance/framework/progress.h"
#include "conformance/framework/stopwatch.h"
#include "conformance/io/atomic_file.h"
#include "conformance/io/leb_file.h"
#include "conformance/io/leb_file_codec.h"
#include "conformance/io/raw_volume.h"
#include "reference/common/byte_stream.h"
#include "reference/iso/diamond_bounds.h"
#include "reference/iso/grid_field.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_padding.h"
#include "reference/leb/mirror_stream.h"

namespace voxref::cli {
namespace {

// The bytes this process may still map under its address-space limit (ulimit -v, RLIMIT_AS), or
// nothing when it has none.
std::optional<std::uint64_t> addressSpaceLeft() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  std::uint64_t mapped = 0;  // the first field of /proc/self/statm: the whole mapped size, in pages
  if (std::ifstream statm("/proc/self/statm"); statm >> mapped)
    mapped *= static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  const auto cap = static_cast<std::uint64_t>(limit.rlim_cur);
  return cap > mapped ? cap - mapped : 0;
}

// Refuses a job whose memory need, known before anything is allocated, exceeds what this process
// may still map (ulimit -v); `what` names the file and the need ("F: decoding needs N bytes (...)").
void refuseBeyondAddressSpace(std::uint64_t need, const std::string& what) {
  if (const std::optional<std::uint64_t> room = addressSpaceLeft(); room && need > *room)
    throw io::IoError(what + ", more than the " + std::to_string(*room) +
                      " bytes this process may still allocate (ulimit -v)");
}

std::string ratioText(double r) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f:1", r);
  return b;
}

void printInfo(const ref::LebStream& s, std::ostream& out) {
  const ref::LebStats st = ref::lebStats(s);
  const int n = s.grid.pointsPerAxis();
  out << "codec           leb (Gregorski, Senecal, Duchaineau, Joy 2004)\n"
      << "volume          " << dimsText(s.dims) << " uint" << s.sampleBits << "\n"
      << "grid            " << n << "^3 (k = " << s.grid.k << ", " << s.grid.levelCount() << " levels)";
  if (st.gridPoints != st.volumePoints)
    out << "; padding " << (st.gridPoints - st.volumePoints) << " points beyond " << dimsText(s.dims)
        << ", not coded (they take their prediction) and excluded from the ratios";
  out << "\ncoder           "
      << (s.coder == ref::LebCoder::Lead1      ? "lead1 (the paper's Huffman code of lead-1 symbols; version 2)"
          : s.coder == ref::LebCoder::Adaptive ? "adaptive (voxref's range coder; version 3, reference/leb/FORMAT.md)"
                                               : "context (voxref's range coder of the samples and gradients with "
                                                 "their corners' contexts; version 4, reference/leb/FORMAT.md)");
  out << "\npages           " << st.storedPages << " stored of the grid's " << st.pages << ", each "
      << (1u << s.pageBits) << " points (pages of padding alone are not stored)\n";
  for (const ref::LebChannelStats& c : st.channels) {
    const bool data = c.kind == ref::LebChannelKind::Data;
    out << (data ? "data            " : "gradients       ") << c.rawBytes << " bytes raw -> " << c.compressedBytes()
        << " (" << c.payloadBytes << " coded, " << c.descriptorBytes << " tables)"
        << (data ? " + " + std::to_string(st.headerBytes) + " header" : "") << ", ratio "
        << ratioText(st.channelRatio(c.kind)) << "\n";
  }
  if (s.derivedGradients)
    out << "gradients       derived from the data when decoded (central differences; reference/leb/FORMAT.md, "
           "header byte 23): none stored\n";
  out << "stream          " << st.streamBytes << " bytes, ratio " << ratioText(st.ratio())
      << " (raw bytes of the volume" << (st.channels.size() > 1 ? " and its gradients" : "") << " over the stream)\n";
}

void printInfo(const ref::MirroredLebStream& m, std::ostream& out) {
  const ref::LebMirrorHeader& h = m.header;
  const std::uint64_t points = ref::sampleCount(h.dims), kept = ref::sampleCount(m.inner.dims);
  out << "mirrored        the volume is stored folded across its mirror planes (reference/leb/FORMAT.md, "
         "\"Mirrored streams\")\n"
      << "volume          " << dimsText(h.dims) << " uint" << h.sampleBits << "\n"
      << "mirror planes   " << ref::lebMirrorPlanesText(h.planes) << "\n"
      << "folded volume   " << dimsText(m.inner.dims) << ": " << kept << " of the " << points
      << " points stored, the other " << (points - kept) << " are their images\n"
      << "exceptions      " << m.exceptions.size() << " mirrored points differ from their image: " << m.exceptionBytes
      << " bytes\n"
      << "gradients       "
      << (h.gradients == ref::LebMirrorGradients::Derived
              ? "derived from the unfolded samples when decoded (central differences): none stored"
          : h.storedGradients() ? "stored folded with the samples (a mirrored point's gradient is its image's with "
                                  "the component across each of its planes negated; the others are exceptions)"
                                : "none")
      << "\n"
      << "stream          " << m.streamBytes << " bytes, ratio "
      << ratioText(static_cast<double>(points * (h.sampleBits / 8 + (h.storedGradients() ? 3u : 0u))) /
                   static_cast<double>(m.streamBytes))
      << " (raw bytes of the volume" << (h.storedGradients() ? " and its gradients" : "") << " over the stream)\n"
      << "the folded volume's stream, from byte " << m.innerOffset << ":\n";
  printInfo(m.inner, out);
}

void printAnyInfo(const std::variant<io::LebFile, io::MirroredLebFile>& file, std::ostream& out) {
  std::visit([&](const auto& f) { printInfo(f.stream, out); }, file);
}

}  // namespace

int encodeLebCommand(const EncodeOptions& o) {
  if (o.out.extension() != ".vxleb") throw conf::UsageError("--out must name a .vxleb file, got " + o.out.string());
  if (o.plume)
    throw conf::UsageError("--plume is for the timevarying codec; the leb codec encodes --input FILE --dims X Y Z");
  if (o.inputs.size() != 1)
    throw conf::UsageError("the leb codec encodes one volume: give --input FILE once (got " +
                           std::to_string(o.inputs.size()) + ")");
  if (o.dims.size() != 3) throw conf::UsageError("--dims needs three extents X Y Z");
  const auto type = io::parseVoxelType(o.type);
  if (!type) throw conf::UsageError("--type must be uint8 or uint16, got " + o.type);
  const ref::Dims3 dims{o.dims[0], o.dims[1], o.dims[2]};
  ref::LebEncodeOptions options;
  options.pageBits = o.pageBits;
  options.gradients = !o.noGradients;
  options.deriveGradients = o.deriveGradients;
  if (o.noGradients && o.deriveGradients)
    throw conf::UsageError("--derive-gradients and --no-gradients contradict each other: give one");
  if (o.lebCoder == "lead1")
    options.coder = ref::LebCoder::Lead1;
  else if (o.lebCoder == "adaptive")
    options.coder = ref::LebCoder::Adaptive;
  else if (o.lebCoder == "context")
    options.coder = ref::LebCoder::Context;
  else
    throw conf::UsageError("--coder must be lead1, adaptive or context, got " + o.lebCoder);
  if (o.mirror != "off" && o.mirror != "auto") throw conf::UsageError("--mirror must be off or auto, got " + o.mirror);
  const bool mirror = o.mirror == "auto";
  if (mirror && !o.boundsOut.empty())
    throw conf::UsageError("--mirror auto and --bounds-out: the diamond bounds are written for unfolded streams only");
  // What the encoder will allocate is known from the extents (the samples, and the padding that
  // predictions reach: leb_padding.h). Refused before the volume is read when the process may not
  // allocate it.
  (void)io::voxelsOf(o.inputs[0], dims);  // extents that are not positive or too many: named before any other check
  const ref::LebGrid grid = ref::lebGridCovering(dims);
  const bool bounds = !o.boundsOut.empty();
  std::uint64_t need = 0;
  try {
    // Without bounds the encoder streams from the file (conformance/io/leb_file_codec.h); the
    // bounds need the volume in memory, and the stream is then made there too, so that the two
    // files are written together.
    need = bounds ? ref::lebEncodeMemoryBytes(dims, options) + 2 * ref::sampleCount(dims)  // + the volume at 16 bits
                  : io::lebFileEncodeAddressBytes(dims, *type, options);
    if (mirror)  // the folded volume and its gradients, at most this
      need += ref::sampleCount(dims) *
              ((*type == io::VoxelType::UInt8 ? 1 : 2) + (ref::lebStoresGradients(options) ? 3 : 0));
  } catch (const std::invalid_argument& e) {
    throw conf::UsageError(e.what());
  }
  if (bounds) {  // diamond_bounds.h: 8 bytes per grid point, beside a copy of the volume and its (zero) gradients
    const auto n = static_cast<std::uint64_t>(grid.pointsPerAxis());
    need += 16 * n * n * n + 5 * ref::sampleCount(dims);  // the bounds and their serialized copy
  }
  const std::string needText =
      o.inputs[0].string() + ": encoding needs " + std::to_string(need) + " bytes (" + dimsText(dims) +
      " samples in the " + std::to_string(grid.pointsPerAxis()) + "^3 grid of k = " + std::to_string(grid.k) +
      (bounds ? ": the volume, its deltas, gradients and coded pages, and the "
              : ": the volume and its gradients mapped from files, a batch of pages, and the ") +
      std::to_string(ref::LebPadding::shellPoints(grid, dims)) + " padding points predictions reach" +
      (bounds ? "; and 16 bytes per grid point for the diamond bounds and their file" : "") + ")";
  refuseBeyondAddressSpace(need, needText);
  const int bits = *type == io::VoxelType::UInt8 ? 8 : 16;
  const auto t0 = conf::Clock::now();
  if (!bounds) {
    try {
      conf::Progress progress("voxref encode --codec leb", 1000);
      const io::LebFileRun run = io::encodeLebFile(
          o.inputs[0], dims, *type, o.out, options, io::kLebWindowBytes,
          [&](double done, std::string_view step) { progress.update(std::lround(1000 * done), step); }, {mirror, {}});
      progress.finish();
      if (mirror)
        std::cout << "mirror planes   "
                  << (run.mirrorPlanes.any()
                          ? ref::lebMirrorPlanesText(run.mirrorPlanes)
                          : std::string("none found (no axis on which the volume is its own mirror image in all but "
                                        "one of 1024 points") +
                                (ref::lebStoresGradients(options)
                                     ? ", and in its sample or gradient in all but one of 32"
                                     : "") +
                                "): the stream is not folded")
                  << "\n";
    } catch (const std::invalid_argument& e) {
      throw conf::UsageError(e.what());
    } catch (const std::bad_alloc&) {
      throw io::IoError(needText + ": out of memory");
    }
    std::cout << "wrote " << o.out.string() << " in " << conf::secondsSince(t0) << " s\n";
    printAnyInfo(io::openAnyLebFile(o.out), std::cout);
    return 0;
  }
  ref::Volume<std::uint16_t> volume = *type == io::VoxelType::UInt8
                                          ? ref::widenToU16(io::readRawVolumeU8(o.inputs[0], dims))
                                          : io::readRawVolumeU16(o.inputs[0], dims);
  std::string stream, boundsBytes;
  try {
    stream = ref::encodeLeb(volume, bits, options);
    const ref::DenseGridField field(volume, std::vector<std::int8_t>(3 * volume.data().size(), 0));  // values only
    boundsBytes = ref::serializeDiamondBounds(ref::computeDiamondBounds(field.grid(), field.values()));
  } catch (const std::invalid_argument& e) {
    throw conf::UsageError(e.what());
  } catch (const std::bad_alloc&) {
    throw io::IoError(needText + ": out of memory");
  }
  const double seconds = conf::secondsSince(t0);
  // The stream and its bounds are written together: a failure leaves neither.
  io::writeFilesAtomically({{o.out, stream}, {o.boundsOut, boundsBytes}});
  std::cout << "wrote " << o.out.string() << " in " << seconds << " s\n";
  std::cout << "wrote the diamond bounds into " << o.boundsOut.string() << "\n";
  printInfo(ref::parseLebStream(std::move(stream)), std::cout);
  return 0;
}

namespace {

// What voxref decode says of a stream before it maps anything: its volume, and what the decode needs.
struct DecodePlan {
  ref::Dims3 dims;
  int sampleBits;
  bool hasGradients;
  std::uint64_t need;
  std::string needText;
};

DecodePlan decodePlan(const std::filesystem::path& input, const ref::LebStream& s) {
  const std::uint64_t need = io::lebFileDecodeAddressBytes(s);
  return {s.dims, s.sampleBits, s.hasGradients(), need,
          input.string() + ": decoding needs " + std::to_string(need) + " bytes (" + dimsText(s.dims) +
              " samples and their gradients mapped to files, the stream, and the " +
              std::to_string(ref::LebPadding::shellPoints(s.grid, s.dims)) + " padding points of the " +
              std::to_string(s.grid.pointsPerAxis()) + "^3 grid of k = " + std::to_string(s.grid.k) +
              " that predictions reach)"};
}

DecodePlan decodePlan(const std::filesystem::path& input, const ref::MirroredLebStream& s) {
  const std::uint64_t need = io::lebFileDecodeAddressBytes(s);
  return {s.header.dims, s.header.sampleBits, s.header.hasGradients(), need,
          input.string() + ": decoding needs " + std::to_string(need) + " bytes (" + dimsText(s.header.dims) +
              " samples" + (s.header.hasGradients() ? " and their gradients" : "") +
              " mapped to files, the stream, its " + std::to_string(s.exceptions.size()) +
              " exceptions, and the padding points of the folded " + dimsText(s.inner.dims) +
              " volume's grid that predictions reach)"};
}

}  // namespace

int decodeLebCommand(const DecodeOptions& o) {
  if (o.step) throw conf::UsageError("--step is for the timevarying codec");
  const std::variant<io::LebFile, io::MirroredLebFile> file = io::openAnyLebFile(o.input);
  const DecodePlan plan = std::visit([&](const auto& f) { return decodePlan(o.input, f.stream); }, file);
  if (!o.gradientsOut.empty() && !plan.hasGradients)
    throw conf::UsageError(o.input.string() + " has no gradients (encoded with --no-gradients)");
  // What decoding will map and allocate is known from the header (the stream, the samples and
  // their gradients, the padding that predictions reach): refused here, before any of it is
  // mapped, when it exceeds what this process may still map.
  refuseBeyondAddressSpace(plan.need, plan.needText);
  try {
    conf::Progress progress("voxref decode --codec leb", 1000);
    std::visit(
        [&](const auto& f) {
          io::decodeLebFile(f, o.out, o.gradientsOut, 0, io::kLebWindowBytes, [&](double done, std::string_view step) {
            progress.update(std::lround(1000 * done), step);
          });
        },
        file);
    progress.finish();
  } catch (const std::bad_alloc&) {
    throw io::IoError(plan.needText + ": out of memory");
  }
  std::cout << "decoded " << dimsText(plan.dims) << " uint" << plan.sampleBits << " samples (x fastest) into "
            << o.out.string();
  if (!o.gradientsOut.empty()) std::cout << " and their gradients (3 int8 per sample) into " << o.gradientsOut.string();
  std::cout << "\n";
  return 0;
}

int infoLebCommand(const InfoOptions& o) {
  printAnyInfo(io::openAnyLebFile(o.input), std::cout);
  return 0;
}

}  // namespace voxref::cli
