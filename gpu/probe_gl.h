// The probe frames of `voxref probe` (reference/common/probe_frames.h) drawn on a real GL context
// and read back bit for bit: the input of driver fingerprinting (conformance/framework/probe/).
#pragma once

#include <vector>

#include "gpu/context.h"
#include "reference/common/probe_frames.h"

namespace voxref::gpu {

// One frame per sweep, then one per write, in the design's order (as emu::emulateProbeFrames).
// Codes are what glReadPixels returns in each target format's own type. Throws GlUnsupported when
// a target does not fit GL_MAX_RENDERBUFFER_SIZE, GlError / ShaderError on GL failures.
std::vector<ref::ProbeFrame> renderProbeFramesGl(Context& context, const ref::ProbeDesign& design);

}  // namespace voxref::gpu
