#version 330 core
// Two-light Blinn-Phong in view space (a key light over the viewer's shoulder, a dim fill from
// the other side), two-sided so that open or inverted patches stay visible.
in vec3 viewPosition;
in vec3 viewNormal;

uniform vec3 baseColour;

out vec4 colour;

vec3 light(vec3 n, vec3 v, vec3 l, vec3 tint) {
  float diffuse = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float specular = pow(max(dot(n, h), 0.0), 48.0) * step(0.0, diffuse);
  return tint * (diffuse * baseColour + 0.25 * specular);
}

void main() {
  vec3 n = normalize(viewNormal);
  vec3 v = normalize(-viewPosition);
  if (dot(n, v) < 0.0) n = -n;
  vec3 c = 0.12 * baseColour;
  c += light(n, v, normalize(vec3(0.4, 0.6, 0.7)), vec3(1.0));
  c += light(n, v, normalize(vec3(-0.6, -0.2, 0.4)), vec3(0.35));
  colour = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
