#version 430
// Buffer slots: TETSKIN_SLOT_* (modules/rendering/src/GpuContract.h defines them).
// TetSkin gpu-2pass, pass 1a: deformed positions, as SurfaceDeformer: sum
// w_i X_i over a triangle's 3 control nodes (or an embedding tetrahedron's
// 4), plus the shift: a constant vector (the Displacement offset) and the
// normal offset d along the deformed triangle's unit normal.
layout(local_size_x = 64) in;
layout(std430, binding = TETSKIN_SLOT_CONTROL_POSITIONS) readonly buffer ControlPositions { vec4 control[]; };
layout(std430, binding = TETSKIN_SLOT_BINDING_IDS) readonly buffer BindingIds { ivec4 ids[]; };  // 4th -1: a triangle
layout(std430, binding = TETSKIN_SLOT_BINDING_WEIGHTS) readonly buffer BindingWeights { vec4 weights[]; };
layout(std430, binding = TETSKIN_SLOT_BINDING_SHIFTS) readonly buffer BindingShifts { vec4 shifts[]; };  // x y z d
layout(std430, binding = TETSKIN_SLOT_DEFORMED_POSITIONS) writeonly buffer Positions { vec4 positions[]; };
uniform int vertexCount;
void main() {
  uint v = gl_GlobalInvocationID.x;
  if (v >= uint(vertexCount)) return;
  ivec4 id = ids[v];
  vec4 w = weights[v];
  vec4 shift = shifts[v];
  vec3 a = control[id.x].xyz, b = control[id.y].xyz, c = control[id.z].xyz;
  vec3 p = w.x * a + w.y * b + w.z * c + shift.xyz;
  if (id.w >= 0) {
    p += w.w * control[id.w].xyz;
  } else {
    vec3 n = cross(b - a, c - a);
    float len = length(n);
    if (len > 0.0) p += (shift.w / len) * n;
  }
  positions[v] = vec4(p, 1.0);
}
