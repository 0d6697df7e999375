// TetSkin gpu-2pass, pass 2: the draw reads what pass 1 computed.
uniform samplerBuffer tetskinDeformedPositions;
uniform samplerBuffer tetskinDeformedNormals;
//VTK::CustomUniforms::Dec
