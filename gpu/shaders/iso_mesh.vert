// The isosurface mesh (gpu/iso_gl.h): positions in grid coordinates, one MVP matrix.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uMvp;
out vec3 vNormal;
out vec3 vWorld;
void main() {
  vNormal = aNormal;
  vWorld = aPosition;
  gl_Position = uMvp * vec4(aPosition, 1.0);
}
