// TetSkin fur-cpu: the CPU placed every fur vertex; pass the coordinates on.
vec4 deformedMC = vertexMC;
vec3 deformedNormalMC = normalMC;
tetskinFurCoordVSOutput = vec3(tetskinFurTCoords, tetskinFurHeight);
tetskinColorCoordVSOutput = tetskinColorTCoords;
