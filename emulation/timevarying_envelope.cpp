#include "emulation/timevarying_envelope.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "emulation/framebuffer_emu.h"
#include "emulation/interval_arithmetic.h"
#include "reference/common/frame_sampling.h"
#include "reference/common/parallel.h"
#include "reference/common/rounding.h"

namespace voxref::emu {
namespace {

Interval point(double v) { return {v, v}; }

bool isPoint(const Interval& v, double x) { return v.lo == x && v.hi == x; }

// int(x) for x >= 0 (GLSL 4.60 section 5.4.1: the fractional part is dropped).
Interval truncInt(const Interval& v) {
  if (!isBounded(v)) return v;
  return {std::trunc(v.lo), std::trunc(v.hi)};
}

Interval minWith(const Interval& v, double m) { return {std::min(v.lo, m), std::min(v.hi, m)}; }

std::size_t offset(const ref::Dims3& d, int x, int y, int z) {
  return static_cast<std::size_t>(x) + static_cast<std::size_t>(d[0]) * (y + static_cast<std::size_t>(d[1]) * z);
}

// One quantization to the 8-bit grid of a blend operation, in code units (GL 4.6 section 17.3.6:
// "precision no lower than" the destination's; either neighbouring level, exact on a level).
Interval level8(double lo, double hi) {
  return {std::clamp(std::floor(lo), 0.0, 255.0), std::clamp(std::ceil(hi), 0.0, 255.0)};
}

// One SRC_ALPHA / ONE_MINUS_SRC_ALPHA blend of source codes s (alpha a) onto destination codes d.
Interval blendChannel(const Interval& s, const Interval& a, const Interval& d) {
  const Interval product = isPoint(a, 0.0) ? point(0.0) : level8(s.lo * a.lo / 255.0, s.hi * a.hi / 255.0);
  const Interval oneMinusA{255.0 - a.hi, 255.0 - a.lo};  // 1 - a of a value on the grid: exact
  const Interval kept =
      isPoint(oneMinusA, 255.0) ? d : level8(d.lo * oneMinusA.lo / 255.0, d.hi * oneMinusA.hi / 255.0);
  return {std::min(product.lo + kept.lo, 255.0), std::min(product.hi + kept.hi, 255.0)};  // clamped, stored exactly
}

// A fragment value interval [lo, hi] (in [0, 1] after the clamp) stored to the nearest code, with
// 2^-16 code of slack for the float product x 255.
Interval nearestCode(double lo, double hi) {
  const double slack = ref::powerOfTwo(-16);
  return {std::clamp(std::ceil(lo * 255.0 - 0.5 - slack), 0.0, 255.0),
          std::clamp(std::floor(hi * 255.0 + 0.5 + slack), 0.0, 255.0)};
}

// The measured blend of code intervals: its extremes at the ends of s and d, and over every a.
Interval measuredBlendChannel(const Interval& s, const Interval& a, const Interval& d,
                              MeasuredArithmetic::Blend blend) {
  auto m = [&](int x, int y) {
    return blend == MeasuredArithmetic::Blend::Mulnorm ? static_cast<int>(mulnorm8(static_cast<std::uint8_t>(x),
                                                                                   static_cast<std::uint8_t>(y)))
                                                       : (x * y + 127) / 255;  // round(x y / 255): never a tie
  };
  int lo = 255, hi = 0;
  for (int av = static_cast<int>(a.lo); av <= static_cast<int>(a.hi); ++av) {
    lo = std::min(lo, std::min(255, m(static_cast<int>(s.lo), av) + m(static_cast<int>(d.lo), 255 - av)));
    hi = std::max(hi, std::min(255, m(static_cast<int>(s.hi), av) + m(static_cast<int>(d.hi), 255 - av)));
  }
  return {static_cast<double>(lo), static_cast<double>(hi)};
}

}  // namespace

std::string TimeVaryingEnvelope::basis() const {
  const bool measured = measured_.srcAlphaBlend != MeasuredArithmetic::Blend::Spec &&
                        measured_.unorm8Store == MeasuredArithmetic::Store::Nearest;
  return !measured ? "spec"
         : measured_.srcAlphaBlend == MeasuredArithmetic::Blend::Mulnorm
             ? "measured nearest 8-bit stores, measured mulnorm blending"
             : "measured nearest 8-bit stores, measured exact blending";
}

bool AllowedColours::contains(const ref::Rgba8& c) const {
  for (const RgbaIntervals& b : boxes)
    if (b[0].contains(c[0]) && b[1].contains(c[1]) && b[2].contains(c[2]) && b[3].contains(c[3])) return true;
  return false;
}

AllowedColours::Miss AllowedColours::miss(const ref::Rgba8& c) const {
  Miss best{1 << 30, 0, {}, 0};
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const RgbaIntervals& b = boxes[i];
    Miss m{0, 0, b[0], i};
    for (int ch = 0; ch < 4; ++ch) {
      const double d = std::max({b[ch].lo - c[ch], c[ch] - b[ch].hi, 0.0});
      if (d > m.codes) m = {static_cast<int>(d), ch, b[ch], i};
    }
    if (m.codes < best.codes) best = m;
  }
  return best;
}

