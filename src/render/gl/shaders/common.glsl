// Shared by every shader: the frame's uniforms, wind, lighting, fog and dithering.
// C++ mirror: FrameUniforms in scene_renderer.hpp (std140: only vec4 and mat4 members).
layout(std140, binding = 0) uniform FrameBlock {
  mat4 uViewProj;
  mat4 uLightViewProj;    // the shadow pass being drawn: its cascade's
  mat4 uInverseViewProj;
  mat4 uShadowCascades[SHADOW_CASCADES];  // every cascade's, nearest first
  vec4 uCamera;      // xyz eye position; w wind time (radians of the sway oscillation)
  vec4 uToSun;       // xyz unit direction toward the sun; w 1 when the shadow map is used
  vec4 uSunColor;    // rgb beam; w fog density per metre
  vec4 uSkyZenith;   // rgb; w the altitude of the haze's base (m): the landscape's mean
  vec4 uSkyHorizon;  // rgb; w the haze's scale height (m)
  vec4 uAmbient;     // rgb sky light
  vec4 uWind;        // xy directed wind toward (east, south) in units of the bend basis;
                     // z undirected sway in units of the sway basis; w gust amplitude
};

layout(binding = 4) uniform sampler2DArrayShadow uShadowMap;  // a layer per cascade

// Wind displacement of a vertex in its tree's frame (docs/rendering.md): the undirected sway
// of EcoMod linearised in the branch rotations, sin(t) * swaySin + cos(t) * swayCos, plus the
// directed bend toward a horizontal wind, a sum over its two axes (bend bases for wind toward
// east and toward south). `windLocal` is the directed wind in the tree frame.
vec3 windOffset(vec3 swaySin, vec3 swayCos, vec3 bendEast, vec3 bendSouth, float t,
                vec2 windLocal, float sway, float gust) {
  float gustFactor = 1.0 + gust * sin(0.31 * t);
  return sway * (sin(t) * swaySin + cos(t) * swayCos) +
         gustFactor * (windLocal.x * bendEast + windLocal.y * bendSouth);
}

// Rotation about the vertical by yaw (radians), x east toward z south.
vec3 rotateYaw(vec3 v, float yaw) {
  float c = cos(yaw), s = sin(yaw);
  return vec3(c * v.x - s * v.z, v.y, s * v.x + c * v.z);
}

// The light reaching a point: 1 in the sun, 0 in full shadow. The finest cascade whose map
// holds the point (with room for the filter) answers; beyond the last there is no shadow.
float shadowAt(vec3 worldPosition) {
  if (uToSun.w < 0.5) return 1.0;
  vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0).xy);
  for (int c = 0; c < SHADOW_CASCADES; ++c) {
    vec4 p = uShadowCascades[c] * vec4(worldPosition, 1.0);
    vec3 q = p.xyz / p.w * 0.5 + 0.5;
    if (any(lessThan(q, vec3(texel, 0.0))) || any(greaterThan(q, vec3(1.0 - texel, 1.0))))
      continue;
    // A receiver is lit unless something lies nearer the sun by more than a texel's width
    // (plus 5 cm): the depth a texel holds is its centre's, and a surface slanted to the sun
    // changes depth across it. The bias grows with the cascade's texels (7 cm to 1.8 m), so
    // a sapling's shadow near the camera is kept and a far slope does not shadow itself.
    mat4 m = uShadowCascades[c];
    float texelMetres = 2.0 * texel.x / length(vec3(m[0][0], m[1][0], m[2][0]));
    float depthPerMetre = 0.5 * length(vec3(m[0][2], m[1][2], m[2][2]));
    float bias = (texelMetres + 0.05) * depthPerMetre;
    // 2x2 percentage-closer filtering on top of the hardware comparison.
    float lit = 0.0;
    for (int i = 0; i < 4; ++i) {
      vec2 o = (vec2(i & 1, i >> 1) - 0.5) * texel;
      lit += texture(uShadowMap, vec4(q.xy + o, float(c), q.z - bias));
    }
    return lit * 0.25;
  }
  return 1.0;
}

vec3 skyColor(vec3 direction) {
  float up = clamp(direction.y, 0.0, 1.0);
  vec3 sky = mix(uSkyHorizon.rgb, uSkyZenith.rgb, pow(up, 0.6));
  float sun = max(dot(direction, uToSun.xyz), 0.0);
  return sky + uSunColor.rgb * (0.02 * pow(sun, 8.0) + 4.0 * smoothstep(0.9995, 0.9999, sun));
}

