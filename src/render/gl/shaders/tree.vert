// Instanced tree meshes (LOD0-2): the model's vertices plus their wind bases, per-instance
// placement, and the cross-fade code.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec3 aSwaySin;
layout(location = 4) in vec3 aSwayCos;
layout(location = 5) in vec3 aBendEast;
layout(location = 6) in vec3 aBendSouth;
layout(location = 7) in float aSkyVisibility;  // through the tree's own crown
layout(location = 8) in vec4 iPositionYaw;  // world position of the stem base, yaw (radians)
layout(location = 9) in vec4 iScale;        // horizontal scale, vertical scale, keep from, phase
layout(location = 10) in vec4 iTint;        // rgb multiplier, keep up to
layout(location = 11) in vec2 iLean;        // the site's lean, a steady directed wind (east, south)

out vec3 vWorld;
out vec3 vNormal;
out vec2 vUv;
out float vSkyVisibility;
flat out vec3 vTint;
flat out vec2 vKeep;  // the dither thresholds this draw keeps: [lo, hi)
#ifdef FEEDBACK
out vec3 fbLocal;  // the displaced vertex in its tree's frame, for the wind test
#endif

void main() {
  float yaw = iPositionYaw.w;
  float t = uCamera.w + iScale.w;
  vec3 windWorld = vec3(uWind.x, 0.0, uWind.y);
  vec3 windLocal = rotateYaw(windWorld, -yaw);
  vec3 leanLocal = rotateYaw(vec3(iLean.x, 0.0, iLean.y), -yaw);
  vec3 local = aPosition + windOffset(aSwaySin, aSwayCos, aBendEast, aBendSouth, t,
                                      windLocal.xz, uWind.z, uWind.w) +
               leanLocal.x * aBendEast + leanLocal.z * aBendSouth;
#ifdef FEEDBACK
  fbLocal = local;
#endif
  vec3 scale = vec3(iScale.x, iScale.y, iScale.x);
  vWorld = iPositionYaw.xyz + rotateYaw(local * scale, yaw);
  vNormal = rotateYaw(normalize(aNormal / scale), yaw);
  vUv = aUv;
  vSkyVisibility = aSkyVisibility;
  vTint = iTint.rgb;
  vKeep = vec2(iScale.z, iTint.w);
#ifdef SHADOW_PASS
  gl_Position = uLightViewProj * vec4(vWorld, 1.0);
#else
  gl_Position = uViewProj * vec4(vWorld, 1.0);
#endif
}
