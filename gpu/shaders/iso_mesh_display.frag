// The frame's image as a display shows it (IsoMeshRenderer::display): iso_mesh.frag's colour,
// without reading gl_PrimitiveID, which the oracles need and llvmpipe charges for (docs/iso.md,
// "The frame's image without the oracles' ids"). Like occlusion_box.frag it writes 0 ("nothing
// drawn") to the ids' attachment, which display() does not read.
layout(location = 0) out vec4 fragColor;
layout(location = 1) out uint primitiveId;
void main() {
  fragColor = isoShadedColour();
  primitiveId = 0u;
}
