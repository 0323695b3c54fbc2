#include "reference/common/fields.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace voxref::ref {
namespace {

struct Blob {
  double cx, cy, cz, sx, sy, sz, amplitude;
};

constexpr std::array<Blob, 5> kBlobs{{
    {0.30, 0.35, 0.40, 0.10, 0.14, 0.12, 1.2},
    {0.68, 0.30, 0.55, 0.08, 0.08, 0.16, 1.0},
    {0.50, 0.70, 0.30, 0.16, 0.07, 0.09, 0.9},
    {0.25, 0.72, 0.72, 0.06, 0.10, 0.06, 1.4},
    {0.75, 0.72, 0.80, 0.12, 0.12, 0.05, 0.8},
}};

double gaussianBlobs(double x, double y, double z) {
  double sum = 0.0;
  for (const Blob& b : kBlobs) {
    const double dx = (x - b.cx) / b.sx, dy = (y - b.cy) / b.sy, dz = (z - b.cz) / b.sz;
    sum += b.amplitude * std::exp(-0.5 * (dx * dx + dy * dy + dz * dz));
  }
  return 1.0 - std::exp(-sum);  // smooth, in [0, 1)
}

// |psi_320| of hydrogen: R_32(r) ~ r^2 exp(-r/3), Y_20 ~ 3 cos^2(theta) - 1, on [-20, 20]^3 Bohr
// radii. |psi| peaks at r = 6 on the z axis, where r^2 e^{-r/3} (3 - 1) = 72 e^-2.
double hydrogenOrbital(double x, double y, double z) {
  constexpr double kHalfExtent = 20.0;
  const double px = (2.0 * x - 1.0) * kHalfExtent, py = (2.0 * y - 1.0) * kHalfExtent,
               pz = (2.0 * z - 1.0) * kHalfExtent;
  const double r2 = px * px + py * py + pz * pz;
  const double r = std::sqrt(r2);
  const double angular = r2 > 0.0 ? 3.0 * pz * pz / r2 - 1.0 : 0.0;
  const double peak = 72.0 * std::exp(-2.0);
  return std::min(1.0, std::fabs(r2 * std::exp(-r / 3.0) * angular) / peak);
}

double tentProduct(double x, double y, double z) { return 64.0 * (x * (1.0 - x)) * (y * (1.0 - y)) * (z * (1.0 - z)); }

double figure9(double x, double y, double z) {
  const bool a = x == 0.25 && y == 0.5 && z == 0.5, b = x == 0.5 && y == 0.25 && z == 0.5,
             c = x == 0.5 && y == 0.5 && z == 0.25;
  return a || b || c ? 0.0 : 0.8;
}

// The 60 vertices of a truncated icosahedron (the C60 cage): the even permutations of
// (0, +-1, +-3 phi), (+-1, +-(2 + phi), +-2 phi) and (+-phi, +-2, +-(2 phi + 1)), phi the golden
// ratio; all at distance sqrt(9 phi + 10) from the origin.
std::vector<std::array<double, 3>> makeBuckyballVertices() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  const double base[3][3] = {{0.0, 1.0, 3.0 * phi}, {1.0, 2.0 + phi, 2.0 * phi}, {phi, 2.0, 2.0 * phi + 1.0}};
  const int evenPermutations[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
  std::vector<std::array<double, 3>> v;
  for (const auto& b : base)
    for (const auto& perm : evenPermutations)
      for (int signs = 0; signs < 8; ++signs) {
        std::array<double, 3> p{};
        bool duplicate = false;
        for (int a = 0; a < 3; ++a) {
          const double c = b[perm[a]];
          const bool negative = (signs >> a) & 1;
          if (negative && c == 0.0) duplicate = true;  // -0 is 0
          p[static_cast<std::size_t>(a)] = negative ? -c : c;
        }
        if (!duplicate) v.push_back(p);
      }
  return v;
}

// Gaussian "atoms" of width 0.03 at the C60 vertices, on a sphere of radius 0.35 around the
// cube's centre.
constexpr double kBuckyRadius = 0.35, kBuckySigma = 0.03;
double buckyScale() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  return kBuckyRadius / std::sqrt(9.0 * phi + 10.0);
}

double gaussianBuckyball(double x, double y, double z) {
  static const std::vector<std::array<double, 3>> vertices = makeBuckyballVertices();
  constexpr double kSigma = kBuckySigma;
  const double scale = buckyScale();
  double sum = 0.0;
  for (const auto& v : vertices) {
    const double dx = x - 0.5 - scale * v[0], dy = y - 0.5 - scale * v[1], dz = z - 0.5 - scale * v[2];
    sum += std::exp(-(dx * dx + dy * dy + dz * dz) / (2.0 * kSigma * kSigma));
  }
  return std::min(1.0, sum);
}

double ridge(double x, double y, double z) {
  const double d = (x + y + z - 1.5) / 0.02;
  return std::exp(-d * d);
}

}  // namespace

std::vector<std::string> analyticFieldNames() {
  return {"gaussian_blobs",
          "hydrogen_orbital",
          "tent_product",
          "constant_one",
          "zero",
          "ridge",
          "figure9",
          "gaussian_buckyball",
          "blobs_near_flt_max",
          "blobs_denormal",
          "blobs_near_half_max",
          "blobs_half_denormal"};
}

