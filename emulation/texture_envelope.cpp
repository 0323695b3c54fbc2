#include "emulation/texture_envelope.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "reference/common/rounding.h"
#include "reference/common/texel_format.h"

namespace voxref::emu {

double floatingPointError(double value, int accurateBits) {
  // (2^(23 - bits) - 1) units of 2^(exponent - 23): dEQP tcuTexVerifierUtil.cpp.
  if (value == 0.0) return 0.0;
  int e;
  std::frexp(std::fabs(value), &e);  // |value| in [2^(e-1), 2^e)
  return (ref::powerOfTwo(23 - accurateBits) - 1.0) * ref::powerOfTwo((e - 1) - 23);
}

double fixedPointError(int accurateBits) { return floatingPointError(1.0, accurateBits); }

TextureEnvelope::TextureEnvelope(const ref::Dims3& dims, ref::TexelFormat format,
                                 const std::vector<std::uint32_t>& codes, const ref::SamplerState& sampler)
    : dims_(dims), sampler_(sampler), values_(codes.size()) {
  for (std::size_t i = 0; i < codes.size(); ++i) values_[i] = ref::decodeTexel(format, codes[i]);
  border_ = ref::unormBits(format) ? std::clamp(sampler.borderRed, 0.0, 1.0) : sampler.borderRed;
}

double TextureEnvelope::texel(int x, int y, int z) const {
  int c[3] = {x, y, z};
  for (int a = 0; a < 3; ++a) {
    const int n = dims_[a];
    switch (sampler_.wrap) {
      case ref::Wrap::ClampToEdge:
        c[a] = std::clamp(c[a], 0, n - 1);
        break;
      case ref::Wrap::Repeat:
        c[a] = ((c[a] % n) + n) % n;
        break;
      case ref::Wrap::ClampToBorder:
        if (c[a] < 0 || c[a] >= n) return border_;
        break;
    }
  }
  return values_[static_cast<std::size_t>(c[0]) +
                 static_cast<std::size_t>(dims_[0]) * (c[1] + static_cast<std::size_t>(dims_[1]) * c[2])];
}

int TextureEnvelope::candidates(double u, int n, const EnvelopePrecision& p, Candidate out[4]) const {
  // The shader's division may be 2.5 ULP (float32) off, the texture unit keeps coordBits.
  const double shaderErr = p.divisionUlps * ref::powerOfTwo(std::ilogb(u == 0.0 ? 1.0 : u) - 23);
  const double coordErr = shaderErr + floatingPointError(u, p.coordBits);
  const double uvwErr = fixedPointError(p.uvwBits);
  const double lo = (u - coordErr) * n - uvwErr, hi = (u + coordErr) * n + uvwErr;
  int count = 0;
  if (sampler_.filter == ref::Filter::Nearest) {
    for (int i = static_cast<int>(std::floor(lo)); i <= static_cast<int>(std::floor(hi)) && count < 4; ++i)
      out[count++] = {i, 0.0, 0.0};
    return count;
  }
  const double clo = lo - 0.5, chi = hi - 0.5;
  for (int i = static_cast<int>(std::floor(clo)); i <= static_cast<int>(std::floor(chi)) && count < 4; ++i)
    out[count++] = {i, std::max(clo - i, 0.0), std::min(chi - i, 1.0)};
  return count;
}

Interval TextureEnvelope::lookup(const glm::dvec3& u, const EnvelopePrecision& p) const {
  Candidate cx[4], cy[4], cz[4];
  const int nx = candidates(u.x, dims_[0], p, cx), ny = candidates(u.y, dims_[1], p, cy),
            nz = candidates(u.z, dims_[2], p, cz);
  Interval out{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  auto include = [&](double v) {
    out.lo = std::min(out.lo, v);
    out.hi = std::max(out.hi, v);
  };
  for (int a = 0; a < nx; ++a)
    for (int b = 0; b < ny; ++b)
      for (int c = 0; c < nz; ++c) {
        if (sampler_.filter == ref::Filter::Nearest) {
          include(texel(cx[a].i0, cy[b].i0, cz[c].i0));
          continue;
        }
        double v[2][2][2];
        for (int dz = 0; dz < 2; ++dz)
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) v[dz][dy][dx] = texel(cx[a].i0 + dx, cy[b].i0 + dy, cz[c].i0 + dz);
        for (double wx : {cx[a].wlo, cx[a].whi})
          for (double wy : {cy[b].wlo, cy[b].whi})
            for (double wz : {cz[c].wlo, cz[c].whi}) {
              auto l = [](double w, double x0, double x1) { return (1.0 - w) * x0 + w * x1; };
              include(l(wz, l(wy, l(wx, v[0][0][0], v[0][0][1]), l(wx, v[0][1][0], v[0][1][1])),
                        l(wy, l(wx, v[1][0][0], v[1][0][1]), l(wx, v[1][1][0], v[1][1][1]))));
            }
      }
  const double pad = ref::scaleByPowerOfTwo(std::max(std::fabs(out.lo), std::fabs(out.hi)), -40);
  return {out.lo - pad, out.hi + pad};
}

}  // namespace voxref::emu
