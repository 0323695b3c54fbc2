// Scalar fields on the unit cube: the data voxref's built-in scenes sample.
//
// A field maps [0,1]^3 to real values (double). Analytic fields are synthetic and need no
// files; `volumeField` turns a sampled volume into the trilinear interpolant through its samples
// (sample (i,j,k) sits at (i/(X-1), j/(Y-1), k/(Z-1))), which is how a CT or simulation volume
// is "resampled to 2^n+1 points per axis" for a sparse grid.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "reference/common/volume.h"

namespace voxref::ref {

struct Field {
  std::string name;
  std::function<double(double, double, double)> eval;
  double operator()(double x, double y, double z) const { return eval(x, y, z); }
};

// Built-in analytic fields, all with values in [0, 1]:
//   gaussian_blobs    five anisotropic Gaussian blobs (smooth, non-zero on the boundary)
//   hydrogen_orbital  |psi_320|^2 of the hydrogen atom (a 3d_z2 orbital), normalised to max 1;
//                     the paper's data set IV is a hydrogen orbital too
//   tent_product      64 x(1-x) y(1-y) z(1-z): vanishes on the boundary; its hierarchical
//                     surpluses are 64 * 4^-(l1+l2+l3) exactly (closed form, used by tests)
//   constant_one      1 everywhere (data at the upper extreme)
//   zero              0 everywhere (data at the lower extreme)
//   ridge             a sharp ridge along a plane: large negative surpluses next to it
//   figure9           the clamping counterexample of Teitzel et al. Fig. 9 lifted to 3D: 0 at
//                     (1/4,1/2,1/2), (1/2,1/4,1/2), (1/2,1/2,1/4), 0.8 everywhere else; sampled
//                     on a level-2 sparse grid, no order of unscaled blend passes evaluates it
//                     correctly (conformance/modules/sparsegrid/figure9_conf.cpp)
//   gaussian_buckyball 60 Gaussian atoms (sigma 0.03) at the vertices of a truncated icosahedron
//                     of radius 0.35 around the centre: a synthetic C60, like the buckyball of
//                     Gregorski et al. 2004 ("a synthetic dataset made from Gaussian functions")
//   blobs_near_flt_max gaussian_blobs * 2^126 (peak near FLT_MAX / 4): extreme floats
//   blobs_denormal    gaussian_blobs * 2^-140: every nonzero value a float32 denormal
//   blobs_near_half_max gaussian_blobs * 65000 (peak near the largest half float, 65504)
//   blobs_half_denormal gaussian_blobs * 2^-15: every nonzero value below 2^-14, a half denormal
// Throws std::invalid_argument naming the known fields for an unknown name.
Field analyticField(std::string_view name);
std::vector<std::string> analyticFieldNames();

// The 60 vertices of the truncated icosahedron gaussian_buckyball uses (centred at the origin,
// edge length 2).
std::vector<std::array<double, 3>> buckyballVertices();

// The field sampled on a grid of `dims` points spanning [0, 1]^3 (sample i at i / (n - 1); 0.5 on
// an axis of one sample), stored as round(255 f) with f clamped to [0, 1].
Volume<std::uint8_t> sampleFieldU8(const Field& field, const Dims3& dims);

// Slice z of sampleFieldU8(analyticField("gaussian_buckyball"), dims), bit for bit, into
// out[x + X y], several times faster: a sample is decided from the atoms within 0.2 of it when
// the bound on the others (60 exp(-0.2^2 / (2 sigma^2)) < 1.5e-8) cannot move its rounding, and
// from the whole sum otherwise. For volumes too large to sample in memory (a 1025^3 buckyball).
void sampleGaussianBuckyballSliceU8(const Dims3& dims, int z, std::uint8_t* out);

// The trilinear interpolant of `volume` (values scaled by `scale`, e.g. 1/255 for uint8).
// The volume must have at least 2 samples per axis. The field shares ownership of the data.
Field volumeField(std::string name, std::shared_ptr<const Volume<std::uint8_t>> volume, double scale);

}  // namespace voxref::ref
