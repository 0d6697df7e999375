// TetSkin fur lighting, replacing VTK's: the fur texel's alpha is the hair,
// the colour texture tints it and masks it (alpha 0: no fur); specular light
// is scaled by the hair's alpha so gaps do not shine.
vec4 tetskinHair = texture(tetskinFurTexture, tetskinFurCoordVSOutput);
vec4 tetskinColor = vec4(1.0);
if (tetskinHasColorTexture != 0) tetskinColor = texture(tetskinColorTexture, tetskinColorCoordVSOutput);
if (tetskinColor.a < 0.5) discard;
vec3 tetskinN = normalize(normalVCVSOutput);  // VTK flipped it toward the viewer
vec3 tetskinV = vec3(0.0, 0.0, 1.0);
vec3 tetskinL = tetskinLightVC;
float tetskinAlpha = tetskinHair.a;
if (tetskinFins != 0) {
  // A fin is seen edge-on where its surface normal is perpendicular to the view.
  float tetskinFacing = abs(tetskinN.z);
  tetskinAlpha *= 1.0 - smoothstep(0.15, 0.45, tetskinFacing);
}
if (tetskinAlpha <= 0.004) discard;
vec3 tetskinBase = tetskinHair.rgb * tetskinColor.rgb * tetskinFurTint;
float tetskinDiffuse;
float tetskinSpecular;
if (tetskinKajiyaKay != 0) {
  // Kajiya-Kay: a hair runs along the normal it grew from.
  float tl = dot(tetskinN, tetskinL), tv = dot(tetskinN, tetskinV);
  float sinL = sqrt(max(0.0, 1.0 - tl * tl)), sinV = sqrt(max(0.0, 1.0 - tv * tv));
  tetskinDiffuse = 0.35 + 0.65 * sinL;
  tetskinSpecular = pow(max(0.0, tl * tv + sinL * sinV), specularPower);
} else {
  // Velvet: the highlight peaks at an angle off the mirror direction.
  vec3 tetskinH = normalize(tetskinL + tetskinV);
  float angle = acos(clamp(dot(tetskinN, tetskinH), -1.0, 1.0));
  float peak = tetskinVelvet * 1.2;
  tetskinDiffuse = max(0.0, dot(tetskinN, tetskinL)) * 0.8 + 0.2;
  tetskinSpecular = pow(max(0.0, cos(angle - peak)), max(1.0, 0.5 * specularPower));
}
gl_FragData[0] = vec4(tetskinBase * (0.15 + tetskinDiffuse) +
                          tetskinSpecular * specularColor * tetskinAlpha,
                      tetskinAlpha * opacity);
