// TetSkin gpu-1pass: position = sum w_i x_i + s + d n, n the unit normal of
// the deformed control triangle (exact under rigid motion), s the
// displacement offset's constant part; the normal is the control vertex
// normals interpolated with the same weights (as the report).
ivec3 tetskinIds = ivec3(round(tetskinControlIds));
vec3 tetskinA = texelFetch(tetskinControlPositions, tetskinIds.x).xyz;
vec3 tetskinB = texelFetch(tetskinControlPositions, tetskinIds.y).xyz;
vec3 tetskinC = texelFetch(tetskinControlPositions, tetskinIds.z).xyz;
vec3 tetskinFace = cross(tetskinB - tetskinA, tetskinC - tetskinA);
float tetskinLength = length(tetskinFace);
vec3 tetskinPosition = tetskinWeights.x * tetskinA + tetskinWeights.y * tetskinB +
                       tetskinWeights.z * tetskinC + tetskinShift.xyz;
if (tetskinLength > 0.0) tetskinPosition += (tetskinShift.w / tetskinLength) * tetskinFace;
vec4 deformedMC = vec4(tetskinPosition, 1.0);
vec3 deformedNormalMC = normalize(
    tetskinWeights.x * texelFetch(tetskinControlNormals, tetskinIds.x).xyz +
    tetskinWeights.y * texelFetch(tetskinControlNormals, tetskinIds.y).xyz +
    tetskinWeights.z * texelFetch(tetskinControlNormals, tetskinIds.z).xyz);
//VTK::CustomBegin::Impl
