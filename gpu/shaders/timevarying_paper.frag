// Binotto et al. 2003, section 6 and appendix, with the division in float and the layout as
// uniforms (reference/timevarying/decoder_variants.h, "paper"): index lookup at the time step's
// slot plus p / S, refinement lookup at the stored block origin plus the position inside the
// coarse cell. NEAREST lookups in both textures. Every expression is PRECISE.
uniform vec3 slotOrigin;   // slot / S
uniform float slotScale;   // 1 / S
uniform float cellSize;    // 1 / n: one coarse cell of the volume, normalized
uniform float blockScale;  // n / B: the cell's extent in the refinement texture per volume unit
uniform sampler3D texIndex;
uniform sampler3D texRefinement;

out vec4 fragColor;

void main() {
  vec3 p = samplePoint();
  if (outsideUnitCube(p)) discard;
  PRECISE vec3 indexCoord = slotOrigin + p * slotScale;
  vec4 c = texture(texIndex, indexCoord);
  PRECISE vec3 refCoord = c.xyz + mod(p, cellSize) * blockScale;
  if (c.a == 1.0) c = texture(texRefinement, refCoord);
  fragColor = c;
}
