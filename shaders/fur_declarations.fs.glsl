// TetSkin fur, fragment stage (fur-cpu and fur-gpu).
uniform sampler3D tetskinFurTexture;    // (s, t, height): rgb shade, alpha hair
uniform sampler2D tetskinColorTexture;  // over the surface's own coordinates
uniform int tetskinHasColorTexture;
uniform int tetskinFins;              // 1: fade in near the silhouette only
uniform int tetskinKajiyaKay;         // 0: velvet highlight
uniform float tetskinVelvet;          // highlight offset from the mirror direction, [0, 1]
uniform vec3 tetskinLightVC;          // unit direction toward the light, view coordinates
uniform vec3 tetskinFurTint;          // the material colour
in vec3 tetskinFurCoordVSOutput;
in vec2 tetskinColorCoordVSOutput;
