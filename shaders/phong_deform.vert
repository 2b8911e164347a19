#version 330 core
// Phong Deformation on the GPU (James 2020, eq. 19): each embedded vertex is
//   f(X) = sum_i beta_i (x_i + H_i (X - X_i)),   H_i = alpha F_i,
// evaluated from its cell and local coordinates, and the normal from the gradient of f (cofactor
// of grad f times the rest normal). alpha = 0 is linear interpolation, 1/2 Phong, 1 the vertex
// model. The attribute method (Houdini's Point Deform, for comparison) instead moves the rest
// point by the weighted node displacements of its precomputed metaball neighbours, and keeps the
// Phong normal. Also passes a scalar field value to the fragment shader and clips against a plane.
//
// Cost: what does not change per frame is per-vertex data (rest point X and the inverse rest
// Jacobian dxi/dX), and the per-frame node data (O(nodes) upload) is x_i - H_i X_i with H_i, so
// that x_i + H_i (X - X_i) = (x_i - H_i X_i) + H_i X needs no rest node positions here.

layout(location = 0) in int cell;          // cell index
layout(location = 1) in vec3 local;        // tet: (beta1, beta2, beta3); hex: (s, t, u)
layout(location = 2) in vec3 restNormal;
layout(location = 3) in ivec2 neighbours;  // attribute method: first index and count
layout(location = 4) in vec3 restPoint;    // X
layout(location = 5) in mat3 restInverseJacobian;  // d xi / d X at X (locations 5, 6, 7)
layout(location = 8) in ivec4 cellNodesLow;   // the cell's node ids 0..3
layout(location = 9) in ivec4 cellNodesHigh;  // and 4..7 (-1 for a tetrahedron)

uniform samplerBuffer restNodes;    // rest position X_i per node (attribute method only)
uniform samplerBuffer frameNodes;   // 4 texels per node: x_i - H_i X_i, then the rows of H_i
uniform bool attributeMethod;
uniform isamplerBuffer attributeNodes;    // attribute method: neighbour node ids
uniform samplerBuffer attributeWeights;   // and their normalised weights
uniform int fieldMode;                    // 0 none, 1 per cell (cellField), 2 displacement length
uniform samplerBuffer cellField;
uniform vec4 clipPlane;                   // kept where dot(xyz, position) <= w
uniform mat4 modelView;
uniform mat4 projection;

out vec3 deformedPosition;  // world space, read back by transform feedback
out vec3 deformedNormal;
out vec3 viewPosition;      // view space, for lighting (per vertex rather than per fragment)
out vec3 viewNormal;
out float fieldValue;

// Rows of H_i from the frame texture (GLSL matrices are built from columns, hence the transpose).
mat3 nodeGradient(int node) {
  return transpose(mat3(texelFetch(frameNodes, 4 * node + 1).xyz,
                        texelFetch(frameNodes, 4 * node + 2).xyz,
                        texelFetch(frameNodes, 4 * node + 3).xyz));
}

void main() {
  int nodes[8] = int[8](cellNodesLow.x, cellNodesLow.y, cellNodesLow.z, cellNodesLow.w,
                        cellNodesHigh.x, cellNodesHigh.y, cellNodesHigh.z, cellNodesHigh.w);
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
  vec3 X = restPoint;
  vec3 position = vec3(0.0);
  mat3 dfdxi = mat3(0.0);
  mat3 blended = mat3(0.0);
  for (int a = 0; a < count; ++a) {
    mat3 Ha = nodeGradient(nodes[a]);
    vec3 model = texelFetch(frameNodes, 4 * nodes[a]).xyz + Ha * X;
    position += beta[a] * model;
    dfdxi += outerProduct(model, dbeta[a]);
    blended += beta[a] * Ha;
  }
  mat3 G = dfdxi * restInverseJacobian + blended;
  mat3 cofactor = mat3(cross(G[1], G[2]), cross(G[2], G[0]), cross(G[0], G[1]));
  vec3 n = cofactor * restNormal;
  deformedNormal = length(n) > 0.0 ? normalize(n) : restNormal;
  if (attributeMethod) {
    position = X;
    for (int k = 0; k < neighbours.y; ++k) {
      int node = texelFetch(attributeNodes, neighbours.x + k).r;
      vec3 restNode = texelFetch(restNodes, node).xyz;
      vec3 deformedNode = texelFetch(frameNodes, 4 * node).xyz + nodeGradient(node) * restNode;
      position += texelFetch(attributeWeights, neighbours.x + k).r * (deformedNode - restNode);
    }
  }
  deformedPosition = position;
  fieldValue = fieldMode == 1 ? texelFetch(cellField, cell).r
                              : (fieldMode == 2 ? length(position - X) : 0.0);
  gl_ClipDistance[0] = clipPlane.w - dot(clipPlane.xyz, position);
  vec4 eyePosition = modelView * vec4(position, 1.0);
  viewPosition = eyePosition.xyz;
  viewNormal = mat3(modelView) * deformedNormal;
  gl_Position = projection * eyePosition;
}
