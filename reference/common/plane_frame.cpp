#include "reference/common/plane_frame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "reference/common/rounding.h"

namespace voxref::ref {
namespace {

constexpr double kViewBoxSide = 1.75;
constexpr int kMaxExtent = 4096;

double snap(double v, int latticeBits) { return std::ldexp(roundHalfEven(std::ldexp(v, latticeBits)), -latticeBits); }

glm::dvec3 snap(glm::dvec3 v, int latticeBits) {
  return {snap(v.x, latticeBits), snap(v.y, latticeBits), snap(v.z, latticeBits)};
}

bool onLattice(glm::dvec3 v, int bits) {
  return isMultipleOfPowerOfTwo(v.x, bits) && isMultipleOfPowerOfTwo(v.y, bits) && isMultipleOfPowerOfTwo(v.z, bits);
}

double maxAbs(glm::dvec3 v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

void checkSizes(int width, int height, int planes) {
  for (int s : {width, height, planes})
    if (s <= 0 || s > kMaxExtent)
      throw std::invalid_argument("frame size " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                                  std::to_string(planes) + " is outside 1.." + std::to_string(kMaxExtent));
}

bool isFloat32(double v) { return static_cast<double>(static_cast<float>(v)) == v && std::fabs(v) < kMagnitudeBound; }
bool isFloat32(glm::dvec3 v) { return isFloat32(v.x) && isFloat32(v.y) && isFloat32(v.z); }

// Every term of every sample and every partial sum, in every order of association, exactly a
// float32 below the magnitude bound: then no rounding, reassociation or fusing can move a sample.
// Each value is computed exactly in double (the terms are products of a half-integer below 2^13
// and a float32; each sum, when it is a float32, is exact in double as well).
std::string enumeratedViolation(const PlaneFrame& f) {
  for (int k = 0; k < f.planes; ++k) {
    const glm::dvec3 dzTerm = (k + 0.5) * f.dz, a = f.planeOrigin(k);
    if (!isFloat32(dzTerm) || !isFloat32(a)) return "plane " + std::to_string(k) + "'s origin is not a float32";
    for (int j = 0; j < f.height; ++j) {
      const glm::dvec3 c = (j + 0.5) * f.dy;
      for (int i = 0; i < f.width; ++i) {
        const glm::dvec3 b = (i + 0.5) * f.dx;
        if (!isFloat32(b) || !isFloat32(c) || !isFloat32(a + b) || !isFloat32(a + c) || !isFloat32(b + c) ||
            !isFloat32(f.sample(i, j, k)))
          return "sample (" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) +
                 ") or a partial sum of it is not a float32";
      }
    }
  }
  return {};
}

constexpr long kMaxEnumeratedSamples = 1L << 20;

}  // namespace

std::string float32ExactnessViolation(const PlaneFrame& f) {
  std::string lattice;
  if (!onLattice(f.dx, kStepLatticeBits))
    lattice = "dx is not a multiple of 2^-21";
  else if (!onLattice(f.dy, kStepLatticeBits))
    lattice = "dy is not a multiple of 2^-21";
  else if (!onLattice(f.dz, kStepLatticeBits))
    lattice = "dz is not a multiple of 2^-21";
  else if (!onLattice(f.origin, kOriginLatticeBits))
    lattice = "origin is not a multiple of 2^-22";
  if (!lattice.empty()) {
    const long samples = static_cast<long>(f.width) * f.height * f.planes;
    if (samples > kMaxEnumeratedSamples) return lattice + " (and the frame has too many samples to check one by one)";
    const std::string why = enumeratedViolation(f);
    return why.empty() ? std::string() : lattice + ", and " + why;
  }
  // The partial sums are affine in (i, j, k): their largest magnitude is at a corner of the box.
  double worst = 0.0;
  for (int ci = 0; ci < 2; ++ci)
    for (int cj = 0; cj < 2; ++cj)
      for (int ck = 0; ck < 2; ++ck) {
        const int i = ci ? f.width - 1 : 0, j = cj ? f.height - 1 : 0, k = ck ? f.planes - 1 : 0;
        const glm::dvec3 o = f.planeOrigin(k);
        worst = std::max({worst, maxAbs(o), maxAbs((i + 0.5) * f.dx), maxAbs((j + 0.5) * f.dy),
                          maxAbs(o + (i + 0.5) * f.dx), maxAbs(f.sample(i, j, k))});
      }
  if (!(worst < kMagnitudeBound)) return "a sample coordinate or partial sum reaches magnitude 4";
  return {};
}

PlaneFrame explicitFrame(glm::dvec3 origin, glm::dvec3 dx, glm::dvec3 dy, glm::dvec3 dz, int width, int height,
                         int planes) {
  checkSizes(width, height, planes);
  PlaneFrame f{width, height, planes, origin, dx, dy, dz};
  if (const std::string why = float32ExactnessViolation(f); !why.empty())
    throw std::invalid_argument("frame is not float32-exact: " + why);
  return f;
}

PlaneFrame orbitFrame(double azimuthDeg, double elevationDeg, int width, int height, int planes) {
  checkSizes(width, height, planes);
  const double az = azimuthDeg * (M_PI / 180.0), el = elevationDeg * (M_PI / 180.0);
  // The eye looks along `view` at the cube centre; `right` and `up` span the image plane.
  const glm::dvec3 view{-std::cos(el) * std::cos(az), -std::cos(el) * std::sin(az), -std::sin(el)};
  const glm::dvec3 right{-std::sin(az), std::cos(az), 0.0};
  const glm::dvec3 up{-std::sin(el) * std::cos(az), -std::sin(el) * std::sin(az), std::cos(el)};
  PlaneFrame f;
  f.width = width;
  f.height = height;
  f.planes = planes;
  f.dx = snap(right * (kViewBoxSide / width), kStepLatticeBits);
  f.dy = snap(up * (kViewBoxSide / height), kStepLatticeBits);
  f.dz = snap(view * (kViewBoxSide / planes), kStepLatticeBits);
  const glm::dvec3 centre{0.5, 0.5, 0.5};
  f.origin =
      snap(centre - 0.5 * (double(width) * f.dx + double(height) * f.dy + double(planes) * f.dz), kOriginLatticeBits);
  if (const std::string why = float32ExactnessViolation(f); !why.empty())
    throw std::logic_error("orbitFrame built a frame that is not float32-exact: " + why);
  return f;
}

PlaneFrame straddlingFrame(double offset, double spacing, int faces, glm::dvec3 rowStep, int rows, glm::dvec3 first) {
  const double u = std::ldexp(1.0, -24);
  return explicitFrame({offset - spacing / 2 - 2 * u, first.y - rowStep.y / 2, first.z - rowStep.z / 2}, {2 * u, 0, 0},
                       {spacing, 0, 0}, {0, rowStep.y, rowStep.z}, 2, faces, rows);
}

}  // namespace voxref::ref
