// The oracles' image of the mesh (IsoMeshRenderer::render): its colour (iso_shading.glsl) and,
// for each pixel, the triangle drawn there.
layout(location = 0) out vec4 fragColor;
layout(location = 1) out uint primitiveId;  // triangle index + 1 (0: nothing drawn)
void main() {
  fragColor = isoShadedColour();
  primitiveId = uint(gl_PrimitiveID) + 1u;
}
