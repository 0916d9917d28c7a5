// Hemi-octahedral impostors: one camera-facing quad per tree, showing the baked frame whose
// direction is nearest to the direction the tree is seen from.
layout(location = 0) in vec2 aCorner;  // (-1, -1) .. (1, 1)
layout(location = 8) in vec4 iPositionYaw;
layout(location = 9) in vec4 iScale;
layout(location = 10) in vec4 iTint;

uniform vec4 uBounds;  // xyz centre of the baked bounding sphere (tree frame), w its radius
uniform int uFrames;   // frames per side of the atlas

out vec3 vWorld;
out vec2 vUv;
flat out vec3 vTint;
flat out float vFade;
flat out float vYaw;

void main() {
  float yaw = iPositionYaw.w;
  vec3 scale = vec3(iScale.x, iScale.y, iScale.x);
  vec3 centreWorld = iPositionYaw.xyz + rotateYaw(uBounds.xyz * scale, yaw);
#ifdef SHADOW_PASS
  vec3 toViewer = uToSun.xyz;
#else
  vec3 toViewer = normalize(uCamera.xyz - centreWorld);
#endif
  vec3 local = rotateYaw(toViewer, -yaw);
  local.y = max(local.y, 0.0);  // seen from below the horizon: the horizon frame
  vec2 cell = clamp(floor(hemiOctEncode(local) * float(uFrames)), 0.0, float(uFrames - 1));
  vec3 f = hemiOctDecode((cell + 0.5) / float(uFrames));
  vec3 right, up;
  frameAxes(f, right, up);
  vec3 offset = uBounds.w * (aCorner.x * right + aCorner.y * up);
  vWorld = centreWorld + rotateYaw(offset * scale, yaw);
  vUv = (cell + aCorner * 0.5 + 0.5) / float(uFrames);
  vTint = iTint.rgb;
  vFade = iScale.z;
  vYaw = yaw;
#ifdef SHADOW_PASS
  gl_Position = uLightViewProj * vec4(vWorld, 1.0);
#else
  gl_Position = uViewProj * vec4(vWorld, 1.0);
#endif
}
