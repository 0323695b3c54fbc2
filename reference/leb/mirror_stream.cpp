// Mirrored LEB streams: FORMAT.md beside this file, "Mirrored streams", section by section.
#include "reference/leb/mirror_stream.h"

#include <array>
#include <bit>
#include <stdexcept>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/leb/context_codec.h"
#include "reference/leb/delta_decisions.h"
#include "reference/leb/gradients.h"
#include "reference/leb/range_coder.h"

namespace voxref::ref {
namespace {

constexpr char kMagic[4] = {'V', 'X', 'L', 'M'};
constexpr std::size_t kExceptionsCrcAt = 68, kHeaderCrcAt = 72;

// The models of the exceptions' decisions (FORMAT.md, "Mirrored streams", the exceptions): the
// width of each gap down a tree of six levels, the residual as the adaptive coder's decisions in
// one context, and the gradient's residuals (stored gradients) in one context a component.
struct ExceptionModels {
  std::array<BitModel, 64> width{};  // nodes 1..63
  DeltaDecisionModels residual, gradient;
  explicit ExceptionModels(int sampleBits) : residual(sampleBits, 1, 1), gradient(8, 3, 3) {}
};

// A residual of `bits` bits (modulo 2^bits) as the signed value the decisions code, and back.
struct SignedResidual {
  int symbol = 0, negative = 0;
  std::uint32_t magnitude = 0;
};
SignedResidual signedResidual(std::uint32_t r, int bits) {
  const std::uint32_t half = 1u << (bits - 1);
  const std::int64_t d = r >= half ? std::int64_t{r} - 2 * std::int64_t{half} : r;
  const auto magnitude = static_cast<std::uint32_t>(d < 0 ? -d : d);
  return {static_cast<int>(std::bit_width(magnitude)), d < 0 ? 1 : 0, magnitude};
}
std::int64_t signedValue(const SignedResidual& v) {
  return v.negative ? -std::int64_t{v.magnitude} : std::int64_t{v.magnitude};
}

// One exception's decisions, for the encoder and the decoder alike: g = gap + 1 (>= 1; the gap is
// the points skipped since the previous exception, or since the volume's first point) by its bit
// width down the tree of six levels (codeByBitWidth); then the residual as a signed value
// (delta_decisions.h); then, with stored gradients, each component's residual the same way. Returns
// g and sets the residuals (decoding), or codes those given (encoding).
template <class Bits>
std::uint64_t codeException(Bits bits, ExceptionModels& m, bool gradients, std::uint64_t g, SignedResidual& residual,
                            std::array<SignedResidual, 3>& gradient) {
  const std::uint64_t v = codeByBitWidth(
      bits, [&](int node) -> BitModel& { return m.width[static_cast<std::size_t>(node)]; }, 6, g);
  residual.symbol = codeDeltaDecisions(bits, m.residual, 0, 0, residual.symbol, residual.negative, residual.magnitude);
  if (gradients)
    for (int c = 0; c < 3; ++c) {
      SignedResidual& r = gradient[static_cast<std::size_t>(c)];
      r.symbol = codeDeltaDecisions(bits, m.gradient, c, c, r.symbol, r.negative, r.magnitude);
    }
  return v;
}

// What is wrong with exception e, the next after the points before `after`, or an empty string.
std::string exceptionFault(const LebMirrorHeader& h, std::uint64_t after, const LebMirrorException& e) {
  const Dims3& d = h.dims;
  if (e.index < after || e.index >= sampleCount(d))
    return "index " + std::to_string(e.index) + " is not after the previous exception inside the volume's " +
           std::to_string(sampleCount(d)) + " points";
  const std::uint64_t x = e.index % static_cast<std::uint64_t>(d[0]);
  const std::uint64_t y = (e.index / static_cast<std::uint64_t>(d[0])) % static_cast<std::uint64_t>(d[1]);
  const std::uint64_t z = e.index / (static_cast<std::uint64_t>(d[0]) * static_cast<std::uint64_t>(d[1]));
  if (!lebMirroredCoordinate(static_cast<int>(x), h.planes.sum[0]) &&
      !lebMirroredCoordinate(static_cast<int>(y), h.planes.sum[1]) &&
      !lebMirroredCoordinate(static_cast<int>(z), h.planes.sum[2]))
    return "point (" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
           ") is kept, not mirrored: it has no image to differ from";
  if (e.residual >= (1u << h.sampleBits))
    return "residual " + std::to_string(e.residual) + " is not in 0.." + std::to_string((1u << h.sampleBits) - 1);
  if (!h.storedGradients() && e.gradient != std::array<std::uint8_t, 3>{})
    return "a gradient residual in a stream that stores no gradients";
  if (e.residual == 0 && e.gradient == std::array<std::uint8_t, 3>{})
    return h.storedGradients() ? "its sample and gradient equal their image's: it is no exception"
                               : "residual 0: its sample equals its image's, it is no exception";
  return {};
}

std::string exceptionBytes(const LebMirrorHeader& h, const std::vector<LebMirrorException>& exceptions) {
  if (exceptions.empty()) return {};
  RangeEncoder enc;
  ExceptionModels m(h.sampleBits);
  std::uint64_t after = 0;
  for (const LebMirrorException& e : exceptions) {
    if (const std::string fault = exceptionFault(h, after, e); !fault.empty())
      throw std::invalid_argument("mirror exception: " + fault);
    SignedResidual residual = signedResidual(e.residual, h.sampleBits);
    std::array<SignedResidual, 3> gradient;
    for (int c = 0; c < 3; ++c) gradient[c] = signedResidual(e.gradient[c], 8);
    codeException(EncodeBits{enc}, m, h.storedGradients(), e.index - after + 1, residual, gradient);
    after = e.index + 1;
  }
  return enc.finish();
}

std::vector<LebMirrorException> decodeExceptions(const LebMirrorHeader& h, std::uint64_t count, std::string_view bytes,
                                                 std::size_t at) {
  std::vector<LebMirrorException> out;
  if (count == 0) return out;
  RangeDecoder dec(bytes);
  if (!dec.firstByteValid()) ByteReader::fail(at, "exceptions: the first byte of a range-coded part must be 0");
  ExceptionModels m(h.sampleBits);
  const std::uint64_t points = sampleCount(h.dims);
  const std::int64_t half = std::int64_t{1} << (h.sampleBits - 1);
  std::uint64_t after = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    SignedResidual residual;
    std::array<SignedResidual, 3> gradient;
    const std::uint64_t g = codeException(DecodeBits{dec}, m, h.storedGradients(), 0, residual, gradient);
    if (dec.overrun())
      ByteReader::fail(at, "exceptions: the " + std::to_string(bytes.size()) + " bytes end inside exception " +
                               std::to_string(i) + " of " + std::to_string(count));
    if (g - 1 >= points - after)
      ByteReader::fail(at, "exceptions: exception " + std::to_string(i) + " lies past the volume's " +
                               std::to_string(points) + " points");
    const std::int64_t d = signedValue(residual);
    if (d < -half || d >= half)
      ByteReader::fail(at, "exceptions: exception " + std::to_string(i) + " has residual " + std::to_string(d) +
                               ", expected a value in " + std::to_string(-half) + ".." + std::to_string(half - 1));
    LebMirrorException e{after + g - 1, static_cast<std::uint32_t>(d & (2 * half - 1)), {}};
    for (int c = 0; c < 3; ++c) {
      const std::int64_t dc = signedValue(gradient[c]);
      if (dc < -128 || dc > 127)
        ByteReader::fail(at, "exceptions: exception " + std::to_string(i) + " has gradient residual " +
                                 std::to_string(dc) + " in component " + std::to_string(c) +
                                 ", expected a value in -128..127");
      e.gradient[c] = static_cast<std::uint8_t>(dc & 255);
    }
    if (const std::string fault = exceptionFault(h, after, e); !fault.empty())
      ByteReader::fail(at, "exceptions: exception " + std::to_string(i) + ": " + fault);
    out.push_back(e);
    after = e.index + 1;
  }
  if (dec.consumed() != bytes.size())
    ByteReader::fail(at, "exceptions_bytes: " + std::to_string(bytes.size()) + " bytes, but the " +
                             std::to_string(count) + " exceptions take " + std::to_string(dec.consumed()));
  return out;
}

std::string headerBytes(const LebMirrorHeader& h, std::uint64_t exceptionCount, std::string_view exceptions,
                        std::uint64_t totalBytes) {
  ByteWriter w;
  w.bytes(kMagic, 4);
  w.le<std::uint16_t>(kLebMirrorVersion);
  w.le<std::uint8_t>(static_cast<std::uint8_t>(h.sampleBits));
  w.le<std::uint8_t>(static_cast<std::uint8_t>(h.gradients));
  for (int a = 0; a < 3; ++a) w.le<std::uint32_t>(static_cast<std::uint32_t>(h.dims[a]));
  for (int a = 0; a < 3; ++a) w.le<std::uint64_t>(static_cast<std::uint64_t>(h.planes.sum[a]));
  w.le<std::uint64_t>(exceptionCount);
  w.le<std::uint64_t>(exceptions.size());
  w.le<std::uint64_t>(totalBytes);
  w.le<std::uint32_t>(crc32(exceptions));
  w.le<std::uint32_t>(crc32(w.str()));
  return std::move(w.str());
}

// A StreamError of the folded stream, its offset moved to the whole stream's.
StreamError inWholeStream(const StreamError& e, std::size_t innerOffset) {
  const std::string prefix = "offset " + std::to_string(e.offset()) + ": ";
  std::string detail = e.what();
  if (detail.rfind(prefix, 0) == 0) detail.erase(0, prefix.size());
  return StreamError(e.offset() + innerOffset, "folded stream: " + detail);
}

}  // namespace

