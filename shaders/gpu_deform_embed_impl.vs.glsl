// TetSkin gpu-1pass, embed bindings: position = sum w_i x_i + s over the
// four nodes of the embedding tetrahedron (s the displacement offset's
// constant part), as the CPU computes it. The normal is the rest normal
// carried by the tetrahedron's deformation gradient F = d D^-1 (d, D its
// deformed and rest edges), as normals transform: F^-T n = d^-T (D^T n).
// Exact under rigid motion; under other deformations it is constant over
// each tetrahedron (the CPU path recomputes the surface's own).
ivec4 tetskinIds = ivec4(round(tetskinControlIds));
vec3 tetskinX0 = texelFetch(tetskinControlPositions, tetskinIds.x).xyz;
vec3 tetskinX1 = texelFetch(tetskinControlPositions, tetskinIds.y).xyz;
vec3 tetskinX2 = texelFetch(tetskinControlPositions, tetskinIds.z).xyz;
vec3 tetskinX3 = texelFetch(tetskinControlPositions, tetskinIds.w).xyz;
vec4 deformedMC = vec4(tetskinWeights.x * tetskinX0 + tetskinWeights.y * tetskinX1 +
                       tetskinWeights.z * tetskinX2 + tetskinWeights.w * tetskinX3 +
                       tetskinShift.xyz, 1.0);
// d^-T m = cof(d) m / det(d), cof(d) the cofactor matrix: its columns are
// the cross products of d's columns. (Dividing by det, not taking its
// absolute value, keeps the normal's side through an inversion.)
vec3 tetskinE1 = tetskinX1 - tetskinX0;
vec3 tetskinE2 = tetskinX2 - tetskinX0;
vec3 tetskinE3 = tetskinX3 - tetskinX0;
mat3 tetskinCofactor = mat3(cross(tetskinE2, tetskinE3), cross(tetskinE3, tetskinE1),
                            cross(tetskinE1, tetskinE2));
float tetskinDet = dot(tetskinE1, tetskinCofactor[0]);
vec3 tetskinNormal = tetskinCofactor * tetskinRestFrameNormal;
vec3 deformedNormalMC = tetskinDet < 0.0 ? -normalize(tetskinNormal) : normalize(tetskinNormal);
//VTK::CustomBegin::Impl
