#include "conformance/io/leb_file_codec.h"

#include <fcntl.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <memory>
#include <optional>
#include <vector>

#include "conformance/io/atomic_file.h"
#include "conformance/io/mapped_file.h"
#include "reference/common/byte_stream.h"
#include "reference/leb/gradients.h"

namespace voxref::io {
namespace {

// 16-bit samples are read and written in place as the file's little-endian words.
static_assert(std::endian::native == std::endian::little, "the LEB file codec maps uint16 little endian in place");

std::uint64_t bytesPerSample(VoxelType t) { return t == VoxelType::UInt8 ? 1 : 2; }

// A temporary file for `destination` (the gradients of an encode, the gradients nobody asked for
// of a decode) in the folder of its temporary output (beside it, or the system's temporary folder
// for a device or pipe: atomic_file.h), removed when this goes out of scope or the process is
// ended by a signal (temporary_files.h).
class ScratchFile {
 public:
  ScratchFile(const AtomicOutput& output, const std::filesystem::path& destination, const std::string& what)
      : path_(output.temporary().parent_path() /
              ("." + destination.filename().string() + ".tmp" + std::to_string(::getpid()) + "." + what)),
        guard_(path_) {}
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  ~ScratchFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  TemporaryFileGuard guard_;
};

// The samples of `input`: mapped, or for a ".gz" inflated into `held`.
struct InputSamples {
  std::optional<MappedFile> mapped;
  ref::Volume<std::uint8_t> held8;
  ref::Volume<std::uint16_t> held16;
  const std::uint8_t* data8 = nullptr;
  const std::uint16_t* data16 = nullptr;
};

InputSamples inputSamples(const std::filesystem::path& input, const ref::Dims3& dims, VoxelType type) {
  const std::uint64_t need = voxelsOf(input, dims) * bytesPerSample(type);
  InputSamples in;
  requireVolumeFile(input);
  if (isGzipFile(input)) {  // as the raw volume readers do, by content
    if (type == VoxelType::UInt8) {
      in.held8 = readRawVolumeU8(input, dims);
      in.data8 = in.held8.data().data();
    } else {
      in.held16 = readRawVolumeU16(input, dims);
      in.data16 = in.held16.data().data();
    }
    return in;
  }
  in.mapped = MappedFile::openRead(input);  // a regular file, checked above
  requireVolumeSize(input, in.mapped->size(), need);
  if (type == VoxelType::UInt8)
    in.data8 = in.mapped->data();
  else
    in.data16 = reinterpret_cast<const std::uint16_t*>(in.mapped->data());
  return in;
}

// The gradients of the samples into `file` (3 bytes a sample), slice by slice, in parallel over
// batches of slices with the window between batches.
template <class T>
void writeGradients(const T* samples, const ref::Dims3& d, MappedFile& file, int threads, ResidentWindow& window,
                    const LebProgress& progress) {
  ref::quantizedGradientsInto(samples, d, reinterpret_cast<std::int8_t*>(file.data()), threads, [&](double done) {
    window();
    if (progress) progress(done, "gradients");
  });
}

// Writes at offsets into a file it created; throws IoError naming the destination.
class PositionedFile {
 public:
  PositionedFile(const std::filesystem::path& path, const std::filesystem::path& destination)
      : destination_(destination), fd_(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)) {
    if (fd_ < 0) fail(errno);
  }
  PositionedFile(const PositionedFile&) = delete;
  PositionedFile& operator=(const PositionedFile&) = delete;
  ~PositionedFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  void write(std::uint64_t offset, std::string_view bytes) {
    while (!bytes.empty()) {
      const ssize_t n = ::pwrite(fd_, bytes.data(), bytes.size(), static_cast<off_t>(offset));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) fail(n < 0 ? errno : EIO);
      bytes.remove_prefix(static_cast<std::size_t>(n));
      offset += static_cast<std::uint64_t>(n);
    }
  }
  void close() {
    const int fd = fd_;
    fd_ = -1;
    if (::fsync(fd) != 0 || ::close(fd) != 0) fail(errno);
  }