RgbaIntervals AllowedColours::hull() const {
  RgbaIntervals h{};
  for (int ch = 0; ch < 4; ++ch) {
    h[ch] = {INFINITY, -INFINITY};
    for (const RgbaIntervals& b : boxes) h[ch] = {std::min(h[ch].lo, b[ch].lo), std::max(h[ch].hi, b[ch].hi)};
  }
  return h;
}

TimeVaryingEnvelope::TimeVaryingEnvelope(const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant,
                                         const MeasuredArithmetic& measured)
    : tex_(&textures), variant_(variant), measured_(measured) {
  if (const std::string why = ref::decoderIncompatibility(variant, textures.layout, textures.index.encoding);
      !why.empty())
    throw std::invalid_argument(why);
  std::array<int, 4> lo{255, 255, 255, 255}, hi{0, 0, 0, 0};
  for (std::size_t i = 0; i < textures.refinement.texels.size(); ++i) {
    lo[i % 4] = std::min<int>(lo[i % 4], textures.refinement.texels[i]);
    hi[i % 4] = std::max<int>(hi[i % 4], textures.refinement.texels[i]);
  }
  for (int ch = 0; ch < 4; ++ch)
    refinementHull_[ch] = {unormToFloatF32(std::min(lo[ch], hi[ch]), 8, kEnvelopePass.divisionUlps).lo,
                           unormToFloatF32(hi[ch], 8, kEnvelopePass.divisionUlps).hi};
}

RgbaIntervals TimeVaryingEnvelope::indexValue(int x, int y, int z) const {
  const std::uint32_t* c = &tex_->index.texels[4 * offset(tex_->index.dims, x, y, z)];
  RgbaIntervals v{};
  for (int ch = 0; ch < 4; ++ch) switch (tex_->index.encoding) {
      case ref::IndexEncoding::NormalizedRgba16:
        v[ch] = unormToFloatF32(c[ch], 16, kEnvelopePass.divisionUlps);
        break;
      case ref::IndexEncoding::NormalizedFloat: {
        // Float texels are returned as stored; a denormal may be flushed to zero (GLSL 4.60 4.7.1).
        const double f = std::bit_cast<float>(c[ch]);
        v[ch] = std::fabs(f) < 0x1p-126 ? Interval{std::min(f, 0.0), std::max(f, 0.0)} : point(f);
        break;
      }
      default:
        v[ch] = unormToFloatF32(c[ch], 8, kEnvelopePass.divisionUlps);
    }
  return v;
}

