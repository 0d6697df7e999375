// TetSkin fur-gpu: place this fur vertex above its deformed surface vertex.
int tetskinSource = int(round(tetskinFurSource));
vec3 tetskinSkin = texelFetch(tetskinDeformedPositions, tetskinSource).xyz;
vec3 tetskinNormal = normalize(texelFetch(tetskinDeformedNormals, tetskinSource).xyz);
vec3 tetskinVelocity = vec3(0.0);
if (tetskinFrameSeconds > 0.0)
  tetskinVelocity = (tetskinSkin - texelFetch(tetskinPreviousPositions, tetskinSource).xyz) /
                    tetskinFrameSeconds;
float tetskinHeight = tetskinFurHeight;
if (tetskinShellCount > 0) tetskinHeight += float(gl_InstanceID + 1) / float(tetskinShellCount);
vec4 deformedMC =
    vec4(tetskinSkin + tetskinShellOffset(tetskinNormal, tetskinVelocity, tetskinHeight), 1.0);
vec3 deformedNormalMC = tetskinNormal;
tetskinFurCoordVSOutput = vec3(tetskinFurTCoords, tetskinHeight);
tetskinColorCoordVSOutput = tetskinColorTCoords;
