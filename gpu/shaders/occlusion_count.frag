// Counts each box's samples that pass the depth test (gpu/iso_gl.h, SampleCounter::Buffer).
// early_fragment_tests (GLSL 4.60 section 4.4.1.3; GL 4.6 section 14.9.4): the depth test runs
// before this shader, which runs only for fragments that pass it; the target has one sample a
// pixel, so a fragment is a sample and the count is the samples-passed count of an occlusion query
// around the box's draw. Helper invocations (gl_HelperInvocation) write nothing: their atomics have
// no effect.
layout(early_fragment_tests) in;
layout(std430, binding = 0) buffer SampleCounts {
  uint counts[];
};
flat in uint vBox;
void main() {
  atomicAdd(counts[vBox], 1u);
}
