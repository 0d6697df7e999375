// TetSkin gpu-1pass, embed bindings: per vertex the embedding tetrahedron's
// nodes and weights and the rest normal carried into the tetrahedron's frame
// (uploaded once), and the control mesh's positions (a texture buffer,
// uploaded every frame).
uniform samplerBuffer tetskinControlPositions;  // xyz_ per dataset node
in vec4 tetskinControlIds;  // exact as floats up to 2^24
in vec4 tetskinWeights;
in vec4 tetskinShift;            // x y z: the displacement offset's constant part
in vec3 tetskinRestFrameNormal;  // D^T n: D the rest tetrahedron's edges, n the rest normal
//VTK::CustomUniforms::Dec
