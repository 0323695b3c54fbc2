// Occlusion-query boxes write nothing (colour and depth masks are off); the query counts samples.
layout(location = 0) out vec4 fragColor;
layout(location = 1) out uint primitiveId;
void main() {
  fragColor = vec4(1.0);
  primitiveId = 0u;
}
