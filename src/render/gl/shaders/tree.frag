// Tree materials: textured bark, alpha-masked leaf and needle cards, crown proxies.
in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;
in float vSkyVisibility;
flat in vec3 vTint;
flat in vec2 vKeep;

layout(binding = 0) uniform sampler2D uTexture;
uniform vec4 uBaseColor;
uniform int uHasTexture;
uniform int uAlphaMask;
uniform float uTranslucency;
uniform int uLeafyNoise;  // crown proxies (LOD2): break the smooth hull into leafy clumps

float hash3(vec3 p) { return fract(sin(dot(p, vec3(127.1, 311.7, 74.7))) * 43758.5453); }
float valueNoise(vec3 p) {
  vec3 i = floor(p), f = fract(p);
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(mix(hash3(i), hash3(i + vec3(1, 0, 0)), f.x),
                 mix(hash3(i + vec3(0, 1, 0)), hash3(i + vec3(1, 1, 0)), f.x), f.y),
             mix(mix(hash3(i + vec3(0, 0, 1)), hash3(i + vec3(1, 0, 1)), f.x),
                 mix(hash3(i + vec3(0, 1, 1)), hash3(i + vec3(1, 1, 1)), f.x), f.y), f.z);
}

#ifdef BAKE
layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outDepth;
#else
out vec4 outColor;
#endif

void main() {
#ifndef BAKE
  if (!ditherKeeps(vKeep)) discard;
#endif
#ifdef SHADOW_PASS
  // Only the coverage, where the material is masked: the texture bound is its linear view
  // (ForestRenderer::Material::coverage), whose alpha is the same.
  if (uAlphaMask != 0 &&
      uBaseColor.a * (uHasTexture != 0 ? texture(uTexture, vUv).a : 1.0) < 0.5)
    discard;
#else
  vec4 albedo = uBaseColor;
  if (uHasTexture != 0) albedo *= texture(uTexture, vUv);
  if (uAlphaMask != 0 && albedo.a < 0.5) discard;
  vec3 normal = normalize(vNormal);
  if (!gl_FrontFacing) normal = -normal;  // double-sided cards light from the side seen
  if (uLeafyNoise != 0) {
    // Clumps of about a metre: darker gaps between them and normals that scatter the light
    // like foliage instead of a smooth shell.
    float clump = valueNoise(vWorld * 1.3) * 0.65 + valueNoise(vWorld * 3.1) * 0.35;
    albedo.rgb *= 0.45 + 0.8 * clump;
    vec3 scatter = vec3(valueNoise(vWorld * 2.0 + 17.0), valueNoise(vWorld * 2.0 + 31.0),
                        valueNoise(vWorld * 2.0 + 47.0)) - 0.5;
    normal = normalize(normal + 1.2 * scatter);
  }
#ifdef BAKE
  outAlbedo = vec4(albedo.rgb * vTint, 1.0);
  outNormal = vec4(normal * 0.5 + 0.5, uTranslucency);
  // The bake's orthographic view spans 4 radii from 2 radii in front of the centre, so the
  // window depth z is 0.5 on the plane through the centre: toward the camera by
  // (2 - 4z) radii, stored in [0, 1] for [-1, 1] radii.
  // Green: the sky visibility inside the crown, for the impostor to shade with.
  outDepth = vec4(clamp(1.5 - 2.0 * gl_FragCoord.z, 0.0, 1.0), vSkyVisibility, 0.0, 1.0);
#else
  outColor =
      vec4(shade(albedo.rgb * vTint, normal, vWorld, uTranslucency, vSkyVisibility), 1.0);
#endif
#endif
}
