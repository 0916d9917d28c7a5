// Grass and herb tufts near the camera (render/scene/ground_cover.hpp): three crossed cards
// a tuft, shrinking to nothing over the outer half of the ground cover's radius so that
// none pops in, their tips swaying in the wind.
layout(location = 0) in vec3 aCorner;  // x across the card (-0.5..0.5), y up (0..1), z its angle
layout(location = 1) in vec4 iFoot;    // world position of the tuft's foot; w its height (m)
layout(location = 2) in vec4 iLook;    // x yaw (radians), y plant (0 grass, 1 herb), z variation,
                                       // w the ground's moisture (Ellenberg F)

uniform float uRadius;        // of the ground cover (m)
uniform vec2 uAltitudeRange;  // lowest and highest altitude of the map

out vec3 vWorld;
out vec3 vNormal;
out vec2 vUv;
flat out float vPlant;
flat out vec3 vAlbedo;
flat out uint vCoverageSeed;  // the card's own alpha-test thresholds

void main() {
  float height = iFoot.w * smoothstep(uRadius, 0.5 * uRadius, distance(iFoot.xyz, uCamera.xyz));
  float angle = iLook.x + aCorner.z;
  vec3 across = vec3(cos(angle), 0.0, sin(angle));
  vec3 world = iFoot.xyz + across * (aCorner.x * height) + vec3(0.0, aCorner.y * height, 0.0);
  // The tip bends with the wind, the foot stays: the directed wind with its gusts and the
  // undirected sway, each tuft in its own phase, at most a third of its height.
  float t = uCamera.w, phase = 6.2831853 * iLook.z;
  vec2 bend = 0.1 * uWind.xy * (1.0 + uWind.w * sin(0.31 * t + phase)) +
              0.05 * uWind.z * vec2(sin(t + phase), cos(1.3 * t + phase));
  float reach = length(bend);
  if (reach > 0.33) bend *= 0.33 / reach;
  world.xz += bend * aCorner.y * aCorner.y * height;
  vWorld = world;
  // Lit nearly as the ground under it is: a card's own normal, tilted toward the sky (the
  // blades of a tuft face every way).
  vNormal = normalize(vec3(0.0, 1.0, 0.0) + 0.5 * vec3(-across.z, 0.0, across.x));
  vUv = vec2(aCorner.x + 0.5, aCorner.y);
  vPlant = iLook.y;
  vCoverageSeed = coverageSeed(vec3(iFoot.xz, aCorner.z));
  float variation = 0.85 + 0.3 * iLook.z;
  if (iLook.y < 0.5) {
    // The meadow's own colour where the tuft stands, as the terrain shows it.
    float altitudeShare = clamp((iFoot.y - uAltitudeRange.x) / max(uAltitudeRange.y - uAltitudeRange.x, 1.0), 0.0, 1.0);
    vAlbedo = meadowGrass(altitudeShare, groundPatches(iFoot.xz), iLook.w) * variation;
  } else {
    vAlbedo = vec3(0.030, 0.070, 0.018) * variation;  // a woodland herb's deeper green
  }
  gl_Position = uViewProj * vec4(world, 1.0);
}
