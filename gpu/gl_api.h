// The GL entry points voxref calls, loaded through the context's GetProcAddress.
//
// voxref never links a GL dispatch library: the OSMesa context hands out OSMesa's entry points
// and the EGL context (real GPUs) the vendor's, so one binary can use either. Loading fails with
// a GlUnavailable naming the first missing entry point.
#pragma once

#include <GL/glcorearb.h>

#include <functional>
#include <string>

namespace voxref::gpu {

using GetProcAddress = std::function<void*(const char*)>;

struct GlApi {
  PFNGLGETSTRINGPROC GetString = nullptr;
  PFNGLGETSTRINGIPROC GetStringi = nullptr;
  PFNGLGETINTEGERVPROC GetIntegerv = nullptr;
  PFNGLGETERRORPROC GetError = nullptr;
  PFNGLENABLEPROC Enable = nullptr;
  PFNGLDISABLEPROC Disable = nullptr;
  PFNGLVIEWPORTPROC Viewport = nullptr;
  PFNGLCLEARCOLORPROC ClearColor = nullptr;
  PFNGLCLEARPROC Clear = nullptr;
  PFNGLFINISHPROC Finish = nullptr;
  PFNGLPIXELSTOREIPROC PixelStorei = nullptr;
  PFNGLREADPIXELSPROC ReadPixels = nullptr;
  PFNGLREADBUFFERPROC ReadBuffer = nullptr;
  PFNGLDRAWBUFFERSPROC DrawBuffers = nullptr;
  PFNGLBLENDFUNCPROC BlendFunc = nullptr;
  PFNGLBLENDEQUATIONPROC BlendEquation = nullptr;
  // Textures
  PFNGLGENTEXTURESPROC GenTextures = nullptr;
  PFNGLDELETETEXTURESPROC DeleteTextures = nullptr;
  PFNGLBINDTEXTUREPROC BindTexture = nullptr;
  PFNGLACTIVETEXTUREPROC ActiveTexture = nullptr;
  PFNGLTEXIMAGE3DPROC TexImage3D = nullptr;
  PFNGLTEXPARAMETERIPROC TexParameteri = nullptr;
  PFNGLTEXPARAMETERFVPROC TexParameterfv = nullptr;
  // Framebuffers
  PFNGLGENFRAMEBUFFERSPROC GenFramebuffers = nullptr;
  PFNGLDELETEFRAMEBUFFERSPROC DeleteFramebuffers = nullptr;
  PFNGLBINDFRAMEBUFFERPROC BindFramebuffer = nullptr;
  PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer = nullptr;
  PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus = nullptr;
  PFNGLGENRENDERBUFFERSPROC GenRenderbuffers = nullptr;
  PFNGLDELETERENDERBUFFERSPROC DeleteRenderbuffers = nullptr;
  PFNGLBINDRENDERBUFFERPROC BindRenderbuffer = nullptr;
  PFNGLRENDERBUFFERSTORAGEPROC RenderbufferStorage = nullptr;
  // Shaders and programs
  PFNGLCREATESHADERPROC CreateShader = nullptr;
  PFNGLSHADERSOURCEPROC ShaderSource = nullptr;
  PFNGLCOMPILESHADERPROC CompileShader = nullptr;
  PFNGLGETSHADERIVPROC GetShaderiv = nullptr;
  PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog = nullptr;
  PFNGLDELETESHADERPROC DeleteShader = nullptr;
  PFNGLCREATEPROGRAMPROC CreateProgram = nullptr;
  PFNGLATTACHSHADERPROC AttachShader = nullptr;
  PFNGLLINKPROGRAMPROC LinkProgram = nullptr;
  PFNGLGETPROGRAMIVPROC GetProgramiv = nullptr;
  PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog = nullptr;
  PFNGLDELETEPROGRAMPROC DeleteProgram = nullptr;
  PFNGLUSEPROGRAMPROC UseProgram = nullptr;
  PFNGLGETUNIFORMLOCATIONPROC GetUniformLocation = nullptr;
  PFNGLUNIFORM1IPROC Uniform1i = nullptr;
  PFNGLUNIFORM1FPROC Uniform1f = nullptr;
  PFNGLUNIFORM3FPROC Uniform3f = nullptr;
  PFNGLUNIFORM3IPROC Uniform3i = nullptr;
  // Vertex arrays and drawing
  PFNGLGENVERTEXARRAYSPROC GenVertexArrays = nullptr;
  PFNGLDELETEVERTEXARRAYSPROC DeleteVertexArrays = nullptr;
  PFNGLBINDVERTEXARRAYPROC BindVertexArray = nullptr;
  PFNGLDRAWARRAYSPROC DrawArrays = nullptr;
  // Meshes, depth and occlusion queries (the isosurface renderer).
  PFNGLGENBUFFERSPROC GenBuffers = nullptr;
  PFNGLDELETEBUFFERSPROC DeleteBuffers = nullptr;
  PFNGLBINDBUFFERPROC BindBuffer = nullptr;
  PFNGLBUFFERDATAPROC BufferData = nullptr;
  PFNGLBUFFERSUBDATAPROC BufferSubData = nullptr;
  PFNGLVERTEXATTRIBPOINTERPROC VertexAttribPointer = nullptr;
  PFNGLENABLEVERTEXATTRIBARRAYPROC EnableVertexAttribArray = nullptr;
  PFNGLDRAWELEMENTSPROC DrawElements = nullptr;
  PFNGLUNIFORMMATRIX4FVPROC UniformMatrix4fv = nullptr;
  PFNGLDEPTHFUNCPROC DepthFunc = nullptr;
  PFNGLDEPTHMASKPROC DepthMask = nullptr;
  PFNGLCOLORMASKPROC ColorMask = nullptr;
  PFNGLCLEARDEPTHPROC ClearDepth = nullptr;
  PFNGLGENQUERIESPROC GenQueries = nullptr;
  PFNGLDELETEQUERIESPROC DeleteQueries = nullptr;
  PFNGLBEGINQUERYPROC BeginQuery = nullptr;
  PFNGLENDQUERYPROC EndQuery = nullptr;
  PFNGLGETQUERYOBJECTUIVPROC GetQueryObjectuiv = nullptr;
  PFNGLCLEARBUFFERFVPROC ClearBufferfv = nullptr;
  PFNGLCLEARBUFFERUIVPROC ClearBufferuiv = nullptr;
  PFNGLCULLFACEPROC CullFace = nullptr;
  PFNGLFRONTFACEPROC FrontFace = nullptr;
  // Counting samples in a shader storage buffer (GL 4.3; gpu/iso_gl.h, SampleCounter::Buffer).
  // MemoryBarrier is GL 4.2: null where the context does not provide it, and the counter refuses.
  PFNGLBINDBUFFERBASEPROC BindBufferBase = nullptr;
  PFNGLGETBUFFERSUBDATAPROC GetBufferSubData = nullptr;
  PFNGLMEMORYBARRIERPROC MemoryBarrier = nullptr;
};

// Throws GlUnavailable (gl_error.h) naming the first entry point the context does not provide.
GlApi loadGlApi(const GetProcAddress& getProcAddress);

}  // namespace voxref::gpu
