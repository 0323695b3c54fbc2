// A subtly wrong combination shader (tests/CMakeLists.txt, check_shader.*): the built-in
// combination.frag with every grid's interpolant scaled by 0.999. The exact oracle must catch it.
uniform vec3 nodeScale;
uniform vec3 extent;
uniform vec3 brickOrigin;
uniform vec3 cellLo;
uniform vec3 cellHi;
uniform sampler3D grid;

out vec4 fragColor;

void main() {
  vec3 p = samplePoint();
  if (outsideUnitCube(p)) discard;
  PRECISE vec3 c = p * nodeScale;
  if (any(lessThan(c, cellLo)) || any(greaterThanEqual(c, cellHi))) discard;
  PRECISE vec3 u = (c + 0.5 - brickOrigin) / extent;
  fragColor = vec4(0.999 * texture(grid, u).r, 0.0, 0.0, 0.0);
}
