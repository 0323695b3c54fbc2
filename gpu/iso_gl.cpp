#include "gpu/iso_gl.h"

#include <algorithm>
#include <optional>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gpu/gl_error.h"
#include "gpu/gl_objects.h"
#include "gpu/shader_sources.h"
#include "reference/iso/iso_shading.h"

namespace voxref::gpu {
// The renderer's parts: a named namespace, since IsoMeshRenderer::State holds them.
namespace iso_gl_parts {

// An RGBA8 colour and a DEPTH_COMPONENT32F depth renderbuffer (float depth reads back exactly).
class IsoTarget {
 public:
  IsoTarget(const GlApi& gl, int maxRenderbufferSize, int width, int height)
      : gl_(&gl), width_(width), height_(height) {
    if (width > maxRenderbufferSize || height > maxRenderbufferSize)
      throw GlUnsupported("a " + std::to_string(width) + "x" + std::to_string(height) +
                          " target exceeds GL_MAX_RENDERBUFFER_SIZE " + std::to_string(maxRenderbufferSize));
    color_ = renderbuffer(GL_RGBA8);
    ids_ = renderbuffer(GL_R32UI);
    depth_ = renderbuffer(GL_DEPTH_COMPONENT32F);
    GLuint fb = 0;
    gl.GenFramebuffers(1, &fb);
    framebuffer_ = GlHandle(&gl, fb, [](const GlApi& g, GLuint i) { g.DeleteFramebuffers(1, &i); });
    gl.BindFramebuffer(GL_FRAMEBUFFER, fb);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.id());
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, ids_.id());
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    if (const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER); status != GL_FRAMEBUFFER_COMPLETE)
      throw GlError("the RGBA8 + DEPTH_COMPONENT32F framebuffer is incomplete (status " + std::to_string(status) + ")");
    const GLenum drawBuffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl.DrawBuffers(2, drawBuffers);
    checkGl(gl, "creating the isosurface framebuffer");
  }

  int width() const { return width_; }
  int height() const { return height_; }
  // Binds the framebuffer (its draw buffers are framebuffer state) and sets the viewport to it.
  void bind() const {
    gl_->BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    gl_->Viewport(0, 0, width_, height_);
  }

  void read(IsoImageGl& out) const {
    const std::size_t n = static_cast<std::size_t>(width_) * height_;
    out.width = width_;
    out.height = height_;
    readColour(out.rgba);
    out.windowDepth.resize(n);
    out.primitive.resize(n);
    gl_->ReadBuffer(GL_COLOR_ATTACHMENT1);
    gl_->ReadPixels(0, 0, width_, height_, GL_RED_INTEGER, GL_UNSIGNED_INT, out.primitive.data());
    gl_->ReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, out.windowDepth.data());
    checkGl(*gl_, "reading back the isosurface image");
  }
  // The colour attachment alone, row 0 at the bottom.
  void readColour(std::vector<std::array<std::uint8_t, 4>>& rgba) const {
    rgba.resize(static_cast<std::size_t>(width_) * height_);
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_->ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_->ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    checkGl(*gl_, "reading back the isosurface image's colour");
  }

 private:
  GlHandle renderbuffer(GLenum format) {
    GLuint rb = 0;
    gl_->GenRenderbuffers(1, &rb);
    GlHandle h(gl_, rb, [](const GlApi& g, GLuint i) { g.DeleteRenderbuffers(1, &i); });
    gl_->BindRenderbuffer(GL_RENDERBUFFER, rb);
    gl_->RenderbufferStorage(GL_RENDERBUFFER, format, width_, height_);
    return h;
  }
  const GlApi* gl_;
  int width_, height_;
  GlHandle color_, ids_, depth_, framebuffer_;
};

