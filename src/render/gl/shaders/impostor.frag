in vec3 vWorld;
flat in vec2 vCell;
flat in vec3 vTint;
flat in vec2 vKeep;
flat in float vYaw;

layout(binding = 1) uniform sampler2D uAlbedoAtlas;
layout(binding = 2) uniform sampler2D uNormalAtlas;
uniform int uFrames;

out vec4 outColor;

void main() {
  if (!ditherKeeps(vKeep)) discard;
  // gl_PointCoord runs downward; the atlas (OpenGL's convention) upward.
  vec2 uv = (vCell + vec2(gl_PointCoord.x, 1.0 - gl_PointCoord.y)) / float(uFrames);
  vec4 albedo = texture(uAlbedoAtlas, uv);
  if (albedo.a < 0.5) discard;
  vec4 packedNormal = texture(uNormalAtlas, uv);
  vec3 normal = rotateYaw(normalize(packedNormal.xyz * 2.0 - 1.0), vYaw);
  outColor = vec4(shade(albedo.rgb * vTint, normal, vWorld, packedNormal.a), 1.0);
}
