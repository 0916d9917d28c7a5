// Ground coloured by altitude and slope, or by a condition map (the overlay).
in vec3 vWorld;
in vec3 vNormal;
in vec2 vMapUv;

layout(binding = 3) uniform sampler2D uOverlay;
uniform int uHasOverlay;
uniform vec2 uAltitudeRange;  // lowest and highest altitude of the map

out vec4 outColor;

float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }

void main() {
#ifdef SHADOW_PASS
  return;
#else
  vec3 normal = normalize(vNormal);
  vec3 albedo;
  if (uHasOverlay != 0) {
    albedo = texture(uOverlay, vMapUv).rgb;
  } else {
    float height = clamp((vWorld.y - uAltitudeRange.x) / max(uAltitudeRange.y - uAltitudeRange.x, 1.0), 0.0, 1.0);
    vec3 meadow = mix(vec3(0.045, 0.09, 0.018), vec3(0.10, 0.10, 0.035), height);
    vec3 rock = vec3(0.13, 0.12, 0.10);
    float steep = smoothstep(0.70, 0.55, normal.y);  // slopes steeper than about 50 degrees
    albedo = mix(meadow, rock, steep);
    // Two octaves of value noise break up the flat colour at ground level.
    vec2 cell = floor(vWorld.xz * 0.5);
    albedo *= 0.85 + 0.15 * hash(cell) + 0.1 * hash(floor(vWorld.xz * 0.05));
  }
  outColor = vec4(shade(albedo, normal, vWorld, 0.0), 1.0);
#endif
}
