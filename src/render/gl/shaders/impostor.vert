// Hemi-octahedral impostors: one point sprite per tree, showing the baked frame whose
// direction is nearest to the direction the tree is seen from. A sprite is one vertex where a
// quad would be four: at a hundred thousand far trees the vertex stage is the cost.
layout(location = 8) in vec4 iPositionYaw;
layout(location = 9) in vec4 iScale;
layout(location = 10) in vec4 iTint;

uniform vec4 uBounds;  // xyz centre of the baked bounding sphere (tree frame), w its radius
uniform int uFrames;   // frames per side of the atlas
uniform float uPixelsPerUnit;  // viewport height / 2 times projection[1][1]

flat out vec3 vCentre;
// The sprite's world axes (right and up on the screen, toward the camera), each as long as
// the tree's bounding radius: where each of its pixels lies.
flat out vec3 vRight, vUp, vToward;
flat out vec2 vCell;
flat out vec3 vTint;
flat out vec2 vKeep;  // the dither thresholds this draw keeps: [lo, hi)
flat out float vYaw;

void main() {
  float yaw = iPositionYaw.w;
  vec3 scale = vec3(iScale.x, iScale.y, iScale.x);
  vec3 centreWorld = iPositionYaw.xyz + rotateYaw(uBounds.xyz * scale, yaw);
#ifdef SHADOW_PASS
  // Seen from the sun, through the shadow map's orthographic view.
  vec3 local = rotateYaw(uToSun.xyz, -yaw);
#else
  vec3 local = rotateYaw(normalize(uCamera.xyz - centreWorld), -yaw);
#endif
  local.y = max(local.y, 0.0);  // seen from below the horizon: the horizon frame
  vCell = clamp(floor(hemiOctEncode(local) * float(uFrames)), 0.0, float(uFrames - 1));
  vCentre = centreWorld;
  float radius = uBounds.w * max(scale.x, scale.y);
#ifdef SHADOW_PASS
  vec3 toward = uToSun.xyz;
#else
  vec3 toward = normalize(uCamera.xyz - centreWorld);
#endif
  vec3 right = cross(-toward, vec3(0.0, 1.0, 0.0));
  right = length(right) > 1e-4 ? normalize(right) : vec3(1.0, 0.0, 0.0);
  vRight = radius * right;
  vUp = radius * cross(right, -toward);
  vToward = radius * toward;
  vTint = iTint.rgb;
  vKeep = vec2(iScale.z, iTint.w);
  vYaw = yaw;
  float diameter = 2.0 * radius;
#ifdef SHADOW_PASS
  gl_Position = uLightViewProj * vec4(centreWorld, 1.0);
  gl_PointSize = diameter * uPixelsPerUnit;  // orthographic
#else
  gl_Position = uViewProj * vec4(centreWorld, 1.0);
  // The sphere's diameter on screen; the sprite is a screen-aligned square, which for a tree
  // this small differs from the frame's own plane by less than a pixel.
  gl_PointSize = diameter * uPixelsPerUnit / max(gl_Position.w, 1e-3);
#endif
}