bool isMirroredLebStream(std::string_view bytes) { return bytes.substr(0, 4) == std::string_view(kMagic, 4); }

std::uint64_t encodeMirroredLebTo(const LebVolumeIn& folded, const LebMirrorHeader& h,
                                  const std::vector<LebMirrorException>& exceptions, const LebEncodeOptions& options,
                                  const LebStreamWrite& write) {
  if (!h.planes.any()) throw std::invalid_argument("a mirrored stream folds at least one axis: no mirror plane given");
  requireLebMirrorPlanes(h.dims, h.planes);
  if (folded.dims != lebFoldedDims(h.dims, h.planes) || folded.sampleBits != h.sampleBits)
    throw std::invalid_argument("the folded volume is " + dimsText(folded.dims) + ", expected " +
                                dimsText(lebFoldedDims(h.dims, h.planes)));
  LebMirrorHeader header = h;
  header.gradients = !options.gradients            ? LebMirrorGradients::None
                     : lebStoresGradients(options) ? LebMirrorGradients::Stored
                                                   : LebMirrorGradients::Derived;
  if (header.storedGradients() && folded.gradients == nullptr)
    throw std::invalid_argument("a mirrored stream that stores its gradients needs the folded volume's gradients");
  if (exceptions.size() > lebMirrorExceptionCap(h.dims, h.planes, header.storedGradients()))
    throw std::invalid_argument(
        "more exceptions than one in " +
        std::to_string(header.storedGradients() ? kLebMirrorGradientExceptionShare : kLebMirrorExceptionShare) +
        " mirrored points");
  const std::string coded = exceptionBytes(header, exceptions);
  const std::uint64_t base = kLebMirrorHeaderBytes + coded.size();
  write(kLebMirrorHeaderBytes, coded);
  LebEncodeOptions inner = options;  // derived gradients are the unfolded volume's: the folded stream has none
  inner.gradients = header.storedGradients();
  inner.deriveGradients = false;
  const std::uint64_t total = base + encodeLebTo(folded, inner, [&](std::uint64_t offset, std::string_view bytes) {
                                write(base + offset, bytes);
                              });
  write(0, headerBytes(header, exceptions.size(), coded, total));
  return total;
}