// Aerial perspective: the air between the eye and a point dims its light and adds the
// sky's, more in blue than in red. uSunColor.w is the extinction at 550 nm (green) at the
// haze's base; the haze's aerosols scatter as lambda^-1.3 (Angstrom's exponent for
// continental air), so red (680 nm) takes 0.76 of it and blue (440 nm) 1.34: far hills turn
// blue-grey. The haze thins with height as exp(-height / scale height), so the extinction
// along the line to the point is the closed-form integral of that density over it: a view
// down from kilometres up crosses the dense air once, where a level view runs through it.
vec3 applyFog(vec3 color, vec3 worldPosition) {
  vec3 toPoint = worldPosition - uCamera.xyz;
  float distance = length(toPoint);
  float scaleHeight = uSkyHorizon.w;
  float rise = toPoint.y / scaleHeight;  // in scale heights
  // The line's mean density against the eye's: (1 - e^-rise) / rise, 1 for a level line.
  float alongLine = abs(rise) > 1e-3 ? (1.0 - exp(-rise)) / rise : 1.0 - 0.5 * rise;
  float atEye = exp(-(uCamera.y - uSkyZenith.w) / scaleHeight);
  vec3 visible = exp(-uSunColor.w * atEye * alongLine * distance * vec3(0.76, 1.0, 1.34));
  return mix(skyColor(normalize(vec3(toPoint.x, max(toPoint.y, 0.0) * 0.2, toPoint.z))), color,
             visible);
}

// Lambert lighting from the sun (with shadow) and the sky; `translucency` lets thin leaves
// pass light from behind. A normal shorter than one is the mean of the normals of several
// leaves (an impostor's coarser mip levels), lit as it is: max(c, 0) + t max(-c, 0) of the
// mean c = n.s is exactly the mean of its leaves' light where they all face the sun or all
// face away from it, and never more than that mean. Leaf cards are lit from the side seen,
// so a texel's leaves all face the viewer and, with the sun anywhere behind the viewer, the
// sun too. (Reading the shortened part as leaves facing every way of the sphere, a quarter
// of the beam each, lit a lone maple's impostor up to a quarter brighter than its mesh:
// Impostor.MatchesTheMeshAtEachQualitysSwitchingSize.) Unit normals are lit as by Lambert.
// `skyVisibility`: the share of the sky's light that reaches the point past nearby
// occluders (a tree's own crown: crown_shade.hpp); the sun's beam is the shadow map's.
vec3 shade(vec3 albedo, vec3 normal, vec3 worldPosition, float translucency,
           float skyVisibility) {
  float cosine = dot(normal, uToSun.xyz);
  float direct = max(cosine, 0.0) + translucency * max(-cosine, 0.0);
  // Linear in the normal, so that a mean normal gets the mean of its leaves' sky light.
  float skyLight = (0.6 + 0.4 * normal.y) * skyVisibility;
  vec3 light = uSunColor.rgb * direct * shadowAt(worldPosition) + uAmbient.rgb * skyLight;
  return applyFog(albedo * light, worldPosition);
}

// Screen-door dithering: every pixel has a threshold in [0, 1), and a draw keeps the pixels
// whose threshold lies in its range [lo, hi). A tree cross-fading between two levels of
// detail (or two age classes) is drawn twice with adjacent ranges, so together the draws
// cover each of its pixels once; a tree appearing or dying keeps a range shorter than 1.
#ifdef FRAGMENT_STAGE
bool ditherKeeps(vec2 range) {
  // A white-noise threshold per pixel: no pattern for the eye to catch during a fade.
  uvec2 p = uvec2(gl_FragCoord.xy);
  uint h = p.x * 1973u + p.y * 9277u;
  h = (h ^ (h >> 15)) * 0x2c1b3c6du;
  h = (h ^ (h >> 12)) * 0x297a2d39u;
  float threshold = float((h ^ (h >> 15)) & 0xffffu) / 65536.0;
  return threshold >= range.x && threshold < range.y;
}
#endif

