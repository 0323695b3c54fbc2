// The time-varying decoders on a real GL context (Binotto et al. 2003, section 6): the index and
// refinement textures as RGBA 3D textures with NEAREST filtering, one of the decoder shaders
// (reference/timevarying/decoder_variants.h), and the planes of a plane frame either read back
// one by one (decode-only) or composited back to front with SRC_ALPHA / ONE_MINUS_SRC_ALPHA into
// RGBA8 (as the paper renders its view-aligned slices).
#pragma once

#include <functional>

#include "gpu/context.h"
#include "gpu/shader_override.h"
#include "reference/common/plane_frame.h"
#include "reference/common/rgba.h"
#include "reference/timevarying/address_textures.h"
#include "reference/timevarying/decoder_variants.h"

namespace voxref::gpu {

// Every plane decoded separately into an RGBA8 target (no blending). Throws GlUnsupported when a
// texture exceeds the context's limits, std::invalid_argument for a decoder that cannot read the
// textures (decoderIncompatibility), ShaderError when `shader` does not compile. `shader`: a
// user's fragment shader in place of the variant's (shader_override.h); nullptr or another
// stage's: the built-in one.
ref::RgbaStack decodePlanesGl(Context& context, const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant,
                              int step, const ref::PlaneFrame& frame, const std::function<void(int)>& progress = {},
                              const ShaderOverride* shader = nullptr);

// The planes composited from the back (k = planes - 1) to the front (k = 0): one image.
ref::RgbaStack compositeGl(Context& context, const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant,
                           int step, const ref::PlaneFrame& frame, const std::function<void(int)>& progress = {},
                           const ShaderOverride* shader = nullptr);

// The texels the decoder fetched at every sample of one step, measured on GL: two decode-planes
// renders through the same shader with the address textures (reference/timevarying/
// address_textures.h) in place of the index, then of the refinement texture; formats, extents and
// sampler state unchanged. Throws as decodePlanesGl, and std::length_error for a texture too large
// to address.
ref::MeasuredFetches measureFetchesGl(Context& context, const ref::TimeVaryingTextures& textures,
                                      ref::DecoderVariant variant, int step, const ref::PlaneFrame& frame,
                                      const ShaderOverride* shader = nullptr);

}  // namespace voxref::gpu
