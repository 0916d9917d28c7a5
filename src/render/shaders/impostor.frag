in vec3 vWorld;
in vec2 vUv;
flat in vec3 vTint;
flat in float vFade;
flat in float vYaw;

layout(binding = 1) uniform sampler2D uAlbedoAtlas;
layout(binding = 2) uniform sampler2D uNormalAtlas;

out vec4 outColor;

void main() {
  if (!ditherKeeps(vFade)) discard;
  vec4 albedo = texture(uAlbedoAtlas, vUv);
  if (albedo.a < 0.5) discard;
#ifndef SHADOW_PASS
  vec4 packedNormal = texture(uNormalAtlas, vUv);
  vec3 normal = rotateYaw(normalize(packedNormal.xyz * 2.0 - 1.0), vYaw);
  outColor = vec4(shade(albedo.rgb * vTint, normal, vWorld, packedNormal.a), 1.0);
#endif
}
