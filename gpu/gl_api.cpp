#include "gpu/gl_api.h"

#include "gpu/gl_error.h"

namespace voxref::gpu {
namespace {

template <class Fn>
void load(const GetProcAddress& get, Fn& slot, const char* name) {
  slot = reinterpret_cast<Fn>(get(name));
  if (!slot) throw GlUnavailable(std::string("the GL context does not provide ") + name);
}

}  // namespace

GlApi loadGlApi(const GetProcAddress& get) {
  GlApi gl;
  load(get, gl.GetString, "glGetString");
  load(get, gl.GetStringi, "glGetStringi");
  load(get, gl.GetIntegerv, "glGetIntegerv");
  load(get, gl.GetError, "glGetError");
  load(get, gl.Enable, "glEnable");
  load(get, gl.Disable, "glDisable");
  load(get, gl.Viewport, "glViewport");
  load(get, gl.ClearColor, "glClearColor");
  load(get, gl.Clear, "glClear");
  load(get, gl.Finish, "glFinish");
  load(get, gl.PixelStorei, "glPixelStorei");
  load(get, gl.ReadPixels, "glReadPixels");
  load(get, gl.ReadBuffer, "glReadBuffer");
  load(get, gl.DrawBuffers, "glDrawBuffers");
  load(get, gl.BlendFunc, "glBlendFunc");
  load(get, gl.BlendEquation, "glBlendEquation");
  load(get, gl.GenTextures, "glGenTextures");
  load(get, gl.DeleteTextures, "glDeleteTextures");
  load(get, gl.BindTexture, "glBindTexture");
  load(get, gl.ActiveTexture, "glActiveTexture");
  load(get, gl.TexImage3D, "glTexImage3D");
  load(get, gl.TexParameteri, "glTexParameteri");
  load(get, gl.TexParameterfv, "glTexParameterfv");
  load(get, gl.GenFramebuffers, "glGenFramebuffers");
  load(get, gl.DeleteFramebuffers, "glDeleteFramebuffers");
  load(get, gl.BindFramebuffer, "glBindFramebuffer");
  load(get, gl.FramebufferRenderbuffer, "glFramebufferRenderbuffer");
  load(get, gl.CheckFramebufferStatus, "glCheckFramebufferStatus");
  load(get, gl.GenRenderbuffers, "glGenRenderbuffers");
  load(get, gl.DeleteRenderbuffers, "glDeleteRenderbuffers");
  load(get, gl.BindRenderbuffer, "glBindRenderbuffer");
  load(get, gl.RenderbufferStorage, "glRenderbufferStorage");
  load(get, gl.CreateShader, "glCreateShader");
  load(get, gl.ShaderSource, "glShaderSource");
  load(get, gl.CompileShader, "glCompileShader");
  load(get, gl.GetShaderiv, "glGetShaderiv");
  load(get, gl.GetShaderInfoLog, "glGetShaderInfoLog");
  load(get, gl.DeleteShader, "glDeleteShader");
  load(get, gl.CreateProgram, "glCreateProgram");
  load(get, gl.AttachShader, "glAttachShader");
  load(get, gl.LinkProgram, "glLinkProgram");
  load(get, gl.GetProgramiv, "glGetProgramiv");
  load(get, gl.GetProgramInfoLog, "glGetProgramInfoLog");
  load(get, gl.DeleteProgram, "glDeleteProgram");
  load(get, gl.UseProgram, "glUseProgram");
  load(get, gl.GetUniformLocation, "glGetUniformLocation");
  load(get, gl.Uniform1i, "glUniform1i");
  load(get, gl.Uniform1f, "glUniform1f");
  load(get, gl.Uniform3f, "glUniform3f");
  load(get, gl.Uniform3i, "glUniform3i");
  load(get, gl.GenVertexArrays, "glGenVertexArrays");
  load(get, gl.DeleteVertexArrays, "glDeleteVertexArrays");
  load(get, gl.BindVertexArray, "glBindVertexArray");
  load(get, gl.DrawArrays, "glDrawArrays");
  load(get, gl.GenBuffers, "glGenBuffers");
  load(get, gl.DeleteBuffers, "glDeleteBuffers");
  load(get, gl.BindBuffer, "glBindBuffer");
  load(get, gl.BufferData, "glBufferData");
  load(get, gl.BufferSubData, "glBufferSubData");
  load(get, gl.VertexAttribPointer, "glVertexAttribPointer");
  load(get, gl.EnableVertexAttribArray, "glEnableVertexAttribArray");
  load(get, gl.DrawElements, "glDrawElements");
  load(get, gl.UniformMatrix4fv, "glUniformMatrix4fv");
  load(get, gl.DepthFunc, "glDepthFunc");
  load(get, gl.DepthMask, "glDepthMask");
  load(get, gl.ColorMask, "glColorMask");
  load(get, gl.ClearDepth, "glClearDepth");
  load(get, gl.GenQueries, "glGenQueries");
  load(get, gl.DeleteQueries, "glDeleteQueries");
  load(get, gl.BeginQuery, "glBeginQuery");
  load(get, gl.EndQuery, "glEndQuery");
  load(get, gl.GetQueryObjectuiv, "glGetQueryObjectuiv");
  load(get, gl.ClearBufferfv, "glClearBufferfv");
  load(get, gl.ClearBufferuiv, "glClearBufferuiv");
  load(get, gl.CullFace, "glCullFace");
  load(get, gl.FrontFace, "glFrontFace");
  load(get, gl.BindBufferBase, "glBindBufferBase");
  load(get, gl.GetBufferSubData, "glGetBufferSubData");
  gl.MemoryBarrier = reinterpret_cast<PFNGLMEMORYBARRIERPROC>(get("glMemoryBarrier"));
  return gl;
}

}  // namespace voxref::gpu
