// A combination shader with one error, on line 9 (tests/CMakeLists.txt, check_shader.*):
// voxref check-shader must report line 9 of this file, not of the prelude it prepends.
uniform sampler3D grid;

out vec4 fragColor;

void main() {
  vec3 p = samplePoint();
  fragColor = vec4(texture(grid, p).r * notDeclaredAnywhere, 0.0, 0.0, 0.0);
}