 private:
  [[noreturn]] void fail(int err) const {
    throw IoError("cannot write " + destination_.string() + ": " + std::strerror(err));
  }
  std::filesystem::path destination_;
  int fd_;
};

std::vector<MappedFile*> present(std::initializer_list<MappedFile*> files) {
  std::vector<MappedFile*> v;
  for (MappedFile* f : files)
    if (f) v.push_back(f);
  return v;
}

// Writes a stream through `encode` (handed the write of each part at its offset) into the temporary
// file of `output`, then syncs it and renames it into place; returns the stream's size.
template <class Encode>
std::uint64_t writeStreamFile(AtomicOutput& output, const std::filesystem::path& out, Encode&& encode) {
  PositionedFile file(output.temporary(), out);
  const std::uint64_t size = encode([&](std::uint64_t offset, std::string_view bytes) { file.write(offset, bytes); });
  file.close();
  output.commit();
  return size;
}

}  // namespace

std::uint64_t lebFileEncodeAddressBytes(const ref::Dims3& dims, VoxelType type, const ref::LebEncodeOptions& o) {
  const std::uint64_t samples = ref::sampleCount(dims);
  return samples * bytesPerSample(type) + (ref::lebStoresGradients(o) ? 3 * samples : 0) +
         ref::lebEncodeToMemoryBytes(dims, o);
}

