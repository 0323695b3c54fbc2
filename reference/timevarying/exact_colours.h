// The right answer of a time-varying frame, from the input alone (never from the textures, which
// the paper's alpha-one policy can corrupt): the colour each sample stands for, and the ideal
// back-to-front composite of those colours. What the conformance cases judge decoders and
// composites against, and what `voxref render --backend reference` draws.
#pragma once

#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "reference/common/plane_frame.h"
#include "reference/common/rgba.h"
#include "reference/timevarying/timevarying_codec.h"
#include "reference/timevarying/transfer_function.h"

namespace voxref::ref {

// The right colour of sample p (normalized coordinates in [0, 1]^3): the input voxel
// floor(p * side), clamped to side - 1 per axis (GL's CLAMP_TO_EDGE at p = 1.0), of time step
// `step`, after the transfer function. Exact.
Rgba8 inputColour(const TimeSeries& input, const TransferFunction& tf, int step, const glm::dvec3& p);

// inputColour of every sample of the frame, (0, 0, 0, 0) outside the unit cube. Exact.
RgbaStack exactColours(const TimeSeries& input, const TransferFunction& tf, int step, const PlaneFrame& frame);

// The exact colours composited back to front in real arithmetic (double), per pixel and channel,
// in code units [0, 255]: C = s a + C (1 - a) with a = s_alpha / 255, alpha too; the ideal of
// glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) (GL 4.6 section 17.3.6) without rounding.
// Samples outside the unit cube are skipped. Row 0 at the bottom, x fastest.
std::vector<std::array<double, 4>> idealComposite(const RgbaStack& exact, const PlaneFrame& frame);

}  // namespace voxref::ref
