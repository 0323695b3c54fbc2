// A subtly wrong decoder (tests/CMakeLists.txt, check_shader.*): timevarying_texel_centre.frag
// with the refinement lookup half a texel off its centre (+1.0 instead of +0.5), on the texel
// face, where NEAREST takes the next voxel. The exact oracle must catch it.
uniform vec3 slotTexel;
uniform float indexSize;
uniform float cells;
uniform float side;
uniform float blockSide;
uniform float refinementSize;
uniform sampler3D texIndex;
uniform sampler3D texRefinement;

out vec4 fragColor;

void main() {
  vec3 p = samplePoint();
  if (outsideUnitCube(p)) discard;
  PRECISE vec3 cell = min(floor(p * cells), vec3(cells - 1.0));
  PRECISE vec3 indexCoord = (slotTexel + cell + 0.5) / indexSize;
  vec4 c = texture(texIndex, indexCoord);
  if (c.a == 1.0) {
    PRECISE vec3 block = floor(c.xyz * 255.0 + 0.5);
    PRECISE vec3 voxel = min(floor(p * side), vec3(side - 1.0));
    PRECISE vec3 refCoord = (block * blockSide + (voxel - cell * blockSide) + 1.0) / refinementSize;
    c = texture(texRefinement, refCoord);
  }
  fragColor = c;
}
