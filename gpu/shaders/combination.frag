// One pass of the combination technique (Teitzel et al. 1999, section 6): the trilinear
// interpolant of one component grid at the sampling plane's points, to be blended with
// GL_FUNC_ADD or GL_FUNC_REVERSE_SUBTRACT into the plane's framebuffer.
//
// samplePoint() comes from sample_point.glsl. Every operation of `p` and `c` is exact in float32;
// `u` rounds once, in the division (reference/sparsegrid/combination_textures.h, which also
// explains bricks). PRECISE is `precise` from GLSL 4.00 on.

uniform vec3 nodeScale;    // 2^l per axis: sample coordinate -> node coordinate
uniform vec3 extent;       // texels per axis of this brick
uniform vec3 brickOrigin;  // first texel of the brick in the grid's texture (0 when unbricked)
uniform vec3 cellLo;       // node coordinates the brick serves: cellLo <= c < cellHi
uniform vec3 cellHi;
uniform sampler3D grid;

out vec4 fragColor;

void main() {
  vec3 p = samplePoint();
  if (outsideUnitCube(p)) discard;
  PRECISE vec3 c = p * nodeScale;  // exact: a power-of-two scale
  if (any(lessThan(c, cellLo)) || any(greaterThanEqual(c, cellHi))) discard;  // another brick's cells
  PRECISE vec3 u = (c + 0.5 - brickOrigin) / extent;
  fragColor = vec4(texture(grid, u).r, 0.0, 0.0, 0.0);
}