Field analyticField(std::string_view name) {
  if (name == "gaussian_blobs") return {std::string(name), gaussianBlobs};
  if (name == "hydrogen_orbital") return {std::string(name), hydrogenOrbital};
  if (name == "tent_product") return {std::string(name), tentProduct};
  if (name == "constant_one") return {std::string(name), [](double, double, double) { return 1.0; }};
  if (name == "zero") return {std::string(name), [](double, double, double) { return 0.0; }};
  if (name == "ridge") return {std::string(name), ridge};
  if (name == "figure9") return {std::string(name), figure9};
  if (name == "gaussian_buckyball") return {std::string(name), gaussianBuckyball};
  // Float-texture traps (issue 7): the blobs scaled by powers of two, so every value keeps its
  // significand. 2^126: a quarter of FLT_MAX at the peak, sums of passes stay finite; 2^-140:
  // every value (and every texel, after the 1/n+ scaling) is a float32 denormal.
  if (name == "blobs_near_flt_max")
    return {std::string(name), [](double x, double y, double z) { return std::ldexp(gaussianBlobs(x, y, z), 126); }};
  if (name == "blobs_near_half_max")
    return {std::string(name), [](double x, double y, double z) { return 65000.0 * gaussianBlobs(x, y, z); }};
  if (name == "blobs_half_denormal")
    return {std::string(name), [](double x, double y, double z) { return std::ldexp(gaussianBlobs(x, y, z), -15); }};
  if (name == "blobs_denormal")
    return {std::string(name), [](double x, double y, double z) { return std::ldexp(gaussianBlobs(x, y, z), -140); }};
  std::string known;
  for (const auto& n : analyticFieldNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown analytic field '" + std::string(name) + "' (known: " + known + ")");
}

Field volumeField(std::string name, std::shared_ptr<const Volume<std::uint8_t>> volume, double scale) {
  const Dims3 d = volume->dims();
  for (int e : d)
    if (e < 2) throw std::invalid_argument("volume field '" + name + "' needs at least 2 samples per axis");
  auto eval = [volume, scale, d](double x, double y, double z) {
    const std::array<double, 3> p{x, y, z};
    std::array<int, 3> i0{};
    std::array<double, 3> w{};
    for (int a = 0; a < 3; ++a) {
      const double t = std::clamp(p[a], 0.0, 1.0) * (d[a] - 1);
      i0[a] = std::min(static_cast<int>(std::floor(t)), d[a] - 2);
      w[a] = t - i0[a];
    }
    auto v = [&](int dx, int dy, int dz) {
      return static_cast<double>(volume->at(i0[0] + dx, i0[1] + dy, i0[2] + dz));
    };
    auto lerp = [](double a, double b, double t) { return (1.0 - t) * a + t * b; };
    const double c00 = lerp(v(0, 0, 0), v(1, 0, 0), w[0]), c10 = lerp(v(0, 1, 0), v(1, 1, 0), w[0]);
    const double c01 = lerp(v(0, 0, 1), v(1, 0, 1), w[0]), c11 = lerp(v(0, 1, 1), v(1, 1, 1), w[0]);
    return scale * lerp(lerp(c00, c10, w[1]), lerp(c01, c11, w[1]), w[2]);
  };
  return {std::move(name), eval};
}

std::vector<std::array<double, 3>> buckyballVertices() { return makeBuckyballVertices(); }

Volume<std::uint8_t> sampleFieldU8(const Field& field, const Dims3& dims) {
  Volume<std::uint8_t> v(dims);
  auto coord = [](int i, int n) { return n > 1 ? static_cast<double>(i) / (n - 1) : 0.5; };
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) {
        const double f = field(coord(x, dims[0]), coord(y, dims[1]), coord(z, dims[2]));
        v.at(x, y, z) = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(f, 0.0, 1.0)));
      }
  return v;
}

void sampleGaussianBuckyballSliceU8(const Dims3& dims, int z, std::uint8_t* out) {
  const std::vector<std::array<double, 3>> vertices = makeBuckyballVertices();
  const double scale = buckyScale();
  auto coord = [](int i, int n) { return n > 1 ? static_cast<double>(i) / (n - 1) : 0.5; };
  auto quantize = [](double f) { return std::lround(255.0 * std::clamp(f, 0.0, 1.0)); };
  // Atoms beyond kNear contribute less than exp(-kNear^2 / (2 sigma^2)) each; kSlack covers how
  // differently the two sums round (distances rounded apart by 1e-16 move a term by below 1e-13,
  // 60 terms below 1e-11) with room to spare.
  constexpr double kNear = 0.2, kSlack = 1e-9;
  const double farBound = 60.0 * std::exp(-kNear * kNear / (2.0 * kBuckySigma * kBuckySigma));
  const double cz = coord(z, dims[2]);
  std::vector<std::array<double, 3>> row;  // atom centres near the row
  for (int y = 0; y < dims[1]; ++y) {
    const double cy = coord(y, dims[1]);
    row.clear();
    for (const auto& v : vertices) {
      const double ay = 0.5 + scale * v[1], az = 0.5 + scale * v[2];
      if ((cy - ay) * (cy - ay) + (cz - az) * (cz - az) <= kNear * kNear) row.push_back({0.5 + scale * v[0], ay, az});
    }
    for (int x = 0; x < dims[0]; ++x) {
      const double cx = coord(x, dims[0]);
      double near = 0.0;
      for (const auto& a : row) {
        const double dx = cx - a[0], dy = cy - a[1], dz = cz - a[2];
        const double d2 = dx * dx + dy * dy + dz * dz;
        if (d2 <= kNear * kNear) near += std::exp(-d2 / (2.0 * kBuckySigma * kBuckySigma));
      }
      // The whole sum lies in [near, near + farBound] up to rounding: where both ends round alike,
      // so does it (rounding is monotone).
      const long lo = quantize(near - kSlack), hi = quantize(near + farBound + kSlack);
      out[static_cast<std::size_t>(x) + static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(y)] =
          static_cast<std::uint8_t>(lo == hi ? lo : quantize(gaussianBuckyball(cx, cy, cz)));
    }
  }
}

}  // namespace voxref::ref
