// TetSkin gpu-1pass, embed bindings: per vertex the embedding tetrahedron's
// nodes and weights and the rest normal (uploaded once), and per node the
// control mesh's positions and normal transforms (texture buffers, uploaded
// every frame).
uniform samplerBuffer tetskinControlPositions;  // xyz_ per dataset node
uniform samplerBuffer tetskinNormalTransforms;  // per dataset node 3 texels: G's columns, xyz_
in vec4 tetskinControlIds;  // exact as floats up to 2^24
in vec4 tetskinWeights;
in vec4 tetskinShift;       // x y z: the displacement offset's constant part
in vec3 tetskinRestNormal;  // the rest surface's vertex normal
//VTK::CustomUniforms::Dec