// A seed of the surface an alpha-tested pixel belongs to (a sprite's tree, a tuft's card),
// from numbers that stay with it from frame to frame (its position, its look), for
// coverageMask().
uint coverageSeed(vec3 v) {
  uvec3 b = floatBitsToUint(v);
  uint h = b.x * 0x8da6b343u ^ b.y * 0xd8163841u ^ b.z * 0xcb1ab31fu;
  h = (h ^ (h >> 16)) * 0x7feb352du;
  return h ^ (h >> 15);
}

#ifdef FRAGMENT_STAGE
// The hashed alpha test of a texel whose alpha is the share of it covered (far impostor
// texels, grass blades; Wyman and McGuire 2017): the samples of this pixel it keeps, as a
// mask for gl_SampleMask (0: none, discard). With one sample a pixel the texel is kept where
// alpha exceeds the pixel's threshold u in (0, 1), hashed from the pixel and the surface
// (`seed`, coverageSeed(); independent of ditherKeeps', as a fading tree's pixels are not
// its alpha-tested ones), so a texel a fifth covered keeps a fifth of the pixels, as thin
// twigs hit about that share of pixel centres, where a fixed threshold of one half lost
// them. Each surface draws its own thresholds: crowns one behind the other let light through
// independently, as layers of leaves do (with one threshold a pixel for every sprite over
// it, a high threshold discarded them all, and a closed canopy of sprites showed the dark
// ground through gaps that overlapping crowns close). With n samples (anti-aliasing),
// sample s keeps where alpha exceeds ((s + turn) mod n + u) / n, the turn hashed as u is:
// the pixel takes the floor or the ceiling of alpha n of its samples, alpha's share on
// average, where it took all or none, and surfaces still take theirs independently
// (stochastic transparency: Enderton et al. 2010).
int coverageMask(float alpha, uint seed) {
  uvec2 p = uvec2(gl_FragCoord.xy);
  uint h = p.x * 7919u + p.y * 104729u + 0x9e3779b9u + seed;
  h = (h ^ (h >> 16)) * 0x7feb352du;
  h = (h ^ (h >> 15)) * 0x846ca68bu;
  h ^= h >> 16;
  float u = (float(h & 0xffffu) + 0.5) / 65536.0;
  int n = gl_NumSamples;
  int turn = int((h >> 16) % uint(n));
  int mask = 0;
  for (int s = 0; s < n; ++s)
    if (alpha * float(n) > float((s + turn) % n) + u) mask |= 1 << s;
  return mask;
}
#endif

// Smooth value noise in the ground plane (no blocks: each cell blends into its
// neighbours), and a sum of octaves of it.
float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }
float valueNoise(vec2 p) {
  vec2 i = floor(p), f = fract(p);
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(hash(i), hash(i + vec2(1, 0)), f.x), mix(hash(i + vec2(0, 1)), hash(i + vec2(1, 1)), f.x),
             f.y);
}
float octaves(vec2 p) {
  return 0.5 * valueNoise(p) + 0.3 * valueNoise(2.03 * p + 17.0) + 0.2 * valueNoise(4.01 * p + 41.0);
}

// The ground's patches of about 3 m (0..1), and the meadow's colour there: olive higher up
// (`altitudeShare` 0 at the map's lowest point, 1 at its highest), drier and lighter in
// patches; by the ground's `moisture` (Ellenberg F), browning toward straw on dry ground
// (F 4 down to 2.5) and lusher, darker and bluer on wet ground (F 6 up to 8). The terrain
// and the grass tufts standing on it (ground_cover.vert) share it.
float groundPatches(vec2 ground) { return octaves(ground * 0.33); }
vec3 meadowGrass(float altitudeShare, float patches, float moisture) {
  vec3 grass = mix(vec3(0.045, 0.09, 0.018), vec3(0.10, 0.10, 0.035), altitudeShare);
  grass = mix(grass, vec3(0.12, 0.10, 0.045), 0.8 * smoothstep(4.0, 2.5, moisture));
  grass = mix(grass, vec3(0.025, 0.065, 0.025), 0.8 * smoothstep(6.0, 8.0, moisture));
  return grass * mix(vec3(0.8, 0.85, 0.8), vec3(1.2, 1.15, 1.0), patches);
}

// Hemi-octahedral impostor frames (impostor.hpp): unit direction (y >= 0) -> [0, 1]^2.
vec2 hemiOctEncode(vec3 d) {
  d /= abs(d.x) + abs(d.y) + abs(d.z);
  return vec2(d.x + d.z, d.x - d.z) * 0.5 + 0.5;
}
