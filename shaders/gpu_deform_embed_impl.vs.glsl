// TetSkin gpu-1pass, embed bindings: position = sum w_i x_i + s over the
// four nodes of the embedding tetrahedron (s the displacement offset's
// constant part), as the CPU computes it. The normal is the rest normal
// turned by sum w_i G_i, G_i the nodes' normal transforms (deformation
// NormalTransforms.h: each node's volume-weighted mean of its tetrahedra's
// cof(F)): continuous across the tetrahedra, exact under any affine
// deformation (the CPU path recomputes the surface's own normals).
ivec4 tetskinIds = ivec4(round(tetskinControlIds));
vec4 deformedMC = vec4(tetskinWeights.x * texelFetch(tetskinControlPositions, tetskinIds.x).xyz +
                       tetskinWeights.y * texelFetch(tetskinControlPositions, tetskinIds.y).xyz +
                       tetskinWeights.z * texelFetch(tetskinControlPositions, tetskinIds.z).xyz +
                       tetskinWeights.w * texelFetch(tetskinControlPositions, tetskinIds.w).xyz +
                       tetskinShift.xyz, 1.0);
vec3 tetskinNormal = vec3(0.0);
for (int tetskinK = 0; tetskinK < 4; ++tetskinK) {
  int tetskinFirst = 3 * tetskinIds[tetskinK];
  tetskinNormal += tetskinWeights[tetskinK] *
                   mat3(texelFetch(tetskinNormalTransforms, tetskinFirst).xyz,
                        texelFetch(tetskinNormalTransforms, tetskinFirst + 1).xyz,
                        texelFetch(tetskinNormalTransforms, tetskinFirst + 2).xyz) *
                   tetskinRestNormal;
}
vec3 deformedNormalMC = normalize(tetskinNormal);
//VTK::CustomBegin::Impl