// A buffer object whose storage grows to fit what is written and is otherwise rewritten in place.
class GrowingBuffer {
 public:
  GrowingBuffer(const GlApi& gl, GLenum target) : gl_(&gl), target_(target) {
    GLuint b = 0;
    gl.GenBuffers(1, &b);
    handle_ = GlHandle(&gl, b, [](const GlApi& g, GLuint i) { g.DeleteBuffers(1, &i); });
  }
  // Binds the buffer to its target (the first bind makes the object) and leaves it bound.
  void write(const void* data, std::size_t bytes) {
    gl_->BindBuffer(target_, handle_.id());
    if (bytes > capacity_) {
      capacity_ = std::max(bytes, capacity_ + capacity_ / 2);
      gl_->BufferData(target_, static_cast<GLsizeiptr>(capacity_), nullptr, GL_DYNAMIC_DRAW);
    }
    if (bytes > 0) gl_->BufferSubData(target_, 0, static_cast<GLsizeiptr>(bytes), data);
  }
  GLuint id() const { return handle_.id(); }

 private:
  const GlApi* gl_;
  GLenum target_;
  GlHandle handle_;
  std::size_t capacity_ = 0;
};

glm::mat4 mvpOf(const ref::ViewCamera& camera) {
  return glm::mat4(ref::projectionMatrix(camera) * ref::viewMatrix(camera));
}

void clearTarget(const GlApi& gl) {
  gl.ClearDepth(1.0);
  gl.DepthMask(GL_TRUE);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl.Clear(GL_DEPTH_BUFFER_BIT);
  const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const GLuint none[4] = {0, 0, 0, 0};
  gl.ClearBufferfv(GL_COLOR, 0, black);
  gl.ClearBufferuiv(GL_COLOR, 1, none);  // GL 4.6 section 17.4.3: integer buffers need ClearBuffer*
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Disable(GL_CULL_FACE);
  gl.Disable(GL_BLEND);
}

// The 12 triangles of a box, as 36 vertices, each face wound clockwise seen from outside the box.
void appendBox(const QueryBox& b, std::vector<float>& out) {
  static constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                       {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  auto corner = [&](int c) {
    return std::array<float, 3>{static_cast<float>((c & 1) ? b.hi[0] : b.lo[0]),
                                static_cast<float>((c & 2) ? b.hi[1] : b.lo[1]),
                                static_cast<float>((c & 4) ? b.hi[2] : b.lo[2])};
  };
  for (const auto& f : kFaces)
    for (int v : {f[0], f[1], f[2], f[0], f[2], f[3]})
      for (float x : corner(v)) out.push_back(x);
}

}  // namespace iso_gl_parts

using namespace iso_gl_parts;

