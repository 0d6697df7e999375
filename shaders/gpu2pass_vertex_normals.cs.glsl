#version 430
// Buffer slots: TETSKIN_SLOT_* (modules/rendering/src/GpuContract.h defines them).
// TetSkin gpu-2pass, pass 1c: smooth vertex normals by gathering each
// vertex's one-ring of faces (no atomics), normalized.
layout(local_size_x = 64) in;
layout(std430, binding = TETSKIN_SLOT_FACE_NORMALS) readonly buffer FaceNormals { vec4 faces[]; };
layout(std430, binding = TETSKIN_SLOT_RING_OFFSETS) readonly buffer RingOffsets { int offsets[]; };
layout(std430, binding = TETSKIN_SLOT_RING_FACES) readonly buffer RingFaces { int ring[]; };
layout(std430, binding = TETSKIN_SLOT_DEFORMED_NORMALS) writeonly buffer Normals { vec4 normals[]; };
uniform int vertexCount;
void main() {
  uint v = gl_GlobalInvocationID.x;
  if (v >= uint(vertexCount)) return;
  vec3 n = vec3(0.0);
  for (int i = offsets[v]; i < offsets[v + 1]; ++i) n += faces[ring[i]].xyz;
  float len = length(n);
  normals[v] = vec4(len > 0.0 ? n / len : n, 0.0);
}
