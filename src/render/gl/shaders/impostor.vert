// Hemi-octahedral impostors: one point sprite per tree, showing the baked frame whose
// direction is nearest to the direction the tree is seen from. A sprite is one vertex where a
// quad would be four: at a hundred thousand far trees the vertex stage is the cost.
layout(location = 8) in vec4 iPositionYaw;
layout(location = 9) in vec4 iScale;
layout(location = 10) in vec4 iTint;

uniform vec4 uBounds;  // xyz centre of the baked bounding sphere (tree frame), w its radius
uniform int uFrames;   // frames per side of the atlas
uniform float uPixelsPerUnit;  // viewport height / 2 times projection[1][1]

out vec3 vWorld;
flat out vec2 vCell;
flat out vec3 vTint;
flat out vec2 vKeep;  // the dither thresholds this draw keeps: [lo, hi)
flat out float vYaw;

void main() {
  float yaw = iPositionYaw.w;
  vec3 scale = vec3(iScale.x, iScale.y, iScale.x);
  vec3 centreWorld = iPositionYaw.xyz + rotateYaw(uBounds.xyz * scale, yaw);
  vec3 local = rotateYaw(normalize(uCamera.xyz - centreWorld), -yaw);
  local.y = max(local.y, 0.0);  // seen from below the horizon: the horizon frame
  vCell = clamp(floor(hemiOctEncode(local) * float(uFrames)), 0.0, float(uFrames - 1));
  vWorld = centreWorld;
  vTint = iTint.rgb;
  vKeep = vec2(iScale.z, iTint.w);
  vYaw = yaw;
  gl_Position = uViewProj * vec4(centreWorld, 1.0);
  // The sphere's diameter on screen; the sprite is a screen-aligned square, which for a tree
  // this small differs from the frame's own plane by less than a pixel.
  gl_PointSize = 2.0 * uBounds.w * max(scale.x, scale.y) * uPixelsPerUnit / max(gl_Position.w, 1e-3);
}
