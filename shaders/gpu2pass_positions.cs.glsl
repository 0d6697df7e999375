#version 430
// TetSkin gpu-2pass, pass 1a: deformed positions (as SurfaceDeformer, normal offset).
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer ControlPositions { vec4 control[]; };
layout(std430, binding = 1) readonly buffer BindingIds { ivec4 ids[]; };
layout(std430, binding = 2) readonly buffer BindingWeights { vec4 weights[]; };  // w0 w1 w2 d
layout(std430, binding = 3) writeonly buffer Positions { vec4 positions[]; };
uniform int vertexCount;
void main() {
  uint v = gl_GlobalInvocationID.x;
  if (v >= uint(vertexCount)) return;
  ivec4 id = ids[v];
  vec4 w = weights[v];
  vec3 a = control[id.x].xyz, b = control[id.y].xyz, c = control[id.z].xyz;
  vec3 n = cross(b - a, c - a);
  float len = length(n);
  vec3 p = w.x * a + w.y * b + w.z * c;
  if (len > 0.0) p += (w.w / len) * n;
  positions[v] = vec4(p, 1.0);
}
