// Two-sided Lambert with a headlight, reference/iso/iso_shading.h:
//   shade = ambient + (1 - ambient) * |n . l|, l towards the eye.
in vec3 vNormal;
in vec3 vWorld;
uniform vec3 uEye;
uniform float uAmbient;
layout(location = 0) out vec4 fragColor;
layout(location = 1) out uint primitiveId;  // triangle index + 1 (0: nothing drawn)
void main() {
  vec3 n = normalize(vNormal);
  vec3 l = normalize(uEye - vWorld);
  float shade = uAmbient + (1.0 - uAmbient) * abs(dot(n, l));
  fragColor = vec4(shade, shade, shade, 1.0);
  primitiveId = uint(gl_PrimitiveID) + 1u;
}
