// A corrected decoder (reference/timevarying/decoder_variants.h, "texel_centre"): integer cell,
// block and voxel numbers, every lookup at a texel centre, so NEAREST picks the intended texel
// with half a texel of margin. Reads block_rgba8 indices (integer block coordinates).
uniform vec3 slotTexel;        // first texel of the time step's slot in the index texture
uniform float indexSize;       // index texels per axis
uniform float cells;           // n
uniform float side;            // voxels per axis
uniform float blockSide;       // r
uniform float refinementSize;  // refinement texels per axis
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
    PRECISE vec3 refCoord = (block * blockSide + (voxel - cell * blockSide) + 0.5) / refinementSize;
    c = texture(texRefinement, refCoord);
  }
  fragColor = c;
}
