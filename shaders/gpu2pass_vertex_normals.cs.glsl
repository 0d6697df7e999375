#version 430
// TetSkin gpu-2pass, pass 1c: smooth vertex normals by gathering each
// vertex's one-ring of faces (no atomics), normalized.
layout(local_size_x = 64) in;
layout(std430, binding = 5) readonly buffer FaceNormals { vec4 faces[]; };
layout(std430, binding = 6) readonly buffer RingOffsets { int offsets[]; };
layout(std430, binding = 7) readonly buffer RingFaces { int ring[]; };
layout(std430, binding = 8) writeonly buffer Normals { vec4 normals[]; };
uniform int vertexCount;
void main() {
  uint v = gl_GlobalInvocationID.x;
  if (v >= uint(vertexCount)) return;
  vec3 n = vec3(0.0);
  for (int i = offsets[v]; i < offsets[v + 1]; ++i) n += faces[ring[i]].xyz;
  float len = length(n);
  normals[v] = vec4(len > 0.0 ? n / len : n, 0.0);
}
