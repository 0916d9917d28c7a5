layout(location = 0) in vec3 aPosition;  // world
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aMapUv;     // (0, 0) at the north-west cell centre

out vec3 vWorld;
out vec3 vNormal;
out vec2 vMapUv;

void main() {
  vWorld = aPosition;
  vNormal = aNormal;
  vMapUv = aMapUv;
#ifdef SHADOW_PASS
  gl_Position = uLightViewProj * vec4(aPosition, 1.0);
#else
  gl_Position = uViewProj * vec4(aPosition, 1.0);
#endif
}
