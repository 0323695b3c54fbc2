// Occlusion boxes counted in one draw (gpu/iso_gl.h, SampleCounter::Buffer): 36 vertices a box, in
// the order of the boxes drawn, so a vertex's box is its index over 36 (gl_VertexID counts from the
// draw's first vertex, 0 here).
layout(location = 0) in vec3 aPosition;
uniform mat4 uMvp;
flat out uint vBox;
void main() {
  vBox = uint(gl_VertexID) / 36u;
  gl_Position = uMvp * vec4(aPosition, 1.0);
}