// The mesh program with the mesh's vertex array (positions at 0, normals at 1, the indices), the
// display program (the same colour, no primitive ids; made with the mesh program, so that a frame
// loop's first display does not link it), and for the occlusion tests the depth-only program (the
// mesh's depth and the query boxes), the counting program and buffer, and the boxes' vertex array
// (positions at 0); the occlusion tests' programs are made when first needed.
struct IsoMeshRenderer::State {
  State(Context& c, std::string_view fragmentSource)
      : context(c),
        gl(c.gl()),
        meshProgram(gl, c.info().glslNumber, shaders::kIsoMeshVert,
                    fragmentSource.empty() ? shaders::kIsoMeshFrag : fragmentSource, "iso_mesh.frag",
                    shaders::kIsoShadingGlsl),
        displayProgram(gl, c.info().glslNumber, shaders::kIsoMeshVert, shaders::kIsoMeshDisplayFrag,
                       "iso_mesh_display.frag", shaders::kIsoShadingGlsl),
        meshVao(gl),
        positions(gl, GL_ARRAY_BUFFER),
        normals(gl, GL_ARRAY_BUFFER),
        indices(gl, GL_ELEMENT_ARRAY_BUFFER),
        boxVao(gl),
        boxVertices(gl, GL_ARRAY_BUFFER),
        counts(gl, GL_SHADER_STORAGE_BUFFER) {
    // Attribute `index` of the bound vertex array reads vec3s from `b`. An attribute's source is
    // vertex-array state, taken from the buffer bound at the call, and so is the element buffer's
    // binding; the buffers keep their names when their storage grows.
    auto attach = [&](GrowingBuffer& b, GLuint index) {
      b.write(nullptr, 0);
      gl.VertexAttribPointer(index, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
      gl.EnableVertexAttribArray(index);
    };
    boxVao.bind();
    attach(boxVertices, 0);
    meshVao.bind();
    attach(positions, 0);
    attach(normals, 1);
    indices.write(nullptr, 0);
    checkGl(gl, "making the isosurface renderer");
  }

  // The target of the camera's size, made anew only when the size changes; bound.
  const IsoTarget& targetFor(const ref::ViewCamera& camera) {
    if (!target || target->width() != camera.width || target->height() != camera.height) {
      target.reset();
      target.emplace(gl, context.info().maxRenderbufferSize, camera.width, camera.height);
    }
    target->bind();
    return *target;
  }

  // The camera's target, cleared, with the loaded mesh drawn on it by `program` (the mesh program
  // or the display one: iso_shading.glsl's colour); bound, for reading back.
  const IsoTarget& drawMesh(const Program& program, const ref::ViewCamera& camera) {
    ref::cameraBasis(camera);  // validates
    const IsoTarget& drawn = targetFor(camera);
    clearTarget(gl);
    useWithCamera(program, camera);
    gl.Uniform3f(program.uniform("uEye"), static_cast<float>(camera.eye.x), static_cast<float>(camera.eye.y),
                 static_cast<float>(camera.eye.z));
    gl.Uniform1f(program.uniform("uAmbient"), static_cast<float>(ref::kIsoAmbient));
    drawMeshTriangles("drawing the isosurface mesh");
    return drawn;
  }

  // The samples of the first `boxes` boxes in the box buffer, a query and a draw each.
  std::vector<std::uint32_t> countByQueries(std::size_t boxes, const ref::ViewCamera& camera) {
    useWithCamera(depthOnly(), camera);
    std::vector<GLuint> queries(boxes, 0);
    if (boxes > 0) gl.GenQueries(static_cast<GLsizei>(boxes), queries.data());
    for (std::size_t i = 0; i < boxes; ++i) {
      gl.BeginQuery(GL_SAMPLES_PASSED, queries[i]);
      gl.DrawArrays(GL_TRIANGLES, static_cast<GLint>(36 * i), 36);
      gl.EndQuery(GL_SAMPLES_PASSED);
    }
    std::vector<std::uint32_t> out(boxes, 0);
    for (std::size_t i = 0; i < boxes; ++i) gl.GetQueryObjectuiv(queries[i], GL_QUERY_RESULT, &out[i]);
    if (boxes > 0) gl.DeleteQueries(static_cast<GLsizei>(boxes), queries.data());
    return out;
  }

  // The same counts from one draw of all of them, into a storage buffer (occlusion_count.frag).
  std::vector<std::uint32_t> countInBuffer(std::size_t boxes, const ref::ViewCamera& camera) {
    if (!countProgram)
      countProgram.emplace(gl, context.info().glslNumber, shaders::kOcclusionCountVert, shaders::kOcclusionCountFrag,
                           "occlusion_count.frag");
    std::vector<std::uint32_t> out(boxes, 0);
    if (boxes == 0) return out;
    GLint maxBlock = 0;
    gl.GetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    if (static_cast<std::uint64_t>(boxes) * sizeof(std::uint32_t) > static_cast<std::uint64_t>(maxBlock))
      throw GlUnsupported("counting " + std::to_string(boxes) + " boxes in a buffer needs " +
                          std::to_string(boxes * sizeof(std::uint32_t)) +
                          " bytes of storage block; GL_MAX_SHADER_STORAGE_BLOCK_SIZE is " + std::to_string(maxBlock));
    useWithCamera(*countProgram, camera);
    counts.write(out.data(), boxes * sizeof(std::uint32_t));  // zeros
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counts.id());
    gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(36 * boxes));
    // GL 4.6 section 7.13.2: buffer reads after shader writes need the buffer-update barrier.
    gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(boxes * sizeof(std::uint32_t)),
                        out.data());
    return out;
  }

  // The mesh's depth alone, for the occlusion tests: the mesh's vertex shader with a fragment
  // shader that computes nothing (the colour masks are off), cheaper to draw than the shaded mesh
  // (docs/iso.md, "Occlusion tests in one draw").
  void drawMeshDepth(const ref::ViewCamera& camera) {
    useWithCamera(depthOnly(), camera);
    drawMeshTriangles("drawing the isosurface mesh's depth");
  }

  // The loaded mesh's triangles with the program in use; `what` names the draw in a GL error.
  void drawMeshTriangles(const char* what) const {
    meshVao.bind();
    if (indexCount > 0) gl.DrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
    checkGl(gl, what);
  }

  // The mesh's vertex shader with occlusion_box.frag: writes depth alone when the colour masks are off.
  const Program& depthOnly() {
    if (!depthOnlyProgram)
      depthOnlyProgram.emplace(gl, context.info().glslNumber, shaders::kIsoMeshVert, shaders::kOcclusionBoxFrag,
                               "occlusion_box.frag");
    return *depthOnlyProgram;
  }

  void useWithCamera(const Program& program, const ref::ViewCamera& camera) const {
    program.use();
    const glm::mat4 mvp = mvpOf(camera);
    gl.UniformMatrix4fv(program.uniform("uMvp"), 1, GL_FALSE, glm::value_ptr(mvp));
  }

  Context& context;
  const GlApi& gl;
  Program meshProgram, displayProgram;
  VertexArray meshVao;
  GrowingBuffer positions, normals, indices;
  GLsizei indexCount = 0;
  VertexArray boxVao;
  GrowingBuffer boxVertices;
  std::optional<Program> depthOnlyProgram, countProgram;
  GrowingBuffer counts;
  std::optional<IsoTarget> target;
};

