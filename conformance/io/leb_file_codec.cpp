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

}  // namespace

std::uint64_t lebFileEncodeAddressBytes(const ref::Dims3& dims, VoxelType type, const ref::LebEncodeOptions& o) {
  const std::uint64_t samples = ref::sampleCount(dims);
  return samples * bytesPerSample(type) + (ref::lebStoresGradients(o) ? 3 * samples : 0) +
         ref::lebEncodeToMemoryBytes(dims, o);
}

LebFileRun encodeLebFile(const std::filesystem::path& input, const ref::Dims3& dims, VoxelType type,
                         const std::filesystem::path& out, const ref::LebEncodeOptions& options, std::uint64_t budget,
                         const LebProgress& progress) {
  InputSamples in = inputSamples(input, dims, type);
  AtomicOutput output(out);
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
  ResidentWindow window(budget, present({in.mapped ? &*in.mapped : nullptr, gradients ? &*gradients : nullptr}));
  if (gradients) {
    if (in.data8)
      writeGradients(in.data8, dims, *gradients, options.threads, window, progress);
    else
      writeGradients(in.data16, dims, *gradients, options.threads, window, progress);
  }
  ref::LebEncodeOptions o = options;
  o.window = [&](double done) {
    window();
    if (progress) progress(done, "encoding");
  };
  const ref::LebVolumeIn span{dims, type == VoxelType::UInt8 ? 8 : 16, in.data8, in.data16,
                              gradients ? reinterpret_cast<const std::int8_t*>(gradients->data()) : nullptr};
  PositionedFile file(output.temporary(), out);
  LebFileRun run;
  run.streamBytes =
      ref::encodeLebTo(span, o, [&](std::uint64_t offset, std::string_view bytes) { file.write(offset, bytes); });
  file.close();
  output.commit();
  run.trims = window.trims();
  return run;
}

std::uint64_t lebFileDecodeAddressBytes(const ref::LebStream& s) {
  const std::uint64_t samples = ref::sampleCount(s.dims);
  return s.bytes.size() + samples * static_cast<std::uint64_t>(s.sampleBits / 8) +
         (s.hasGradients() ? 3 * samples : 0) + ref::lebDecodeShellBytes(s);
}

LebFileRun decodeLebFile(const LebFile& input, const std::filesystem::path& out,
                         const std::filesystem::path& gradientsOut, int threads, std::uint64_t budget,
                         const LebProgress& progress) {
  const ref::LebStream& s = input.stream;
  if (!gradientsOut.empty() && !s.hasGradients())
    throw std::invalid_argument(input.file->path().string() + " has no gradients (encoded with --no-gradients)");
  // A gradients channel is decoded whether wanted or not (into a scratch file when not); derived
  // gradients are computed only when wanted.
  const bool hasGradients = s.channel(ref::LebChannelKind::Gradients) != nullptr || !gradientsOut.empty();
  if (!gradientsOut.empty() && std::filesystem::weakly_canonical(out).lexically_normal() ==
                                   std::filesystem::weakly_canonical(gradientsOut).lexically_normal())
    throw IoError("cannot write " + gradientsOut.string() + " twice: two outputs name the same file");
  const std::uint64_t samples = ref::sampleCount(s.dims);
  AtomicOutput dataOut(out);
  MappedFile data =
      MappedFile::create(dataOut.temporary(), samples * static_cast<std::uint64_t>(s.sampleBits / 8), out);
  std::optional<AtomicOutput> gradientsOutput;
  std::optional<ScratchFile> scratch;
  std::optional<MappedFile> gradients;
  if (hasGradients) {
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
  ResidentWindow window(budget, present({input.file.get(), &data, gradients ? &*gradients : nullptr}));
  const ref::LebVolumeOut span{s.dims, s.sampleBits, s.sampleBits == 8 ? data.data() : nullptr,
                               s.sampleBits == 8 ? nullptr : reinterpret_cast<std::uint16_t*>(data.data()),
                               gradients ? reinterpret_cast<std::int8_t*>(gradients->data()) : nullptr};
  try {
    ref::decodeLebInto(s, span, threads, [&](double done) {
      window();
      if (progress) progress(done, "decoding");
    });
  } catch (const ref::StreamError& e) {
    throw FormatError(input.file->path().string() + ": " + e.what());
  }
  data.flush();
  if (gradientsOutput) gradients->flush();
  dataOut.commit();
  if (gradientsOutput) gradientsOutput->commit();
  return {s.bytes.size(), window.trims()};
}

}  // namespace voxref::io
