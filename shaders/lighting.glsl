// Shared by the surface fragment shaders (prepended after the #version line by render/).
// Two-light Blinn-Phong in view space (a key light over the viewer's shoulder, a dim fill from
// the other side), two-sided so that open or inverted patches stay visible.
vec3 blinnPhong(vec3 n, vec3 v, vec3 l, vec3 tint, vec3 baseColour) {
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float specular = pow(max(dot(n, h), 0.0), 48.0) * step(0.0, diffuse);
  return tint * (diffuse * baseColour + 0.25 * specular);
}

vec4 shade(vec3 viewPosition, vec3 viewNormal, vec3 baseColour) {
  vec3 n = normalize(viewNormal);
  vec3 v = normalize(-viewPosition);
  if (dot(n, v) < 0.0) n = -n;
  vec3 c = 0.12 * baseColour;
  c += blinnPhong(n, v, normalize(vec3(0.4, 0.6, 0.7)), vec3(1.0), baseColour);
  c += blinnPhong(n, v, normalize(vec3(-0.6, -0.2, 0.4)), vec3(0.35), baseColour);
  return vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