std::string encodeMirroredLeb(const Volume<std::uint16_t>& volume, int sampleBits, const LebMirrorPlanes& planes,
                              const LebEncodeOptions& options, const std::vector<std::int8_t>& gradients) {
  if (sampleBits != 8 && sampleBits != 16) throw std::invalid_argument("sample bits must be 8 or 16");
  const Dims3 d = volume.dims();
  requireLebMirrorPlanes(d, planes);
  const bool stored = lebStoresGradients(options);
  if (stored && !gradients.empty() && gradients.size() != 3 * sampleCount(d))
    throw std::invalid_argument("encodeMirroredLeb: " + std::to_string(gradients.size()) + " gradient components for " +
                                std::to_string(sampleCount(d)) + " samples");
  const std::vector<std::int8_t> own =
      stored && gradients.empty() ? quantizedGradients(volume) : std::vector<std::int8_t>{};
  const std::int8_t* g = !stored ? nullptr : gradients.empty() ? own.data() : gradients.data();
  Volume<std::uint16_t> folded(lebFoldedDims(d, planes));
  std::vector<std::int8_t> foldedGradients(g ? 3 * sampleCount(folded.dims()) : 0);
  const std::vector<LebMirrorException> exceptions = foldLebVolume(
      volume.data().data(), g, d, planes, sampleBits, folded.data().data(), g ? foldedGradients.data() : nullptr);
  const LebVolumeIn span{folded.dims(), sampleBits, nullptr, folded.data().data(),
                         g ? foldedGradients.data() : nullptr};
  std::string out;
  encodeMirroredLebTo(span, {d, sampleBits, planes, LebMirrorGradients::None}, exceptions, options,
                      [&](std::uint64_t offset, std::string_view bytes) {
                        if (out.size() < offset + bytes.size()) out.resize(offset + bytes.size());
                        out.replace(offset, bytes.size(), bytes);
                      });
  return out;
}

