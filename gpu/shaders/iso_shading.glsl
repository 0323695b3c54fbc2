// The isosurface mesh's shading, for iso_mesh.frag and iso_mesh_display.frag (prepended to each):
// two-sided Lambert with a headlight, reference/iso/iso_shading.h:
//   shade = ambient + (1 - ambient) * |n . l|, l towards the eye.
in vec3 vNormal;
in vec3 vWorld;
uniform vec3 uEye;
uniform float uAmbient;
vec4 isoShadedColour() {
  vec3 n = normalize(vNormal);
  vec3 l = normalize(uEye - vWorld);
  float shade = uAmbient + (1.0 - uAmbient) * abs(dot(n, l));
  return vec4(shade, shade, shade, 1.0);
}