RgbaIntervals TimeVaryingEnvelope::refinementValue(int x, int y, int z) const {
  const std::uint8_t* c = &tex_->refinement.texels[4 * offset(tex_->refinement.dims, x, y, z)];
  return {unormToFloatF32(c[0], 8, kEnvelopePass.divisionUlps), unormToFloatF32(c[1], 8, kEnvelopePass.divisionUlps),
          unormToFloatF32(c[2], 8, kEnvelopePass.divisionUlps), unormToFloatF32(c[3], 8, kEnvelopePass.divisionUlps)};
}

TimeVaryingEnvelope::Range TimeVaryingEnvelope::nearest(const Interval& s, int n, const EnvelopePrecision& p) const {
  if (!isBounded(s)) return {0, n - 1};
  // dEQP computeNonNormalizedCoordBounds (tcuTexVerifierUtil.cpp), then GL 4.6 section 8.14.2:
  // i = floor(u), CLAMP_TO_EDGE clamps i to [0, n - 1].
  const double lo = (s.lo - floatingPointError(s.lo, p.coordBits)) * n - fixedPointError(p.uvwBits);
  const double hi = (s.hi + floatingPointError(s.hi, p.coordBits)) * n + fixedPointError(p.uvwBits);
  return {std::clamp(static_cast<int>(std::floor(lo)), 0, n - 1),
          std::clamp(static_cast<int>(std::floor(hi)), 0, n - 1)};
}

void TimeVaryingEnvelope::addRefinement(const std::array<std::vector<Range>, 3>& axes,
                                        std::vector<RgbaIntervals>& out) const {
  // Per axis, the union of the texel ranges as sorted disjoint ranges (merged, not expanded: an
  // unconstrained coordinate covers the whole texture, and sorting every texel of it was most of a
  // literal decoder's envelope time).
  std::array<std::vector<Range>, 3> merged;
  std::size_t count = 1;
  for (int a = 0; a < 3; ++a) {
    std::vector<Range> ranges = axes[a];
    std::sort(ranges.begin(), ranges.end(), [](const Range& l, const Range& r) { return l.lo < r.lo; });
    std::size_t texels = 0;
    for (const Range& r : ranges) {
      if (!merged[a].empty() && r.lo <= merged[a].back().hi + 1)
        merged[a].back().hi = std::max(merged[a].back().hi, r.hi);
      else
        merged[a].push_back(r);
    }
    for (const Range& r : merged[a]) texels += static_cast<std::size_t>(r.hi - r.lo + 1);
    count *= texels;
  }
  if (count > 4096) {  // whole regions: their hull is the whole texture's, at worst
    out.push_back(refinementHull_);
    return;
  }
  for (const Range& rz : merged[2])
    for (int z = rz.lo; z <= rz.hi; ++z)
      for (const Range& ry : merged[1])
        for (int y = ry.lo; y <= ry.hi; ++y)
          for (const Range& rx : merged[0])
            for (int x = rx.lo; x <= rx.hi; ++x) out.push_back(refinementValue(x, y, z));
}