LebFileRun encodeLebFile(const std::filesystem::path& input, const ref::Dims3& dims, VoxelType type,
                         const std::filesystem::path& out, const ref::LebEncodeOptions& options, std::uint64_t budget,
                         const LebProgress& progress, const LebFileMirror& mirror) {
  InputSamples in = inputSamples(input, dims, type);
  AtomicOutput output(out);
  const int bits = type == VoxelType::UInt8 ? 8 : 16;
  ref::requireLebMirrorPlanes(dims, mirror.planes);
  LebFileRun run;
  std::optional<ScratchFile> gradientsFile;
  std::optional<MappedFile> gradients;
  if (ref::lebStoresGradients(options)) {  // a stream that derives them needs none
    gradientsFile.emplace(output, out, "gradients");
    gradients = MappedFile::create(gradientsFile->path(), 3 * ref::sampleCount(dims), out);
    // Written here and read back by the encoder under the window: with the kernel's read-around,
    // faults on it brought in far more than they touched, faster than the window's looks could
    // drop (adviseNoReadAround).
    gradients->adviseNoReadAround();
  }
  std::int8_t* g = gradients ? reinterpret_cast<std::int8_t*>(gradients->data()) : nullptr;
  run.mirrorPlanes = mirror.planes;
  {
    ResidentWindow window(budget, present({in.mapped ? &*in.mapped : nullptr, gradients ? &*gradients : nullptr}));
    if (gradients) {
      if (in.data8)
        writeGradients(in.data8, dims, *gradients, options.threads, window, progress);
      else
        writeGradients(in.data16, dims, *gradients, options.threads, window, progress);
    }
    if (mirror.find) {  // with the gradients to be stored, since they are folded too
      if (progress) progress(0, "finding mirror planes");
      run.mirrorPlanes =
          in.data8 ? ref::findLebMirrorPlanes(in.data8, g, dims) : ref::findLebMirrorPlanes(in.data16, g, dims);
    }
    run.trims += window.trims();
  }
  // The next window counts from what is resident when it opens: nothing of these, then.
  if (in.mapped) in.mapped->trim();
  if (gradients) gradients->trim();
  // With mirror planes, the folded volume (and its gradients) into scratch files, then its stream
  // behind the mirror's header.
  const bool fold = run.mirrorPlanes.any();
  const ref::Dims3 f = ref::lebFoldedDims(dims, run.mirrorPlanes);
  std::optional<ScratchFile> foldedFile, foldedGradientsFile;
  std::optional<MappedFile> folded, foldedGradients;
  if (fold) {
    foldedFile.emplace(output, out, "folded");
    folded = MappedFile::create(foldedFile->path(), ref::sampleCount(f) * bytesPerSample(type), out);
    if (gradients) {
      foldedGradientsFile.emplace(output, out, "folded-gradients");
      foldedGradients = MappedFile::create(foldedGradientsFile->path(), 3 * ref::sampleCount(f), out);
    }
  }
  ResidentWindow window(budget, present({in.mapped ? &*in.mapped : nullptr, gradients ? &*gradients : nullptr,
                                         folded ? &*folded : nullptr, foldedGradients ? &*foldedGradients : nullptr}));
  std::vector<ref::LebMirrorException> exceptions;
  if (fold) {
    if (progress) progress(0, "folding");
    auto* fg = foldedGradients ? reinterpret_cast<std::int8_t*>(foldedGradients->data()) : nullptr;
    exceptions = in.data8 ? ref::foldLebVolume(in.data8, g, dims, run.mirrorPlanes, folded->data(), fg)
                          : ref::foldLebVolume(in.data16, g, dims, run.mirrorPlanes, bits,
                                               reinterpret_cast<std::uint16_t*>(folded->data()), fg);
    window();
    run.mirrorExceptions = exceptions.size();
  }
  ref::LebEncodeOptions o = options;
  o.window = [&](double done) {
    window();
    if (progress) progress(done, fold ? "encoding the folded volume" : "encoding");
  };
  const std::uint8_t* data8 = !in.data8 ? nullptr : fold ? folded->data() : in.data8;
  const std::uint16_t* data16 = !in.data16 ? nullptr
                                : fold     ? reinterpret_cast<const std::uint16_t*>(folded->data())
                                           : in.data16;
  const std::int8_t* spanGradients = !fold             ? g
                                     : foldedGradients ? reinterpret_cast<const std::int8_t*>(foldedGradients->data())
                                                       : nullptr;
  const ref::LebVolumeIn span{f, bits, data8, data16, spanGradients};
  run.streamBytes = writeStreamFile(output, out, [&](const ref::LebStreamWrite& write) {
    return fold ? ref::encodeMirroredLebTo(span, {dims, bits, run.mirrorPlanes, ref::LebMirrorGradients::None},
                                           exceptions, o, write)
                : ref::encodeLebTo(span, o, write);
  });
  run.trims += window.trims();
  return run;
}

std::uint64_t lebFileDecodeAddressBytes(const ref::LebStream& s) {
  const std::uint64_t samples = ref::sampleCount(s.dims);
  return s.bytes.size() + samples * static_cast<std::uint64_t>(s.sampleBits / 8) +
         (s.hasGradients() ? 3 * samples : 0) + ref::lebDecodeShellBytes(s);
}

std::uint64_t lebFileDecodeAddressBytes(const ref::MirroredLebStream& s) {
  const std::uint64_t samples = ref::sampleCount(s.header.dims);
  return s.streamBytes + samples * static_cast<std::uint64_t>(s.header.sampleBits / 8) +
         (s.header.hasGradients() ? 3 * samples : 0) + ref::lebDecodeShellBytes(s.inner) +
         s.exceptions.size() * sizeof(ref::LebMirrorException);
}

