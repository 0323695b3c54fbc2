// Ray-casting compositing of planewise samples (Teitzel et al. 1999, section 4): X-ray (line
// integral), maximum intensity projection, and isosurface with Lambert shading.
//
// One function serves every backend: the reference passes samples it evaluated in double, the
// GL path and the emulation pass the values they read back from the framebuffer. Identical
// samples give identical images, bit for bit (the arithmetic is fixed-order double).
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "reference/common/plane_frame.h"

namespace voxref::ref {

enum class RenderMode { XRay, Mip, Iso };
std::string_view name(RenderMode m);
std::optional<RenderMode> parseRenderMode(std::string_view s);

// Sample values of a frame: value(i, j, k) at index i + width * (j + height * k).
struct SampleStack {
  int width = 0, height = 0, planes = 0;
  std::vector<double> values;
  double at(int i, int j, int k) const {
    return values[static_cast<std::size_t>(i) +
                  static_cast<std::size_t>(width) * (j + static_cast<std::size_t>(height) * k)];
  }
};

// A single-channel image, row j = 0 at the bottom (GL convention), value(i, j) at i + width * j.
struct Image {
  int width = 0, height = 0;
  std::vector<double> pixels;
};

struct ShadingParams {
  RenderMode mode = RenderMode::XRay;
  double isovalue = 0.5;  // Iso only
  double ambient = 0.15;  // Iso only: ambient term; diffuse weight is 1 - ambient
};

// X-ray: sum over k of value * |dz| (a Riemann sum of the line integral, eq. 14 without
//        absorption, as the paper's X-ray model).
// MIP:   the larger of 0 and the maximum over k of value (0 is the background).
// Iso:   the first k >= 1 from the eye where (value >= isovalue) differs from the previous
//        sample ("the difference of current function value and iso-value changes the sign"; a
//        value equal to the isovalue counts as inside). The gradient is estimated by central
//        differences on the sample lattice (one-sided at the stack border), interpolated
//        linearly to the crossing, and shaded two-sided Lambert with a headlight:
//        ambient + (1 - ambient) * |n . view|. No crossing gives 0.
// Throws std::invalid_argument if the stack does not match the frame's sizes.
Image shadePlanes(const SampleStack& samples, const PlaneFrame& frame, const ShadingParams& params);

}  // namespace voxref::ref