void TimeVaryingEnvelope::paperOrLiteral(int step, const glm::dvec3& p, const EnvelopePrecision& prec,
                                         std::vector<RgbaIntervals>& out) const {
  const ref::TimeVaryingLayout& L = tex_->layout;
  const auto slot = ref::indexSlot(L, step);
  const bool literal = variant_ == ref::DecoderVariant::Literal;
  const float S = static_cast<float>(L.indexSlots), n = static_cast<float>(L.cells);
  // Uniforms as gpu/timevarying_gl.cpp sets them (float32).
  const Interval slotScale = point(1.0f / S), cellSize = point(1.0f / n),
                 blockScale = point(n / static_cast<float>(L.blockSlots));
  std::array<Range, 3> index{};
  std::array<std::vector<Interval>, 3> offsets;  // mod(p, cellSize) * blockScale, one per branch
  for (int a = 0; a < 3; ++a) {
    const Interval origin = point(static_cast<float>(slot[a]) / S), pa = point(p[a]);
    // literal: origin + texCoord / DR (DR = 8, an int converted to float); paper: slotOrigin + p * slotScale.
    const Interval coord =
        literal ? addF32(origin, divF32(pa, point(8.0), prec.divisionUlps)) : addF32(origin, mulF32(pa, slotScale));
    index[a] = nearest(coord, tex_->index.dims[a], prec);
    if (literal) {
      offsets[a] = {unboundedF32()};  // mod(texCoord, DR / TEX_DIM) = mod(x, 0): unconstrained
    } else {
      for (const Interval& m : modF32(pa, cellSize, prec.divisionUlps)) offsets[a].push_back(mulF32(m, blockScale));
    }
  }
  for (int z = index[2].lo; z <= index[2].hi; ++z)
    for (int y = index[1].lo; y <= index[1].hi; ++y)
      for (int x = index[0].lo; x <= index[0].hi; ++x) {
        const RgbaIntervals c = indexValue(x, y, z);
        if (!isPoint(c[3], 1.0)) out.push_back(c);  // `c.a == 1.0` false: the index colour
        if (!c[3].contains(1.0)) continue;
        std::array<std::vector<Range>, 3> axes;
        for (int a = 0; a < 3; ++a)
          for (const Interval& o : offsets[a])
            axes[a].push_back(nearest(addF32(c[a], o), tex_->refinement.dims[a], prec));
        addRefinement(axes, out);
      }
}

void TimeVaryingEnvelope::texelCentre(int step, const glm::dvec3& p, const EnvelopePrecision& prec,
                                      std::vector<RgbaIntervals>& out) const {
  const ref::TimeVaryingLayout& L = tex_->layout;
  const auto slot = ref::indexSlot(L, step);
  const double cells = L.cells, side = L.side, r = L.blockSide;
  const Interval indexSize = point(L.indexSlots * L.cells), refSize = point(L.blockSlots * L.blockSide);
  // Per axis, every cell value the shader may compute and the index texels it may then read.
  struct CellChoice {
    double cell;
    Range index;
  };
  std::array<std::vector<CellChoice>, 3> choices;
  std::array<Interval, 3> voxel{};
  for (int a = 0; a < 3; ++a) {
    const Interval pa = point(p[a]);
    const Interval cell = minWith(floorF32(mulF32(pa, point(cells))), cells - 1.0);
    voxel[a] = minWith(floorF32(mulF32(pa, point(side))), side - 1.0);
    for (double cv = cell.lo; cv <= cell.hi; ++cv) {
      const Interval coord =
          divF32(addF32(addF32(point(slot[a] * L.cells), point(cv)), point(0.5)), indexSize, prec.divisionUlps);
      choices[a].push_back({cv, nearest(coord, tex_->index.dims[a], prec)});
    }
  }
  for (const CellChoice& cz : choices[2])
    for (const CellChoice& cy : choices[1])
      for (const CellChoice& cx : choices[0]) {
        const CellChoice* ch[3] = {&cx, &cy, &cz};
        for (int z = cz.index.lo; z <= cz.index.hi; ++z)
          for (int y = cy.index.lo; y <= cy.index.hi; ++y)
            for (int x = cx.index.lo; x <= cx.index.hi; ++x) {
              const RgbaIntervals c = indexValue(x, y, z);
              if (!isPoint(c[3], 1.0)) out.push_back(c);
              if (!c[3].contains(1.0)) continue;
              std::array<std::vector<Range>, 3> axes;
              for (int a = 0; a < 3; ++a) {
                // block = floor(c * 255 + 0.5); refCoord = (block r + (voxel - cell r) + 0.5) / refinementSize.
                const Interval block = floorF32(addF32(mulF32(c[a], point(255.0)), point(0.5)));
                const Interval inBlock = subF32(voxel[a], mulF32(point(ch[a]->cell), point(r)));
                const Interval coord =
                    divF32(addF32(addF32(mulF32(block, point(r)), inBlock), point(0.5)), refSize, prec.divisionUlps);
                axes[a].push_back(nearest(coord, tex_->refinement.dims[a], prec));
              }
              addRefinement(axes, out);
            }
      }
}

