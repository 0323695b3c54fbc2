// A corrected decoder (reference/timevarying/decoder_variants.h, "texel_fetch"): integer
// addresses and texelFetch in both textures. Reads block_rgba8 indices.
uniform ivec3 slotTexelI;  // first texel of the time step's slot in the index texture
uniform int cellsI;        // n
uniform int sideI;         // voxels per axis
uniform int blockSideI;    // r
uniform float cells;
uniform float side;
uniform sampler3D texIndex;
uniform sampler3D texRefinement;

out vec4 fragColor;

void main() {
  vec3 p = samplePoint();
  if (outsideUnitCube(p)) discard;
  ivec3 cell = min(ivec3(p * cells), ivec3(cellsI - 1));
  vec4 c = texelFetch(texIndex, slotTexelI + cell, 0);
  if (c.a == 1.0) {
    ivec3 block = ivec3(c.xyz * 255.0 + 0.5);
    ivec3 voxel = min(ivec3(p * side), ivec3(sideI - 1));
    c = texelFetch(texRefinement, block * blockSideI + (voxel - cell * blockSideI), 0);
  }
  fragColor = c;
}
