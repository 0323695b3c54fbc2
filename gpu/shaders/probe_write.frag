// A probe write (reference/common/probe_frames.h): every pixel writes the RGBA value of its pass,
// fetched without filtering or conversion from an RGBA32F texture (layer = pass).
uniform sampler3D values;
uniform int layer;

out vec4 fragColor;

void main() { fragColor = texelFetch(values, ivec3(ivec2(gl_FragCoord.xy), layer), 0); }
