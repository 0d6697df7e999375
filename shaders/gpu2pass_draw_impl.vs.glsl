// One VBO entry per surface point, so gl_VertexID is the point id.
vec4 deformedMC = vec4(texelFetch(tetskinDeformedPositions, gl_VertexID).xyz, 1.0);
vec3 deformedNormalMC = texelFetch(tetskinDeformedNormals, gl_VertexID).xyz;
//VTK::CustomBegin::Impl