void TimeVaryingEnvelope::texelFetch(int step, const glm::dvec3& p, std::vector<RgbaIntervals>& out) const {
  const ref::TimeVaryingLayout& L = tex_->layout;
  const auto slot = ref::indexSlot(L, step);
  std::array<Interval, 3> cell{}, voxel{};
  for (int a = 0; a < 3; ++a) {
    cell[a] = minWith(truncInt(mulF32(point(p[a]), point(L.cells))), L.cells - 1.0);
    voxel[a] = minWith(truncInt(mulF32(point(p[a]), point(L.side))), L.side - 1.0);
  }
  const RgbaIntervals anything{Interval{0.0, 1.0}, Interval{0.0, 1.0}, Interval{0.0, 1.0}, Interval{0.0, 1.0}};
  const ref::Dims3& di = tex_->index.dims;
  for (double cz = cell[2].lo; cz <= cell[2].hi; ++cz)
    for (double cy = cell[1].lo; cy <= cell[1].hi; ++cy)
      for (double cx = cell[0].lo; cx <= cell[0].hi; ++cx) {
        const double cv[3] = {cx, cy, cz};
        const int t[3] = {slot[0] * L.cells + static_cast<int>(cx), slot[1] * L.cells + static_cast<int>(cy),
                          slot[2] * L.cells + static_cast<int>(cz)};
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= di[0] || t[1] >= di[1] || t[2] >= di[2]) {
          out.push_back(anything);  // texelFetch outside the texture: undefined (GL 4.6 section 11.1.3.2)
          continue;
        }
        const RgbaIntervals c = indexValue(t[0], t[1], t[2]);
        if (!isPoint(c[3], 1.0)) out.push_back(c);
        if (!c[3].contains(1.0)) continue;
        std::array<std::vector<Range>, 3> axes;
        bool outside = false;
        for (int a = 0; a < 3; ++a) {
          // block = int(c * 255 + 0.5); texel = block r + (voxel - cell r): integer arithmetic, exact.
          const Interval block = truncInt(addF32(mulF32(c[a], point(255.0)), point(0.5)));
          const double lo = block.lo * L.blockSide + (voxel[a].lo - cv[a] * L.blockSide);
          const double hi = block.hi * L.blockSide + (voxel[a].hi - cv[a] * L.blockSide);
          outside = outside || lo < 0 || hi >= tex_->refinement.dims[a];
          axes[a].push_back({static_cast<int>(lo), static_cast<int>(hi)});
        }
        if (outside)
          out.push_back(anything);
        else
          addRefinement(axes, out);
      }
}

void TimeVaryingEnvelope::fragment(int step, const glm::dvec3& p, const EnvelopePrecision& prec, Fragment& out) const {
  out.colours.clear();
  out.discarded = !ref::insideUnitCube(p);  // outsideUnitCube(p) compares exact values: decided exactly
  if (out.discarded) return;
  switch (variant_) {
    case ref::DecoderVariant::Literal:
    case ref::DecoderVariant::Paper:
      paperOrLiteral(step, p, prec, out.colours);
      break;
    case ref::DecoderVariant::TexelCentre:
      texelCentre(step, p, prec, out.colours);
      break;
    case ref::DecoderVariant::TexelFetch:
      texelFetch(step, p, out.colours);
      break;
  }
}

AllowedColours TimeVaryingEnvelope::decoded(int step, const glm::dvec3& p, const EnvelopePrecision& prec) const {
  Fragment f;
  fragment(step, p, prec, f);
  AllowedColours out;
  if (f.discarded) {
    out.boxes.push_back({point(0.0), point(0.0), point(0.0), point(0.0)});
    return out;
  }
  for (const RgbaIntervals& c : f.colours) {
    const RgbaIntervals codes{unormCodes(c[0], 8), unormCodes(c[1], 8), unormCodes(c[2], 8), unormCodes(c[3], 8)};
    const bool seen = std::any_of(out.boxes.begin(), out.boxes.end(), [&](const RgbaIntervals& b) {
      for (int ch = 0; ch < 4; ++ch)
        if (b[ch].lo != codes[ch].lo || b[ch].hi != codes[ch].hi) return false;
      return true;
    });
    if (!seen) out.boxes.push_back(codes);
  }
  return out;
}

