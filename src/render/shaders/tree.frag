// Tree materials: textured bark, alpha-masked leaf and needle cards, crown proxies.
in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;
flat in vec3 vTint;
flat in float vFade;

layout(binding = 0) uniform sampler2D uTexture;
uniform vec4 uBaseColor;
uniform int uHasTexture;
uniform int uAlphaMask;
uniform float uTranslucency;

#ifdef BAKE
layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;
#else
out vec4 outColor;
#endif

void main() {
#ifndef BAKE
  if (!ditherKeeps(vFade)) discard;
#endif
  vec4 albedo = uBaseColor;
  if (uHasTexture != 0) albedo *= texture(uTexture, vUv);
  if (uAlphaMask != 0 && albedo.a < 0.5) discard;
#ifdef SHADOW_PASS
  return;
#else
  vec3 normal = normalize(vNormal);
  if (!gl_FrontFacing) normal = -normal;  // double-sided cards light from the side seen
#ifdef BAKE
  outAlbedo = vec4(albedo.rgb * vTint, 1.0);
  outNormal = vec4(normal * 0.5 + 0.5, uTranslucency);
#else
  outColor = vec4(shade(albedo.rgb * vTint, normal, vWorld, uTranslucency), 1.0);
#endif
#endif
}
