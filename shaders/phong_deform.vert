#version 330 core
// Phong Deformation on the GPU (James 2020, eq. 19): each embedded vertex is
//   f(X) = sum_i beta_i (x_i + H_i (X - X_i)),   H_i = alpha F_i,
// evaluated from its cell and local coordinates, with per-frame node data in a buffer texture
// (O(nodes) upload), and the normal from the gradient of f (cofactor of grad f times the rest
// normal). alpha = 0 is linear interpolation, 1/2 Phong, 1 the vertex model. The attribute method
// (Houdini's Point Deform, for comparison) instead moves the rest point by the weighted node
// displacements of its precomputed metaball neighbours, and keeps the Phong normal.
// Also passes a scalar field value to the fragment shader and clips against one plane.

layout(location = 0) in int cell;          // cell index
layout(location = 1) in vec3 local;        // tet: (beta1, beta2, beta3); hex: (s, t, u)
layout(location = 2) in vec3 restNormal;
layout(location = 3) in ivec2 neighbours;  // attribute method: first index and count

uniform isamplerBuffer cellNodes;   // 8 node ids per cell; a tet has -1 in slots 4..7
uniform samplerBuffer restNodes;    // rest position X_i per node (xyz of RGBA)
uniform samplerBuffer frameNodes;   // 4 texels per node: x_i, then the rows of F_i
uniform float alpha;
uniform bool attributeMethod;
uniform isamplerBuffer attributeNodes;    // attribute method: neighbour node ids
uniform samplerBuffer attributeWeights;   // and their normalised weights
uniform int fieldMode;                    // 0 none, 1 per cell (cellField), 2 displacement length
uniform samplerBuffer cellField;
uniform vec4 clipPlane;                   // kept where dot(xyz, position) <= w
uniform mat4 modelView;
uniform mat4 projection;

out vec3 deformedPosition;
out vec3 deformedNormal;
out float fieldValue;

void main() {
  int nodes[8];
  for (int k = 0; k < 8; ++k) nodes[k] = texelFetch(cellNodes, 8 * cell + k).r;
  bool tetrahedron = nodes[4] < 0;
  int count = tetrahedron ? 4 : 8;
  float beta[8];
  vec3 dbeta[8];  // d beta / d xi
  if (tetrahedron) {
    beta[0] = 1.0 - local.x - local.y - local.z;
    beta[1] = local.x;
    beta[2] = local.y;
    beta[3] = local.z;
    dbeta[0] = vec3(-1.0);
    dbeta[1] = vec3(1.0, 0.0, 0.0);
    dbeta[2] = vec3(0.0, 1.0, 0.0);
    dbeta[3] = vec3(0.0, 0.0, 1.0);
  } else {
    for (int a = 0; a < 8; ++a) {
      // VTK corner order: 0 (0,0,0) 1 (1,0,0) 2 (1,1,0) 3 (0,1,0), then the same at u = 1.
      vec3 corner = vec3(float(a == 1 || a == 2 || a == 5 || a == 6),
                         float(a == 2 || a == 3 || a == 6 || a == 7), float(a >= 4));
      vec3 f = mix(vec3(1.0) - local, local, corner);
      vec3 df = mix(vec3(-1.0), vec3(1.0), corner);
      beta[a] = f.x * f.y * f.z;
      dbeta[a] = vec3(df.x * f.y * f.z, f.x * df.y * f.z, f.x * f.y * df.z);
    }
  }
  vec3 X = vec3(0.0);
  mat3 dXdxi = mat3(0.0);
  for (int a = 0; a < count; ++a) {
    vec3 Xa = texelFetch(restNodes, nodes[a]).xyz;
    X += beta[a] * Xa;
    dXdxi += outerProduct(Xa, dbeta[a]);
  }
  vec3 position = vec3(0.0);
  mat3 dfdxi = mat3(0.0);
  mat3 blended = mat3(0.0);
  for (int a = 0; a < count; ++a) {
    int base = 4 * nodes[a];
    vec3 xa = texelFetch(frameNodes, base).xyz;
    // Rows of F_a; GLSL matrices are built from columns, hence the transpose.
    mat3 Fa = transpose(mat3(texelFetch(frameNodes, base + 1).xyz,
                             texelFetch(frameNodes, base + 2).xyz,
                             texelFetch(frameNodes, base + 3).xyz));
    vec3 model = xa + alpha * (Fa * (X - texelFetch(restNodes, nodes[a]).xyz));
    position += beta[a] * model;
    dfdxi += outerProduct(model, dbeta[a]);
    blended += beta[a] * alpha * Fa;
  }
  mat3 G = dfdxi * inverse(dXdxi) + blended;
  mat3 cofactor = mat3(cross(G[1], G[2]), cross(G[2], G[0]), cross(G[0], G[1]));
  vec3 n = cofactor * restNormal;
  deformedNormal = length(n) > 0.0 ? normalize(n) : restNormal;
  if (attributeMethod) {
    position = X;
    for (int k = 0; k < neighbours.y; ++k) {
      int node = texelFetch(attributeNodes, neighbours.x + k).r;
      position += texelFetch(attributeWeights, neighbours.x + k).r *
                  (texelFetch(frameNodes, 4 * node).xyz - texelFetch(restNodes, node).xyz);
    }
  }
  deformedPosition = position;
  fieldValue = fieldMode == 1 ? texelFetch(cellField, cell).r
                              : (fieldMode == 2 ? length(position - X) : 0.0);
  gl_ClipDistance[0] = clipPlane.w - dot(clipPlane.xyz, position);
  gl_Position = projection * modelView * vec4(position, 1.0);
}
