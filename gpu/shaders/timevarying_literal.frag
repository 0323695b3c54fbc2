// The fragment shader of Binotto et al. 2003 (appendix, Cg), ported to GLSL word for word, traps
// included: the integer macros make DR / TEX_DIM = 8 / 128 = 0, and the alpha = 1 test takes any
// opaque homogeneous colour for a refinement address. Needs the paper's layout (level 4, 128^3).
// samplePoint() (sample_point.glsl) stands for IN.texCoord, derived exactly from gl_FragCoord.
#define TEX_DIM 128
#define DR 8

uniform vec3 origin;  // the index slot of the time step, normalized (equation 1 as voxref lays it out)
uniform sampler3D texIndex;
uniform sampler3D texRefinement;

out vec4 fragColor;

void main() {
  vec3 texCoord = samplePoint();
  if (outsideUnitCube(texCoord)) discard;
  vec4 color = texture(texIndex, origin.xyz + texCoord / DR);
  vec3 refIndex = color.xyz + mod(texCoord, DR / TEX_DIM);
  if (color.w == 1.0) color = texture(texRefinement, refIndex);
  fragColor = color;
}
