#version 430
// Buffer slots: TETSKIN_SLOT_* (modules/rendering/src/GpuContract.h defines them).
// TetSkin gpu-2pass, pass 1b: area-weighted face normals (twice the area times
// the unit normal) of the deformed surface.
layout(local_size_x = 64) in;
layout(std430, binding = TETSKIN_SLOT_DEFORMED_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = TETSKIN_SLOT_TRIANGLES) readonly buffer Triangles { ivec4 triangles[]; };
layout(std430, binding = TETSKIN_SLOT_FACE_NORMALS) writeonly buffer FaceNormals { vec4 faces[]; };
uniform int triangleCount;
void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= uint(triangleCount)) return;
  ivec4 tri = triangles[t];
  vec3 a = positions[tri.x].xyz, b = positions[tri.y].xyz, c = positions[tri.z].xyz;
  faces[t] = vec4(cross(b - a, c - a), 0.0);
}