AllowedColours TimeVaryingEnvelope::composited(int step, const ref::PlaneFrame& frame, int i, int j,
                                               const EnvelopePrecision& prec) const {
  RgbaIntervals dst{point(0.0), point(0.0), point(0.0), point(0.0)};  // glClearColor(0, 0, 0, 0)
  // The measured rules hold together: nearest stores of the fragment and the integer blend on them.
  const bool measured = measured_.srcAlphaBlend != MeasuredArithmetic::Blend::Spec &&
                        measured_.unorm8Store == MeasuredArithmetic::Store::Nearest;
  Fragment f;
  for (int k = frame.planes - 1; k >= 0; --k) {
    fragment(step, frame.sample(i, j, k), prec, f);
    if (f.discarded) continue;
    // The source: the hull of the candidates, clamped, then the first rounding to the 8-bit grid.
    RgbaIntervals src{};
    for (int ch = 0; ch < 4; ++ch) {
      double lo = INFINITY, hi = -INFINITY;
      for (const RgbaIntervals& c : f.colours) lo = std::min(lo, c[ch].lo), hi = std::max(hi, c[ch].hi);
      src[ch] = measured ? nearestCode(std::clamp(lo, 0.0, 1.0), std::clamp(hi, 0.0, 1.0))
                         : level8(std::clamp(lo, 0.0, 1.0) * 255.0, std::clamp(hi, 0.0, 1.0) * 255.0);
    }
    for (int ch = 0; ch < 4; ++ch)
      dst[ch] = measured ? measuredBlendChannel(src[ch], src[3], dst[ch], measured_.srcAlphaBlend)
                         : blendChannel(src[ch], src[3], dst[ch]);
  }
  return {{dst}};
}

std::vector<std::uint8_t> envelopeTiers(const TimeVaryingEnvelope& envelope, int step, const ref::PlaneFrame& frame,
                                        bool composite, const ref::RgbaStack& judged, int threads,
                                        std::vector<std::uint8_t>* widths) {
  std::vector<std::uint8_t> tier(judged.colours.size(), 0);
  if (widths) widths->assign(judged.colours.size(), 0);
  auto judge = [&](std::size_t idx, auto allowed) {
    const AllowedColours pass = allowed(kEnvelopePass);
    if (widths) {
      const RgbaIntervals h = pass.hull();
      for (const Interval& c : h) (*widths)[idx] = std::max((*widths)[idx], static_cast<std::uint8_t>(c.hi - c.lo));
    }
    if (pass.contains(judged.colours[idx])) return;
    tier[idx] = allowed(kEnvelopeQualityWarning).contains(judged.colours[idx]) ? 1 : 2;
  };
  if (composite) {
    ref::parallelFor(frame.height, threads, [&](int j) {
      for (int i = 0; i < frame.width; ++i)
        judge(static_cast<std::size_t>(i) + static_cast<std::size_t>(frame.width) * j,
              [&](const EnvelopePrecision& p) { return envelope.composited(step, frame, i, j, p); });
    });
    return tier;
  }
  ref::parallelFor(frame.planes, threads, [&](int k) {
    for (int j = 0; j < frame.height; ++j)
      for (int i = 0; i < frame.width; ++i)
        judge(static_cast<std::size_t>(i) +
                  static_cast<std::size_t>(frame.width) * (j + static_cast<std::size_t>(frame.height) * k),
              [&](const EnvelopePrecision& p) { return envelope.decoded(step, frame.sample(i, j, k), p); });
  });
  return tier;
}

}  // namespace voxref::emu
