// voxref encode | decode | info --codec timevarying: the time-varying codec (Binotto et al. 2003).
#include <cstdio>
#include <iostream>

#include "conformance/cli/codecs.h"
#include "conformance/framework/exit_status.h"
#include "conformance/framework/progress.h"
#include "conformance/io/atomic_file.h"
#include "conformance/io/raw_volume.h"
#include "conformance/io/timevarying_file.h"
#include "reference/timevarying/plume.h"

namespace voxref::cli {
namespace {

ref::TimeSeries loadSeries(const EncodeOptions& o) {
  if (o.plume) {
    if (!o.inputs.empty()) throw conf::UsageError("--plume and --input exclude each other");
    // The container's limits (reference/timevarying/FORMAT.md: side 4..512, time_steps 1..65536), checked before the
    // plume is allocated (side^3 bytes per step).
    if (o.plumeSide < 8 || o.plumeSide > 512 || (o.plumeSide & (o.plumeSide - 1)) != 0)
      throw conf::UsageError("--side " + std::to_string(o.plumeSide) +
                             ": expected a power of two in 8..512 (the .vxtv container holds sides up to 512)");
    if (o.plumeSteps < 1 || o.plumeSteps > 65536)
      throw conf::UsageError("--steps " + std::to_string(o.plumeSteps) +
                             ": expected 1..65536 (the .vxtv container's time steps)");
    ref::PlumeOptions p{o.plumeSide, o.plumeSteps};
    if (o.sparseness > 0.0) return ref::dischargePlumeWithSparseness(p, o.sparseness);
    return ref::dischargePlume(p);
  }
  if (o.inputs.empty())
    throw conf::UsageError("give the time steps with --input FILE... (and --dims X Y Z), or --plume");
  if (o.inputs.size() > 65536)  // before any file is read
    throw conf::UsageError(
        "--input: " + std::to_string(o.inputs.size()) +
        " time steps; the .vxtv container holds 1..65536 (reference/timevarying/FORMAT.md, time_steps)");
  if (o.dims.size() != 3) throw conf::UsageError("--dims needs three extents X Y Z");
  if (o.type != "uint8")
    throw conf::UsageError("the timevarying codec takes uint8 volumes (--type uint8), got " + o.type);
  const ref::Dims3 dims{o.dims[0], o.dims[1], o.dims[2]};
  std::vector<ref::Volume<std::uint8_t>> volumes;
  conf::Progress progress("voxref encode: reading", static_cast<long>(o.inputs.size()));
  for (std::size_t i = 0; i < o.inputs.size(); ++i) {
    progress.update(static_cast<long>(i), o.inputs[i].string());
    volumes.push_back(io::readRawVolumeU8(o.inputs[i], dims));
  }
  progress.finish();
  try {
    return ref::padToCube(volumes);
  } catch (const std::invalid_argument& e) {
    throw conf::UsageError("--dims " + dimsText(dims) + ": " +
                           e.what());  // "extent 600 exceeds 512" (the container's largest side)
  }
}

void printInfo(const ref::TimeVaryingFile& f, std::ostream& out) {
  const ref::TimeVaryingLayout& L = f.textures.layout;
  const ref::EncodeStats& s = f.textures.stats;
  const ref::Dims3 cube{L.side, L.side, L.side};
  out << "codec           timevarying (Binotto, Comba, Freitas 2003)\n"
      << "time steps      " << L.timeSteps << " of " << dimsText(L.original);
  if (L.original != cube) out << ", padded with 0 to " << dimsText(cube) << " (padding excluded from the ratios)";
  out << "\nlevel           " << L.level << ": " << L.cells << "^3 cells of " << L.blockSide
      << "^3 voxels per time step\n"
      << "index texture   " << dimsText(f.textures.index.dims) << " " << ref::name(f.textures.index.encoding) << ", "
      << L.indexSlots << "^3 slots\nrefinement      " << dimsText(f.textures.refinement.dims) << " rgba8, "
      << L.blockSlots << "^3 block slots\n"
      << "transfer        " << f.transfer.name << "; alpha-one cells " << s.alphaOneCells << " ("
      << (f.textures.alphaOne == ref::AlphaOnePolicy::Paper
              ? "paper policy: stored as colours, they read as refinement flags"
              : "refined: lossless")
      << ")\ncells           " << s.homogeneousCells << " homogeneous, " << s.refinedCells << " refined\n"
      << "blocks          " << s.distinctBlocks << " distinct, " << s.hashHits << " shared by hash hits, "
      << s.hashCollisions << " hash collisions caught\nindex bytes     " << s.indexBytes << " (allocated "
      << s.indexBytesAllocated << ")\n"
      << "refinement      " << s.refinementBytes << " bytes (allocated " << s.refinementBytesAllocated << ")\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "ratio           %.2f:1 against 4 bytes per voxel, %.2f:1 against 1 byte per voxel\n",
                s.ratioAgainst4Bytes(), s.ratioAgainst1Byte());
  out << buf;
}

}  // namespace