MirroredLebStream parseMirroredLebStream(std::string bytes) {
  auto owner = std::make_shared<const std::string>(std::move(bytes));
  const std::string_view view = *owner;
  return parseMirroredLebStream(view, std::move(owner));
}

MirroredLebStream parseMirroredLebStream(std::string_view b, std::shared_ptr<const void> owner) {
  MirroredLebStream m;
  LebMirrorHeader& h = m.header;
  ByteReader r(b);
  if (r.take(4, "magic") != std::string_view(kMagic, 4))
    r.fail(0, "magic: expected 'VXLM' (not a mirrored LEB stream)");
  r.need(kLebMirrorHeaderBytes - 4, "header");
  if (!crc32Matches(b.substr(0, kHeaderCrcAt), static_cast<std::uint32_t>(loadLe(b.data() + kHeaderCrcAt, 4))))
    r.fail(kHeaderCrcAt, "header_crc: CRC-32 mismatch (the header is corrupt)");
  r.le<std::uint16_t>("version", kLebMirrorVersion, kLebMirrorVersion);
  const std::size_t bitsAt = r.offset();
  h.sampleBits = r.le<std::uint8_t>("sample_bits");
  if (h.sampleBits != 8 && h.sampleBits != 16)
    r.fail(bitsAt, "sample_bits: expected 8 or 16, got " + std::to_string(h.sampleBits));
  h.gradients = static_cast<LebMirrorGradients>(r.le<std::uint8_t>("gradients", 0, 2));
  const auto maxExtent = static_cast<std::uint64_t>(LebGrid{kMaxLebK}.pointsPerAxis());
  for (int a = 0; a < 3; ++a) h.dims[a] = static_cast<int>(r.le<std::uint32_t>("extent", 1, maxExtent));
  for (int a = 0; a < 3; ++a) {
    const std::size_t at = r.offset();
    h.planes.sum[a] = static_cast<std::int64_t>(r.le<std::uint64_t>("mirror_sum"));
    if (h.planes.sum[a] != kNoLebMirror && !lebMirrorSumValid(h.planes.sum[a], h.dims[a]))
      r.fail(at, std::string("mirror_sum: ") + "xyz"[a] + ": expected -1 (none) or 1.." +
                     std::to_string(2 * std::int64_t{h.dims[a]} - 3) + " for an extent of " +
                     std::to_string(h.dims[a]) + ", got " + std::to_string(h.planes.sum[a]));
  }
  if (!h.planes.any()) r.fail(20, "mirror_sum: no axis is mirrored (a mirrored stream folds one at least)");
  const std::uint64_t cap = lebMirrorExceptionCap(h.dims, h.planes, h.storedGradients());
  const std::uint64_t count = r.le<std::uint64_t>("exception_count", 0, cap);
  const std::size_t exceptionBytesAt = r.offset();
  m.exceptionBytes = r.le<std::uint64_t>("exceptions_bytes");
  const std::size_t totalAt = r.offset();
  m.streamBytes = r.le<std::uint64_t>("total_bytes");
  if (m.streamBytes != b.size())
    r.fail(totalAt, "total_bytes: " + std::to_string(m.streamBytes) + ", but the stream is " +
                        std::to_string(b.size()) + " bytes");
  if (m.exceptionBytes > b.size() - kLebMirrorHeaderBytes)
    r.fail(exceptionBytesAt, "exceptions_bytes: " + std::to_string(m.exceptionBytes) + " bytes past the header of a " +
                                 std::to_string(b.size()) + "-byte stream");
  const std::string_view coded = b.substr(kLebMirrorHeaderBytes, m.exceptionBytes);
  if (!crc32Matches(coded, static_cast<std::uint32_t>(loadLe(b.data() + kExceptionsCrcAt, 4))))
    r.fail(kExceptionsCrcAt, "exceptions_crc: CRC-32 mismatch (the exceptions are corrupt)");
  m.exceptions = decodeExceptions(h, count, coded, kLebMirrorHeaderBytes);
  m.innerOffset = kLebMirrorHeaderBytes + m.exceptionBytes;
  try {
    m.inner = parseLebStream(b.substr(m.innerOffset), std::move(owner));
  } catch (const StreamError& e) {
    throw inWholeStream(e, m.innerOffset);
  }
  const Dims3 folded = lebFoldedDims(h.dims, h.planes);
  if (m.inner.dims != folded || m.inner.sampleBits != h.sampleBits)
    r.fail(m.innerOffset, "folded stream: its volume is " + dimsText(m.inner.dims) + " uint" +
                              std::to_string(m.inner.sampleBits) + ", expected the folded " + dimsText(folded) +
                              " uint" + std::to_string(h.sampleBits));
  if (m.inner.derivedGradients || m.inner.channels.size() != (h.storedGradients() ? 2u : 1u))
    r.fail(m.innerOffset, h.storedGradients()
                              ? "folded stream: expected the data and the gradients channels (header byte 7 says the "
                                "gradients are stored)"
                              : "folded stream: expected the data channel alone (header byte 7 says the gradients are "
                                "none or derived from the unfolded samples)");
  return m;
}

