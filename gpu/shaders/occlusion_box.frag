// Writes nothing the occlusion tests keep (the colour masks are off): the occluder's depth pass,
// and the query boxes (depth mask off too), whose samples the queries count.
layout(location = 0) out vec4 fragColor;
layout(location = 1) out uint primitiveId;
void main() {
  fragColor = vec4(1.0);
  primitiveId = 0u;
}