IsoMeshRenderer::IsoMeshRenderer(Context& context, std::string_view fragmentSource)
    : state_(std::make_unique<State>(context, fragmentSource)) {}

IsoMeshRenderer::~IsoMeshRenderer() = default;

void IsoMeshRenderer::load(const ref::IsoMesh& mesh) {
  State& s = *state_;
  s.meshVao.bind();
  s.positions.write(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  s.normals.write(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
  s.indices.write(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  s.indexCount = static_cast<GLsizei>(mesh.indices.size());
  checkGl(s.gl, "uploading the isosurface mesh");
}

IsoImageGl IsoMeshRenderer::render(const ref::ViewCamera& camera) {
  State& s = *state_;
  IsoImageGl out;
  s.drawMesh(s.meshProgram, camera).read(out);
  return out;
}

std::vector<std::array<std::uint8_t, 4>> IsoMeshRenderer::display(const ref::ViewCamera& camera) {
  State& s = *state_;
  std::vector<std::array<std::uint8_t, 4>> rgba;
  s.drawMesh(s.displayProgram, camera).readColour(rgba);
  return rgba;
}

std::vector<std::uint32_t> IsoMeshRenderer::occlusionQueries(const std::vector<QueryBox>& boxes,
                                                             const ref::ViewCamera& camera, SampleCounter counter) {
  State& s = *state_;
  const GlApi& gl = s.gl;
  if (const std::string p = sampleCounterProblem(s.context, counter); !p.empty()) throw GlUnsupported(p);
  // The boxes that can be tested, in order: a box reaching the near plane would be clipped, so it
  // is not tested and counts as visible.
  const ref::CameraBasis basis = ref::cameraBasis(camera);
  std::vector<std::size_t> tested;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    double nearest = 1e300;
    for (int c = 0; c < 8; ++c) {
      const glm::dvec3 p((c & 1) ? boxes[i].hi[0] : boxes[i].lo[0], (c & 2) ? boxes[i].hi[1] : boxes[i].lo[1],
                         (c & 4) ? boxes[i].hi[2] : boxes[i].lo[2]);
      nearest = std::min(nearest, glm::dot(p - camera.eye, basis.forward));
    }
    if (nearest > camera.nearPlane) tested.push_back(i);
  }
  s.targetFor(camera);
  clearTarget(gl);
  gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  s.drawMeshDepth(camera);

  std::vector<float> vertices;
  vertices.reserve(tested.size() * 36 * 3);
  for (std::size_t i : tested) appendBox(boxes[i], vertices);
  s.boxVao.bind();
  s.boxVertices.write(vertices.data(), vertices.size() * sizeof(float));
  gl.DepthMask(GL_FALSE);
  gl.DepthFunc(GL_LEQUAL);
  gl.Enable(GL_CULL_FACE);  // appendBox winds every face clockwise seen from outside
  gl.CullFace(GL_BACK);
  gl.FrontFace(GL_CW);
  const std::vector<std::uint32_t> counts = counter == SampleCounter::Queries ? s.countByQueries(tested.size(), camera)
                                                                              : s.countInBuffer(tested.size(), camera);
  gl.Disable(GL_CULL_FACE);
  gl.FrontFace(GL_CCW);
  gl.DepthMask(GL_TRUE);
  checkGl(gl, "occlusion tests");
  std::vector<std::uint32_t> samples(boxes.size(), kNotTested);
  for (std::size_t t = 0; t < tested.size(); ++t) samples[tested[t]] = counts[t];
  return samples;
}

IsoImageGl renderIsoMeshGl(Context& context, const ref::IsoMesh& mesh, const ref::ViewCamera& camera) {
  IsoMeshRenderer renderer(context);
  renderer.load(mesh);
  return renderer.render(camera);
}

std::vector<std::uint32_t> occlusionQueriesGl(Context& context, const ref::IsoMesh& occluder,
                                              const std::vector<QueryBox>& boxes, const ref::ViewCamera& camera,
                                              SampleCounter counter) {
  IsoMeshRenderer renderer(context);
  renderer.load(occluder);
  return renderer.occlusionQueries(boxes, camera, counter);
}

std::string_view name(SampleCounter counter) { return counter == SampleCounter::Queries ? "queries" : "buffer"; }

std::string sampleCounterProblem(const Context& context, SampleCounter counter) {
  if (counter == SampleCounter::Queries) return "";
  if (context.info().glslNumber < 430)
    return "counting samples in a buffer needs GLSL 4.30 (storage buffers, early fragment tests); the context has " +
           context.info().glslVersion;
  if (!context.gl().MemoryBarrier) return "counting samples in a buffer needs glMemoryBarrier, which the context lacks";
  return "";
}

PrimitiveIdCheck checkPrimitiveIdGl(Context& context) {
  ref::ViewCamera camera;
  camera.eye = {0.0, 0.0, 3.0};
  camera.target = {0.0, 0.0, 0.0};
  camera.up = {0.0, 1.0, 0.0};
  camera.fovYDegrees = 90.0;
  camera.width = camera.height = 16;
  camera.nearPlane = 0.5;
  camera.farPlane = 10.0;
  ref::IsoMesh triangle;  // far larger than the view: it covers every pixel
  triangle.positions = {{-100.0f, -100.0f, 0.0f}, {100.0f, -100.0f, 0.0f}, {0.0f, 100.0f, 0.0f}};
  triangle.normals.assign(3, glm::vec3(0.0f, 0.0f, 1.0f));
  triangle.indices = {0, 1, 2};
  // The control: the same program with the constant id of the first triangle.
  std::string control(shaders::kIsoMeshFrag);
  const std::string read = "uint(gl_PrimitiveID) + 1u";
  const std::size_t at = control.find(read);
  if (at == std::string::npos)
    throw GlError("iso_mesh.frag no longer writes uint(gl_PrimitiveID) + 1u: the primitive-id check needs updating");
  control.replace(at, read.size(), "1u");
  PrimitiveIdCheck out;
  auto draw = [&](std::string_view fragment, std::size_t& drawn, std::size_t* right) {
    IsoMeshRenderer renderer(context, fragment);
    renderer.load(triangle);
    const IsoImageGl image = renderer.render(camera);
    out.pixels = image.windowDepth.size();
    for (std::size_t i = 0; i < image.windowDepth.size(); ++i) {
      const bool written = image.windowDepth[i] < 1.0f || image.rgba[i][3] != 0 || image.primitive[i] != 0;
      drawn += written;
      if (right && written && image.primitive[i] == 1) ++*right;
    }
  };
  draw(shaders::kIsoMeshFrag, out.drawnWithId, &out.rightIds);
  draw(control, out.drawnByControl, nullptr);
  return out;
}

}  // namespace voxref::gpu
