// Planewise sampling geometry (Teitzel et al. 1999, section 4 and Fig. 5): the sample points of
// an orthographic ray caster arranged on view-aligned planes, so that a whole plane can be
// evaluated at once by drawing textured quads.
//
// Sample (i, j, k), with pixel i in [0, width), row j in [0, height) and plane k in [0, planes)
// counted from the eye, sits at
//     planeOrigin(k) + (i + 0.5) * dx + (j + 0.5) * dy,   planeOrigin(k) = origin + (k + 0.5) * dz.
// The shader of the GL path evaluates exactly this expression in float32 from gl_FragCoord
// (which is exactly i + 0.5, j + 0.5). Frames are built on a lattice that makes every term and
// every partial sum exactly representable in float32 (see `isFloat32Exact`), so the GL path,
// its emulation and the double reference sample the very same points, whatever rounding,
// reassociation or fused multiply-add a driver applies to the expression.
#pragma once

#include <string>

#include <glm/vec3.hpp>

namespace voxref::ref {

struct PlaneFrame {
  int width = 0;
  int height = 0;
  int planes = 0;
  glm::dvec3 origin{0.0};
  glm::dvec3 dx{0.0};
  glm::dvec3 dy{0.0};
  glm::dvec3 dz{0.0};  // from plane k to plane k + 1, pointing away from the eye

  glm::dvec3 planeOrigin(int k) const { return origin + (k + 0.5) * dz; }
  glm::dvec3 sample(int i, int j, int k) const { return (planeOrigin(k) + (i + 0.5) * dx) + (j + 0.5) * dy; }
};

// Exponents of the lattice: step vectors are multiples of 2^-kStepLatticeBits, the origin of
// 2^-kOriginLatticeBits, and every sample coordinate and partial sum stays below kMagnitudeBound.
// A multiple of 2^-22 below 4 in magnitude has at most 24 significant bits: exact in float32.
inline constexpr int kStepLatticeBits = 21;
inline constexpr int kOriginLatticeBits = 22;
inline constexpr double kMagnitudeBound = 4.0;

// An orthographic view of the unit cube from the given azimuth (about +z, degrees) and
// elevation (degrees), with a square view box of side 1.75 (the cube's diagonal is 1.732, so
// the cube is inside for every direction). Steps and origin are rounded onto the lattice.
// Throws std::invalid_argument for non-positive sizes or sizes above 4096.
PlaneFrame orbitFrame(double azimuthDeg, double elevationDeg, int width, int height, int planes);

// A frame given explicitly (for hard cases that put samples exactly on nodes or faces).
// Throws std::invalid_argument, naming the offending vector, if it is not float32-exact.
// A frame off the lattice is still float32-exact when, checked sample by sample (frames of up to
// 2^20 samples), every term and every partial sum in every order of association is a float32
// below magnitude 4.
PlaneFrame explicitFrame(glm::dvec3 origin, glm::dvec3 dx, glm::dvec3 dy, glm::dvec3 dz, int width, int height,
                         int planes);

// Empty when the frame satisfies the lattice and magnitude conditions above (or, off the lattice,
// the sample-by-sample check of explicitFrame), else the reason.
std::string float32ExactnessViolation(const PlaneFrame& frame);

// Samples 2^-24 either side of the planes x = offset + m * spacing, m = 0 .. faces - 1: pixel 0
// at the face - 2^-24, pixel 1 at the face + 2^-24, row m; plane k at first + k * rowStep (y and z
// only; the x components of rowStep and first are ignored). 2^-24 is one float32 ulp on either
// side of a face in (0.5, 1), and 2^-24 / ulp(x) ulps nearer 0 (a face at 0 gets -2^-24, outside
// the volume, and +2^-24). Meant for power-of-two spacings and offsets. Throws
// std::invalid_argument when the frame is not float32-exact.
PlaneFrame straddlingFrame(double offset, double spacing, int faces, glm::dvec3 rowStep, int rows, glm::dvec3 first);

}  // namespace voxref::ref