void decodeMirroredLebInto(const MirroredLebStream& m, const LebVolumeOut& out, int threads, const LebWindow& window) {
  const LebMirrorHeader& h = m.header;
  if (out.dims != h.dims || out.sampleBits != h.sampleBits || (out.gradients && !h.hasGradients()) ||
      (!out.gradients && h.storedGradients()) || (out.data8 == nullptr) == (out.data16 == nullptr) ||
      (out.data8 && h.sampleBits != 8))
    throw std::invalid_argument("decodeMirroredLebInto: the output is not the stream's volume (" + dimsText(h.dims) +
                                " uint" + std::to_string(h.sampleBits) + ")");
  // Stored gradients are decoded and unfolded with the samples; derived ones follow them.
  const bool derive = out.gradients != nullptr && !h.storedGradients();
  const LebVolumeOut folded{lebFoldedDims(h.dims, h.planes), h.sampleBits, out.data8, out.data16,
                            h.storedGradients() ? out.gradients : nullptr};
  try {
    decodeLebInto(m.inner, folded, threads, lebProgressPart(window, 0, derive ? 0.6 : 0.8));
  } catch (const StreamError& e) {
    throw inWholeStream(e, m.innerOffset);
  }
  const LebWindow unfoldWindow = lebProgressPart(window, derive ? 0.6 : 0.8, derive ? 0.1 : 0.2);
  if (out.data8)
    unfoldLebVolume(out.data8, folded.gradients, h.dims, h.planes, m.exceptions, unfoldWindow);
  else
    unfoldLebVolume(out.data16, folded.gradients, h.dims, h.planes, h.sampleBits, m.exceptions, unfoldWindow);
  if (derive)
    withLebSamples(out, [&](const auto* samples) {
      quantizedGradientsInto(samples, h.dims, out.gradients, threads, lebProgressPart(window, 0.7, 0.3));
    });
}

LebDecoded decodeMirroredLeb(const MirroredLebStream& m, int threads) {
  LebDecoded d{Volume<std::uint16_t>(m.header.dims), {}};
  if (m.header.hasGradients()) d.gradients.resize(3 * sampleCount(m.header.dims));
  decodeMirroredLebInto(m,
                        {m.header.dims, m.header.sampleBits, nullptr, d.data.data().data(),
                         m.header.hasGradients() ? d.gradients.data() : nullptr},
                        threads);
  return d;
}

std::uint64_t mirroredLebDecodeMemoryBytes(const MirroredLebStream& m) {
  const std::uint64_t samples = sampleCount(m.header.dims);
  return (m.header.hasGradients() ? 5 : 2) * samples + lebDecodeShellBytes(m.inner);
}

}  // namespace voxref::ref
