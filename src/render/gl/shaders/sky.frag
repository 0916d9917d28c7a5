in vec2 vNdc;
out vec4 outColor;
void main() {
  vec4 far = uInverseViewProj * vec4(vNdc, 1.0, 1.0);
  vec4 near = uInverseViewProj * vec4(vNdc, -1.0, 1.0);
  vec3 direction = normalize(far.xyz / far.w - near.xyz / near.w);
  outColor = vec4(skyColor(direction), 1.0);
}