int encodeTimeVaryingCommand(const EncodeOptions& o) {
  if (o.out.extension() != ".vxtv") throw conf::UsageError("--out must name a .vxtv file, got " + o.out.string());
  const ref::TimeSeries series = loadSeries(o);
  ref::TimeVaryingFile f;
  try {
    f.transfer = ref::transferFunction(o.transfer);
  } catch (const std::invalid_argument& e) {
    throw conf::UsageError(e.what());
  }
  ref::TimeVaryingOptions options;
  const auto encoding = ref::parseIndexEncoding(o.encoding);
  if (!encoding)
    throw conf::UsageError("unknown --encoding '" + o.encoding +
                           "' (normalized_rgba8, normalized_rgba16, normalized_float, block_rgba8)");
  options.encoding = *encoding;
  if (o.alphaOne != "refine" && o.alphaOne != "paper") throw conf::UsageError("--alpha-one must be refine or paper");
  options.alphaOne = o.alphaOne == "paper" ? ref::AlphaOnePolicy::Paper : ref::AlphaOnePolicy::Refine;
  try {
    if (o.level == "auto") {
      f.textures = ref::encodeTimeVaryingAutoLevel(series, f.transfer, options);
    } else {
      try {
        options.level = std::stoi(o.level);
      } catch (const std::exception&) {
        throw conf::UsageError("--level must be a number or auto, got '" + o.level + "'");
      }
      f.textures = ref::encodeTimeVarying(series, f.transfer, options);
    }
  } catch (const std::invalid_argument& e) {
    throw conf::UsageError(e.what());
  }
  io::writeTimeVarying(o.out, f);
  std::cout << "wrote " << o.out.string() << "\n";
  printInfo(f, std::cout);
  return 0;
}

int decodeTimeVaryingCommand(const DecodeOptions& o) {
  const ref::TimeVaryingFile f = io::readTimeVarying(o.input);
  const int steps = f.textures.layout.timeSteps;
  if (o.step && (*o.step < 0 || *o.step >= steps))
    throw conf::UsageError("--step " + std::to_string(*o.step) + " is outside 0.." + std::to_string(steps - 1) +
                           " (the time steps of " + o.input.string() + ")");
  io::ensureDirectory(o.out);  // only once the input and the options are known to be good
  const int first = o.step.value_or(0), last = o.step ? *o.step : steps - 1;
  conf::Progress progress("voxref decode", last - first + 1);
  for (int t = first; t <= last; ++t) {
    progress.update(t - first);
    const std::vector<ref::Rgba8> voxels = ref::decodeStep(f.textures, t);
    char name[32];
    std::snprintf(name, sizeof name, "step_%03d.rgba", t);
    io::writeFileAtomically(o.out / name,
                            std::string_view(reinterpret_cast<const char*>(voxels.data()), voxels.size() * 4));
  }
  progress.finish();
  std::cout << "decoded " << (last - first + 1) << " time step(s) of " << dimsText(f.textures.layout.original)
            << " RGBA8 voxels (x fastest) into " << o.out.string() << "\n";
  return 0;
}

int infoTimeVaryingCommand(const InfoOptions& o) {
  printInfo(io::readTimeVarying(o.input), std::cout);
  return 0;
}

}  // namespace voxref::cli
