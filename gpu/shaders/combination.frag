// One pass of the combination technique (Teitzel et al. 1999, section 6): the trilinear
// interpolant of one component grid at the sampling plane's points, to be blended with
// GL_FUNC_ADD or GL_FUNC_REVERSE_SUBTRACT into the plane's framebuffer.
//
// The sample point is derived from gl_FragCoord (exactly pixel + 0.5) instead of an interpolated
// varying, whose bits depend on the driver's fused multiply-adds (PRECISION.md). On voxref's
// plane-frame lattice every operation of `p` and `c` is exact in float32; `u` rounds once, in the
// division (reference/sparsegrid/combination_textures.h, which also explains bricks). PRECISE is
// `precise` from GLSL 4.00 on.

uniform vec3 planeOrigin;  // sample point of pixel (0, 0) minus half a pixel step in x and y
uniform vec3 pixelDx;      // step between horizontally adjacent pixels
uniform vec3 pixelDy;      // step between vertically adjacent pixels
uniform vec3 nodeScale;    // 2^l per axis: sample coordinate -> node coordinate
uniform vec3 extent;       // texels per axis of this brick
uniform vec3 brickOrigin;  // first texel of the brick in the grid's texture (0 when unbricked)
uniform vec3 cellLo;       // node coordinates the brick serves: cellLo <= c < cellHi
uniform vec3 cellHi;
uniform sampler3D grid;

out vec4 fragColor;

void main() {
  PRECISE vec3 p = planeOrigin + gl_FragCoord.x * pixelDx + gl_FragCoord.y * pixelDy;
  if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) discard;
  PRECISE vec3 c = p * nodeScale;  // exact: a power-of-two scale
  if (any(lessThan(c, cellLo)) || any(greaterThanEqual(c, cellHi))) discard;  // another brick's cells
  PRECISE vec3 u = (c + 0.5 - brickOrigin) / extent;
  fragColor = vec4(texture(grid, u).r, 0.0, 0.0, 0.0);
}
