flat in vec3 vCentre;
flat in vec3 vRight, vUp, vToward;
flat in vec2 vFrameScale;
flat in vec2 vCell[3];
flat in vec3 vWeight;
flat in vec3 vTint;
flat in vec2 vKeep;
flat in float vYaw;
flat in vec2 vScale;
flat in uint vCoverageSeed;
flat in float vSpriteShare;

layout(binding = 1) uniform sampler2D uAlbedoAtlas;
layout(binding = 2) uniform sampler2D uNormalAtlas;
layout(binding = 5) uniform sampler2D uDepthAtlas;
uniform int uFrames;

out vec4 outColor;

void main() {
  if (!ditherKeeps(vKeep)) discard;
  // gl_PointCoord runs downward; the atlas (OpenGL's convention) upward. The sprite covers
  // vSpriteShare of the bounding sphere's square (impostor.vert), in whose units the rest
  // is reckoned.
  vec2 onSprite = vSpriteShare * (vec2(gl_PointCoord.x, 1.0 - gl_PointCoord.y) * 2.0 - 1.0);
  vec2 inFrame = onSprite * vFrameScale * 0.5 + 0.5;
  if (any(lessThan(inFrame, vec2(0.0))) || any(greaterThan(inFrame, vec2(1.0)))) discard;
  // The atlases hold values times coverage (alpha), filtered and mipmapped as such: a
  // texel's alpha is the share of it that the tree covers, and dividing by it gives the
  // mean over what covers it. The frames blend by their weights before the division, so a
  // pixel that only one frame covers keeps that frame's colour at its weight's coverage:
  // the silhouettes dissolve into each other as the view turns. (Each frame is shown as
  // it is: reprojecting it onto the sprite's plane, right for a flat card, measured further
  // from the mesh for a crown, which looks about as wide from every side.)
  vec4 albedo = vec4(0.0), packedNormal = vec4(0.0), depthAndSky = vec4(0.0);
  for (int i = 0; i < 3; ++i) {
    if (vWeight[i] <= 0.0) continue;  // the same for the whole sprite
    vec2 uv = (vCell[i] + inFrame) / float(uFrames);
#ifdef SHADOW_PASS
    albedo.a += vWeight[i] * texture(uDepthAtlas, uv).a;
#else
    albedo += vWeight[i] * texture(uAlbedoAtlas, uv);
    packedNormal += vWeight[i] * texture(uNormalAtlas, uv);
    depthAndSky += vWeight[i] * texture(uDepthAtlas, uv);
#endif
  }
  // A hashed alpha test: a far texel half covered by twigs keeps half its pixels (half the
  // samples of each, anti-aliased), as the mesh's thin branches hit about that share of
  // pixel centres, instead of vanishing at a fixed threshold of one half.
  const int coverage = coverageMask(albedo.a, vCoverageSeed);
  if (coverage == 0) discard;
  gl_SampleMask[0] = coverage;
#ifdef SHADOW_PASS
  return;
#else
  packedNormal /= albedo.a;
  // Not normalised: at the coarser mip levels the mean of many leaves' normals is shorter
  // than one, and shade() lights it as leaves facing many ways.
  vec3 normal = packedNormal.xyz * 2.0 - 1.0;
  // The frame shows the tree at its type's proportions; a crown narrower or wider than its
  // type's turns its leaves' normals as the mesh's do (tree.vert: the normal divided by the
  // scale), toward the horizontal in a slender crown. The mean keeps its length.
  float meanLength = length(normal);
  if (meanLength > 1e-4) normal = normalize(normal / vScale.xyx) * meanLength;
  normal = rotateYaw(normal, vYaw);
  // The pixel's own place in the crown, so that it takes its own shadow and fog: inner
  // and far-side leaves fall in the shadow of the tree and its neighbours as a mesh's do.
  depthAndSky /= albedo.a;
  float toward = depthAndSky.r * 2.0 - 1.0;
  vec3 world = vCentre + onSprite.x * vRight + onSprite.y * vUp + toward * vToward;
  outColor = vec4(
      shade(albedo.rgb / albedo.a * vTint, normal, world, packedNormal.a, depthAndSky.g), 1.0);
#endif
}
