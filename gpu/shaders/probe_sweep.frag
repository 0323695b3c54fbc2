// A probe sweep (reference/common/probe_frames.h): sample k = x + width * y of a LINEAR texture at
// u_k = uOrigin + k * uStep. k is an integer below 2^24 and uStep a power of two, so every
// operation is exact in float32 whatever the compiler fuses or reorders (docs/precision.md, "Shader
// arithmetic"): the sampler sees exactly the u the emulation is given.
uniform sampler3D tex;
uniform float uOrigin;
uniform float uStep;
uniform int width;

out vec4 fragColor;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  PRECISE float u = uOrigin + float(pixel.x + width * pixel.y) * uStep;
  fragColor = texture(tex, vec3(u, 0.5, 0.5));
}
