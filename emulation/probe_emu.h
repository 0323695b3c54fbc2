// What a precision profile gives for the probe frames of `voxref probe`
// (reference/common/probe_frames.h): the frames GL would read back if the driver computed exactly
// what the profile models. Bit-exact to the profile's models (texture_sampler_emu.h for the
// sweeps, framebuffer_emu.h for the writes). conformance/framework/probe/ infers a fingerprint from these
// the same way it does from the GL frames, which makes every known profile's expected fingerprint
// a derivation rather than a table.
#pragma once

#include <vector>

#include "emulation/profile.h"
#include "reference/common/probe_frames.h"

namespace voxref::emu {

// One frame per sweep, then one per write, in the design's order. The four channels of a texture
// are sampled independently (each as a one-channel texture of the same format and wrap), which is
// what both Mesa drivers do for the probe's 2- and 3-texel textures.
std::vector<ref::ProbeFrame> emulateProbeFrames(const ref::ProbeDesign& design, const PrecisionProfile& profile);

}  // namespace voxref::emu