namespace {

// What a decode into files needs to know of its stream.
struct DecodeTarget {
  MappedFile& input;
  ref::Dims3 dims;
  int sampleBits = 8;
  bool hasGradients = false;     // a decoder gives gradients (stored or derived)
  bool storesGradients = false;  // a gradients channel, decoded (and so checked) whether wanted or not
};

// The outputs of a decode (the samples, the gradients when wanted or stored) mapped from temporary
// files, `decode` run into them under the window, then both renamed into place.
template <class Decode>
LebFileRun decodeToFiles(const DecodeTarget& t, const std::filesystem::path& out,
                         const std::filesystem::path& gradientsOut, std::uint64_t budget, const LebProgress& progress,
                         Decode&& decode) {
  if (!gradientsOut.empty() && !t.hasGradients)
    throw std::invalid_argument(t.input.path().string() + " has no gradients (encoded with --no-gradients)");
  // A gradients channel is decoded whether wanted or not (into a scratch file when not); derived
  // gradients are computed only when wanted.
  const bool gradientsMapped = t.storesGradients || !gradientsOut.empty();
  if (!gradientsOut.empty() && std::filesystem::weakly_canonical(out).lexically_normal() ==
                                   std::filesystem::weakly_canonical(gradientsOut).lexically_normal())
    throw IoError("cannot write " + gradientsOut.string() + " twice: two outputs name the same file");
  const std::uint64_t samples = ref::sampleCount(t.dims);
  AtomicOutput dataOut(out);
  MappedFile data =
      MappedFile::create(dataOut.temporary(), samples * static_cast<std::uint64_t>(t.sampleBits / 8), out);
  std::optional<AtomicOutput> gradientsOutput;
  std::optional<ScratchFile> scratch;
  std::optional<MappedFile> gradients;
  if (gradientsMapped) {
    std::filesystem::path at, named = gradientsOut;
    if (!gradientsOut.empty()) {
      gradientsOutput.emplace(gradientsOut);
      at = gradientsOutput->temporary();
    } else {
      scratch.emplace(dataOut, out, "gradients");
      at = scratch->path();
      named = out;
    }
    gradients = MappedFile::create(at, 3 * samples, named);
  }
  ResidentWindow window(budget, present({&t.input, &data, gradients ? &*gradients : nullptr}));
  const ref::LebVolumeOut span{t.dims, t.sampleBits, t.sampleBits == 8 ? data.data() : nullptr,
                               t.sampleBits == 8 ? nullptr : reinterpret_cast<std::uint16_t*>(data.data()),
                               gradients ? reinterpret_cast<std::int8_t*>(gradients->data()) : nullptr};
  try {
    decode(span, [&](double done) {
      window();
      if (progress) progress(done, "decoding");
    });
  } catch (const ref::StreamError& e) {
    throw FormatError(t.input.path().string() + ": " + e.what());
  }
  data.flush();
  if (gradientsOutput) gradients->flush();
  dataOut.commit();
  if (gradientsOutput) gradientsOutput->commit();
  return {t.input.size(), window.trims()};
}

}  // namespace

LebFileRun decodeLebFile(const LebFile& input, const std::filesystem::path& out,
                         const std::filesystem::path& gradientsOut, int threads, std::uint64_t budget,
                         const LebProgress& progress) {
  const ref::LebStream& s = input.stream;
  return decodeToFiles(
      {*input.file, s.dims, s.sampleBits, s.hasGradients(), s.channel(ref::LebChannelKind::Gradients) != nullptr}, out,
      gradientsOut, budget, progress, [&](const ref::LebVolumeOut& span, const ref::LebWindow& window) {
        ref::decodeLebInto(s, span, threads, window);
      });
}

LebFileRun decodeLebFile(const MirroredLebFile& input, const std::filesystem::path& out,
                         const std::filesystem::path& gradientsOut, int threads, std::uint64_t budget,
                         const LebProgress& progress) {
  const ref::MirroredLebStream& s = input.stream;
  return decodeToFiles(
      {*input.file, s.header.dims, s.header.sampleBits, s.header.hasGradients(), s.header.storedGradients()}, out,
      gradientsOut, budget, progress, [&](const ref::LebVolumeOut& span, const ref::LebWindow& window) {
        ref::decodeMirroredLebInto(s, span, threads, window);
      });
}

}  // namespace voxref::io
