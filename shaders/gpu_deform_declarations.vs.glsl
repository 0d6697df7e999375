// TetSkin gpu-1pass: per-vertex binding (uploaded once) and the control
// mesh state (a texture buffer, uploaded every frame).
uniform samplerBuffer tetskinControlPositions;  // xyz_ per dataset node
uniform samplerBuffer tetskinControlNormals;    // xyz_ per dataset node
in vec3 tetskinControlIds;  // exact as floats up to 2^24
in vec3 tetskinWeights;
in vec4 tetskinShift;  // x y z: the displacement offset's constant part; w: the normal offset d
//VTK::CustomUniforms::Dec
