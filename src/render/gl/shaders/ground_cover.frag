// Grass and herb tufts: the atlas's plant (grass left, herb right) as a brightness on the
// tuft's colour, cut out by a hashed alpha test (sample by sample) so that far, mipmapped
// blades keep their share of the pixels instead of vanishing at a fixed threshold.
in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;
flat in float vPlant;
flat in vec3 vAlbedo;
flat in uint vCoverageSeed;

layout(binding = 7) uniform sampler2D uAtlas;

out vec4 outColor;

void main() {
  vec4 texel = texture(uAtlas, vec2((vPlant + vUv.x) * 0.5, vUv.y));
  const int coverage = coverageMask(texel.a, vCoverageSeed);
  if (coverage == 0) discard;
  gl_SampleMask[0] = coverage;
  vec3 normal = normalize(vNormal);
  if (!gl_FrontFacing) normal.xz = -normal.xz;
  // The tuft's own blades hide half the sky from its foot.
  float skyVisibility = mix(0.5, 1.0, vUv.y);
  outColor = vec4(shade(vAlbedo * texel.rgb * 1.4, normal, vWorld, 0.35, skyVisibility), 1.0);
}
