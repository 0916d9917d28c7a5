// Hemi-octahedral impostors: one point sprite per tree, showing the baked frames around the
// direction the tree is seen from. A sprite is one vertex where a quad would be four: at a
// hundred thousand far trees the vertex stage is the cost.
layout(location = 8) in vec4 iPositionYaw;
layout(location = 9) in vec4 iScale;
layout(location = 10) in vec4 iTint;

uniform vec4 uBounds;  // xyz centre of the baked bounding sphere (tree frame), w its radius
uniform int uFrames;   // frames per side of the atlas
uniform int uBlendFrames;      // 1: the three frames around the seen direction; 0: the nearest
uniform float uPixelsPerUnit;  // viewport height / 2 times projection[1][1]
uniform int uTilePixels;       // a frame's side in the atlas, in texels
uniform int uCropSprites;      // 1: sprites as large as their frames' content; 0: the sphere's
// Each frame's reach from its centre in units of its half side, at each mip level of the
// albedo atlas: [column, row, level] (ForestRenderer::frameExtentsTexture).
layout(binding = 9) uniform sampler2DArray uFrameExtents;

flat out vec3 vCentre;
// The sprite's world axes (right and up on the screen, toward the camera), each as long as
// the tree's bounding radius: where each of its pixels lies.
flat out vec3 vRight, vUp, vToward;
flat out vec2 vFrameScale;  // sprite units per frame unit along right and up (>= 1)
flat out vec2 vCell[3];  // the frames shown (column, row), with these weights
flat out vec3 vWeight;
flat out vec3 vTint;
flat out vec2 vKeep;  // the dither thresholds this draw keeps: [lo, hi)
flat out float vYaw;
flat out vec2 vScale;  // the tree's horizontal and vertical scale of its type
flat out uint vCoverageSeed;  // the tree's own alpha-test thresholds
flat out float vSpriteShare;  // the sprite's side as a share of the bounding sphere's

void main() {
  float yaw = iPositionYaw.w;
  vec3 scale = vec3(iScale.x, iScale.y, iScale.x);
  vec3 centreWorld = iPositionYaw.xyz + rotateYaw(uBounds.xyz * scale, yaw);
#ifdef SHADOW_PASS
  // Seen from the sun, through the shadow map's orthographic view.
  vec3 toward = uToSun.xyz;
#else
  vec3 toward = normalize(uCamera.xyz - centreWorld);
#endif
  vec3 local = rotateYaw(toward, -yaw);
  local.y = max(local.y, 0.0);  // seen from below the horizon: the horizon frames
  // Frame centres at whole numbers of the grid. Blending: the triangle of frame centres
  // around the seen direction, by barycentric weights (as octahedral impostors blend), so
  // the picture turns with the view instead of jumping from one frame to the next.
  vec2 grid = hemiOctEncode(local) * float(uFrames) - 0.5;
  vec2 base = floor(grid), f = grid - base;
#ifdef SHADOW_PASS
  // Shadows take the nearest frame: the frame a caster shows the sun does not change as the
  // camera moves, so blending would cost three texture reads for no jump it smooths.
  bool blend = false;
#else
  bool blend = uBlendFrames != 0;
#endif
  if (!blend) {
    vCell[0] = vCell[1] = vCell[2] = floor(grid + 0.5);
    vWeight = vec3(1.0, 0.0, 0.0);
  } else {
    bool lower = f.x + f.y <= 1.0;
    vCell[0] = lower ? base : base + 1.0;
    vCell[1] = base + vec2(1.0, 0.0);
    vCell[2] = base + vec2(0.0, 1.0);
    vWeight = lower ? vec3(1.0 - f.x - f.y, f.x, f.y) : vec3(f.x + f.y - 1.0, 1.0 - f.y, 1.0 - f.x);
  }
  for (int i = 0; i < 3; ++i) vCell[i] = clamp(vCell[i], 0.0, float(uFrames - 1));

  vCentre = centreWorld;
  float radius = uBounds.w * max(scale.x, scale.y);
  vec3 right = cross(-toward, vec3(0.0, 1.0, 0.0));
  right = length(right) > 1e-4 ? normalize(right) : vec3(1.0, 0.0, 0.0);
  vec3 up = cross(right, -toward);
  vRight = radius * right;
  vUp = radius * up;
  // A crown narrower or wider than its type's (scale.x against scale.y) is the frame
  // stretched along each of the sprite's axes by the tree's scale seen along it: the
  // horizontal right axis by scale.x, the up axis between scale.y seen level and scale.x seen
  // from above. The sprite is as large as the larger scale needs; the frame fills it along
  // that axis and less of it along the other.
  vFrameScale = radius / (uBounds.w * vec2(scale.x, length(scale * up)));
  vToward = uBounds.w * length(scale * toward) * toward;
  vTint = iTint.rgb;
  vKeep = vec2(iScale.z, iTint.w);
  vYaw = yaw;
  vScale = iScale.xy;
  vCoverageSeed = coverageSeed(iPositionYaw.xyz);
  float diameter = 2.0 * radius;
#ifdef SHADOW_PASS
  gl_Position = uLightViewProj * vec4(centreWorld, 1.0);
  float diameterPixels = diameter * uPixelsPerUnit;  // orthographic
#else
  gl_Position = uViewProj * vec4(centreWorld, 1.0);
  // The sphere's diameter on screen; the sprite is a screen-aligned square, which for a tree
  // this small differs from the frame's own plane by less than a pixel.
  float diameterPixels = diameter * uPixelsPerUnit / max(gl_Position.w, 1e-3);
#endif
  // The sprite covers no more than the frames' content reaches at the mip levels its pixels
  // read (trilinear filtering's two around the texels a pixel spans), plus a texel of the
  // coarser (bilinear filtering reads half of one beyond the last covered) and a pixel to
  // spare: its other pixels are transparent and would only cost fragments.
  diameterPixels = max(diameterPixels, 1.0);
  float texelsPerPixel =
      float(uTilePixels) * max(vFrameScale.x, vFrameScale.y) / diameterPixels;
  int levels = textureSize(uFrameExtents, 0).z;
  int coarser = clamp(int(floor(log2(max(texelsPerPixel, 1.0)))) + 1, 0, levels - 1);
  float extent = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (vWeight[i] <= 0.0) continue;
    for (int level = max(coarser - 1, 0); level <= coarser; ++level)
      extent = max(extent, texelFetch(uFrameExtents, ivec3(vCell[i], level), 0).r);
  }
  extent += exp2(float(coarser + 1)) / float(uTilePixels);
  vSpriteShare = uCropSprites == 0
                     ? 1.0
                     : min(1.0, extent / min(vFrameScale.x, vFrameScale.y) + 2.0 / diameterPixels);
  gl_PointSize = vSpriteShare * diameterPixels;
}
