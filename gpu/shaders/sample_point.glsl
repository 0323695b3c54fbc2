// The sample point of this fragment on a plane frame (reference/common/plane_frame.h), derived
// from gl_FragCoord (exactly pixel + 0.5) instead of an interpolated varying, whose bits depend on
// the driver's fused multiply-adds (docs/precision.md). On voxref's plane-frame lattice every operation
// here is exact in float32, whatever a compiler reassociates or fuses.
uniform vec3 planeOrigin;  // sample point of pixel (0, 0) minus half a pixel step in x and y
uniform vec3 pixelDx;      // step between horizontally adjacent pixels
uniform vec3 pixelDy;      // step between vertically adjacent pixels

vec3 samplePoint() {
  PRECISE vec3 p = planeOrigin + gl_FragCoord.x * pixelDx + gl_FragCoord.y * pixelDy;
  return p;
}

bool outsideUnitCube(vec3 p) { return any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0))); }
