// TetSkin fur-gpu: fur vertices read the surface the gpu-2pass compute pass
// deformed (positions, smooth normals, last frame's positions) and are
// extruded here; shells are instances (gl_InstanceID), fins are not.
uniform samplerBuffer tetskinDeformedPositions;
uniform samplerBuffer tetskinDeformedNormals;
uniform samplerBuffer tetskinPreviousPositions;
uniform int tetskinShellCount;    // 0: not instanced (fins)
uniform float tetskinFurLength;   // model units
uniform float tetskinFrameSeconds;
uniform float tetskinDrag;
uniform float tetskinMaxBend;
uniform float tetskinMinLift;
in float tetskinFurSource;  // vertex of the unsplit surface, exact as float up to 2^24
// The formula of tetskin::furShellOffset (modules/fur/FurDynamics.h).
vec3 tetskinShellOffset(vec3 n, vec3 velocity, float h) {
  float rise = h * tetskinFurLength;
  vec3 shift = -tetskinDrag * h * h * velocity;
  float norm = length(shift);
  float bound = tetskinMaxBend * rise;
  if (norm > bound) shift *= bound / norm;
  float lift = rise + dot(shift, n);
  if (lift < tetskinMinLift * rise) shift += (tetskinMinLift * rise - lift) * n;
  return rise * n + shift;
}
