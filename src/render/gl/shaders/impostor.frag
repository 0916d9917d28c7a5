flat in vec3 vCentre;
flat in vec3 vRight, vUp, vToward;
flat in vec2 vCell;
flat in vec3 vTint;
flat in vec2 vKeep;
flat in float vYaw;

layout(binding = 1) uniform sampler2D uAlbedoAtlas;
layout(binding = 2) uniform sampler2D uNormalAtlas;
layout(binding = 5) uniform sampler2D uDepthAtlas;
uniform int uFrames;

out vec4 outColor;

void main() {
  if (!ditherKeeps(vKeep)) discard;
  // gl_PointCoord runs downward; the atlas (OpenGL's convention) upward.
  vec2 uv = (vCell + vec2(gl_PointCoord.x, 1.0 - gl_PointCoord.y)) / float(uFrames);
  // The atlases hold values times coverage (alpha), filtered and mipmapped as such: a
  // texel's alpha is the share of it that the tree covers, and dividing by it gives the
  // mean over what covers it.
  vec4 albedo = texture(uAlbedoAtlas, uv);
  // A hashed alpha test: a far texel half covered by twigs keeps half its pixels, as the
  // mesh's thin branches hit about that share of pixel centres, instead of vanishing at a
  // fixed threshold of one half.
  if (albedo.a <= coverageThreshold()) discard;
#ifdef SHADOW_PASS
  return;
#else
  vec4 packedNormal = texture(uNormalAtlas, uv) / albedo.a;
  // Not normalised: at the coarser mip levels the mean of many leaves' normals is shorter
  // than one, and shade() lights it as leaves facing many ways.
  vec3 normal = rotateYaw(packedNormal.xyz * 2.0 - 1.0, vYaw);
  // The pixel's own place in the crown, so that it takes its own shadow and fog: inner
  // and far-side leaves fall in the shadow of the tree and its neighbours as a mesh's do.
  vec2 onSprite = vec2(gl_PointCoord.x, 1.0 - gl_PointCoord.y) * 2.0 - 1.0;
  vec4 depthAndSky = texture(uDepthAtlas, uv) / albedo.a;
  float toward = depthAndSky.r * 2.0 - 1.0;
  vec3 world = vCentre + onSprite.x * vRight + onSprite.y * vUp + toward * vToward;
  outColor = vec4(
      shade(albedo.rgb / albedo.a * vTint, normal, world, packedNormal.a, depthAndSky.g), 1.0);
#endif
}
