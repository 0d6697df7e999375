// TetSkin fur, vertex stage shared by fur-cpu and fur-gpu: the fur texture
// coordinates (s, t, height) and the colour-texture coordinates go to the
// fragment stage.
in vec2 tetskinFurTCoords;
in float tetskinFurHeight;
in vec2 tetskinColorTCoords;
out vec3 tetskinFurCoordVSOutput;
out vec2 tetskinColorCoordVSOutput;
