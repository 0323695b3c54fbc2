// The isosurface on a real GL context (Gregorski et al. 2004, sections 4 and 5): the extracted
// mesh drawn from indexed vertex buffers with two-sided headlight Lambert shading
// (reference/iso/iso_shading.h) into RGBA8 + an R32UI triangle-id buffer + a float32 depth buffer, and occlusion
// queries on axis-aligned boxes against the depth of a mesh (the previous frame's surface, as the paper).
//
// Conventions are ref::ViewCamera's (row 0 at the bottom, the pixel centre is the sample point).
// The MVP matrix is computed in double and rounded to float once.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/context.h"
#include "reference/common/view_camera.h"
#include "reference/iso/iso_mesh.h"

namespace voxref::gpu {

struct IsoImageGl {
  int width = 0, height = 0;
  std::vector<std::array<std::uint8_t, 4>> rgba;  // row 0 at the bottom
  std::vector<float> windowDepth;                 // GL window depth in [0, 1]; 1 where nothing was drawn
  std::vector<std::uint32_t> primitive;           // index of the triangle drawn (gl_PrimitiveID) + 1; 0: none
};

// Renders the mesh. Throws GlUnsupported when the size exceeds GL_MAX_RENDERBUFFER_SIZE.
// (IsoMeshRenderer, below, with a renderer of its own.)
IsoImageGl renderIsoMeshGl(Context& context, const ref::IsoMesh& mesh, const ref::ViewCamera& camera);

// Whether fragments of the mesh program reach the framebuffer on this driver: one triangle that
// covers a 16x16 target, drawn by the mesh program (which reads gl_PrimitiveID with no geometry
// shader bound, as GL 4.6 section 15.2.2 and GLSL 1.50 allow) and by a control that differs only
// in writing the constant id 1 instead. A conforming driver draws every pixel both times, with
// id 1. softpipe (Mesa 22.3) draws nothing with the first, and raises no GL error
// (docs/profiles.md).
struct PrimitiveIdCheck {
  std::size_t pixels = 0;          // of the target
  std::size_t drawnWithId = 0;     // pixels the mesh program wrote
  std::size_t rightIds = 0;        // of those, the ones whose id is 1 (the first triangle + 1)
  std::size_t drawnByControl = 0;  // pixels the control program wrote
  bool driverDropsPrimitiveIdDraws() const { return drawnByControl == pixels && drawnWithId < pixels; }
};
PrimitiveIdCheck checkPrimitiveIdGl(Context& context);

struct QueryBox {
  std::array<double, 3> lo, hi;  // grid coordinates
};

// How GL counts a box's samples. Both give the same numbers by the GL and GLSL specifications
// (occlusion_count.frag says why); the iso.frames cases' oracle sample_counters compares them box
// for box (conformance/modules/iso/iso_catalog.h).
enum class SampleCounter {
  Queries,  // GL_SAMPLES_PASSED: a query object and a draw per box, as the paper tests its boxes
  Buffer,   // every box in one draw; a fragment shader run after the depth test (early fragment
            // tests) adds one to its box's counter in a shader storage buffer. Needs GLSL 4.30
            // and glMemoryBarrier: GlUnsupported on contexts without them (softpipe's 3.30), and
            // for more boxes than GL_MAX_SHADER_STORAGE_BLOCK_SIZE / 4 (4 M at GL 4.3's least).
};
std::string_view name(SampleCounter counter);  // "queries", "buffer"
// Why `context` cannot count with `counter`; empty when it can.
std::string sampleCounterProblem(const Context& context, SampleCounter counter);

// For every box, the samples of its front faces (those facing the eye; back faces are culled)
// that pass GL_LEQUAL against the depth of `occluder` (rendered first, depth only) from `camera`,
// counted by `counter`. A box has samples exactly when it would have with its back faces drawn:
// every pixel the box covers is covered by a front face, no farther than the back face there.
// A box whose extent reaches within the near plane of the eye cannot be tested (it would be
// clipped): its count is reported as kNotTested and the caller must treat it as visible.
// Throws GlUnsupported as sampleCounterProblem says.
inline constexpr std::uint32_t kNotTested = 0xffffffffu;
std::vector<std::uint32_t> occlusionQueriesGl(Context& context, const ref::IsoMesh& occluder,
                                              const std::vector<QueryBox>& boxes, const ref::ViewCamera& camera,
                                              SampleCounter counter = SampleCounter::Queries);

// The renderer of a frame loop: its programs, vertex arrays, buffers and target are kept from one
// call to the next. A loaded mesh stays in the buffers until the next load, so the frame after
// can query against it without uploading it again; a buffer's storage grows when a mesh does not
// fit it (glBufferData, to the size needed or to one and a half times its old size, the larger)
// and is otherwise rewritten in place (glBufferSubData), so a loop does not have the driver
// allocate and clear its storage every frame. Each image and each query result is the one
// renderIsoMeshGl and occlusionQueriesGl give for the same mesh and camera (they are this class
// with a renderer of their own). The context must outlive the renderer and be current.
class IsoMeshRenderer {
 public:
  // `fragmentSource`: the mesh program's fragment shader (iso_mesh.frag; checkPrimitiveIdGl's
  // control differs in one expression).
  explicit IsoMeshRenderer(Context& context, std::string_view fragmentSource = {});
  ~IsoMeshRenderer();
  IsoMeshRenderer(const IsoMeshRenderer&) = delete;
  IsoMeshRenderer& operator=(const IsoMeshRenderer&) = delete;

  // Makes `mesh` the one that render() and display() draw and occlusionQueries() tests against.
  void load(const ref::IsoMesh& mesh);
  // The loaded mesh (none: an empty image) from `camera`. Throws GlUnsupported when the size
  // exceeds GL_MAX_RENDERBUFFER_SIZE.
  IsoImageGl render(const ref::ViewCamera& camera);
  // The loaded mesh from `camera` as a display shows it: render()'s colour image alone (row 0 at the
  // bottom), drawn by a program that does not read gl_PrimitiveID (iso_mesh_display.frag, the same
  // shading). What a frame loop times; the oracles judge render()'s image of the same mesh. Throws
  // as render() does.
  std::vector<std::array<std::uint8_t, 4>> display(const ref::ViewCamera& camera);
  // occlusionQueriesGl with the loaded mesh as occluder.
  std::vector<std::uint32_t> occlusionQueries(const std::vector<QueryBox>& boxes, const ref::ViewCamera& camera,
                                              SampleCounter counter = SampleCounter::Queries);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace voxref::gpu
