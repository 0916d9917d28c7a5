// Ground coloured by altitude, slope, moisture and the crowns above it (grass in the open,
// leaf litter and moss under trees, rock on steep slopes, the crowns themselves where their
// trees are too small to draw), or by a condition map (the overlay).
in vec3 vWorld;
in vec3 vNormal;
in vec2 vMapUv;

layout(binding = 3) uniform sampler2D uOverlay;
uniform int uHasOverlay;
uniform vec2 uAltitudeRange;  // lowest and highest altitude of the map
layout(binding = 6) uniform sampler2D uCanopyCover;  // share of each cell under crowns
uniform int uHasCanopyCover;
layout(binding = 8) uniform sampler2D uMoisture;  // Ellenberg F of each cell
uniform int uHasMoisture;
// The crowns of the trees too small to draw (forest_floor.hpp): the crown area of the trees
// shorter than 1, 2, 4 ... 128 m in cell areas (running sums), and their colour (linear).
layout(binding = 10) uniform sampler2D uCrownsBelowLow;   // under 1, 2, 4, 8 m
layout(binding = 11) uniform sampler2D uCrownsBelowHigh;  // under 16, 32, 64, 128 m
layout(binding = 12) uniform sampler2D uCrownColor;
// A tree shorter than this times its distance is not drawn (under a pixel); 0: none shown.
uniform float uUnresolvedPerMetre;

out vec4 outColor;

void main() {
#ifdef SHADOW_PASS
  return;
#else
  vec3 normal = normalize(vNormal);
  vec3 albedo;
  if (uHasOverlay != 0) {
    albedo = texture(uOverlay, vMapUv).rgb;
  } else {
    vec2 ground = vWorld.xz;
    float height = clamp((vWorld.y - uAltitudeRange.x) / max(uAltitudeRange.y - uAltitudeRange.x, 1.0), 0.0, 1.0);
    // Detail at three scales, so that no facet or cell shows from eye height to a
    // kilometre: tufts (0.3 m), patches (3 m) and swathes (30 m).
    float tufts = octaves(ground * 3.0), patches = groundPatches(ground), swathes = octaves(ground * 0.033);
    // Without a moisture field: fresh, F 5 (kFreshMoisture in sim/conditions/moisture.hpp).
    float moisture = uHasMoisture != 0 ? texture(uMoisture, vMapUv).r : 5.0;
    vec3 grass = meadowGrass(height, patches, moisture);
    // Forest floor: brown leaf litter with moss, the mix changing patch by patch.
    vec3 litter = mix(vec3(0.085, 0.050, 0.022), vec3(0.060, 0.045, 0.025), tufts);
    vec3 moss = vec3(0.035, 0.060, 0.015);
    vec3 floorColor = mix(litter, moss, smoothstep(0.45, 0.75, patches) * 0.7);
    float cover = uHasCanopyCover != 0 ? texture(uCanopyCover, vMapUv).r : 0.0;
    // The edge of the litter wanders with the patches instead of following the cells.
    float underCrowns = smoothstep(0.25, 0.65, cover + 0.3 * (patches - 0.5) + 0.2 * (swathes - 0.5));
    albedo = mix(grass, floorColor, underCrowns);
    // Rock on slopes steeper than about 50 degrees, its edge broken by the patches.
    vec3 rock = vec3(0.13, 0.12, 0.10) * (0.8 + 0.4 * tufts);
    float steep = smoothstep(0.70, 0.55, normal.y + 0.08 * (patches - 0.5));
    albedo = mix(albedo, rock, steep);
    albedo *= 0.8 + 0.4 * tufts;
    // The crowns of the trees too small to draw here cover the ground as they would cover
    // its pixel: their area below the height a pixel spans at this distance, read between
    // the doubling heights on a log scale (and from 0 below the first), as a cover of
    // 1 - exp(-area) like the litter's.
    if (uUnresolvedPerMetre > 0.0) {
      float cut = distance(vWorld, uCamera.xyz) * uUnresolvedPerMetre;
      vec4 low = texture(uCrownsBelowLow, vMapUv), high = texture(uCrownsBelowHigh, vMapUv);
      float below[8] = float[8](low.x, low.y, low.z, low.w, high.x, high.y, high.z, high.w);
      float crowns;
      if (cut <= 1.0) {
        crowns = below[0] * cut;
      } else {
        float octave = min(log2(cut), 7.0);
        int band = min(int(octave), 6);
        crowns = mix(below[band], below[band + 1], octave - float(band));
      }
      albedo = mix(albedo, texture(uCrownColor, vMapUv).rgb, 1.0 - exp(-crowns));
    }
  }
  outColor = vec4(shade(albedo, normal, vWorld, 0.0, 1.0), 1.0);
#endif
}
