#version 330 core
// Phong Deformation on the GPU (James 2020, eq. 19): each embedded vertex is
//   f(X) = sum_i beta_i (x_i + H_i (X - X_i)),   H_i = alpha F_i,
// evaluated from its cell and local coordinates, and the normal from the gradient of f (cofactor
// of grad f times the rest normal). alpha = 0 is linear interpolation, 1/2 Phong, 1 the vertex
// model. The attribute method (Houdini's Point Deform, for comparison) instead moves the rest
// point by the weighted node displacements of its precomputed metaball neighbours, and keeps the
// Phong normal. Also evaluates the scalar field shown. Runs once per vertex per new frame with
// transform feedback (render/phong_gpu_deformer.cpp); deformed_surface.vert then draws the result.
//
// Cost (vertex processing dominates drawing here): what does not change per frame is per-vertex
// data (rest point X, inverse rest Jacobian dxi/dX, the cell's nodes); the per-frame node data
// (O(nodes) upload, 3 texels per node) is x_i - H_i X_i with H_i, so that
// x_i + H_i (X - X_i) = (x_i - H_i X_i) + H_i X needs no rest node positions. Data that only a
// field or the attribute method needs is fetched by vertex id when they are on.

layout(location = 1) in vec3 local;        // tet: (beta1, beta2, beta3); hex: (s, t, u)
layout(location = 2) in vec3 restNormal;
layout(location = 4) in vec3 restPoint;    // X
layout(location = 5) in mat3 restInverseJacobian;  // d xi / d X at X (locations 5, 6, 7)
layout(location = 8) in ivec4 cellNodesLow;   // the cell's node ids 0..3
layout(location = 9) in ivec4 cellNodesHigh;  // and 4..7 (-1 for a tetrahedron)

uniform samplerBuffer restNodes;    // rest position X_i per node (attribute method only)
uniform samplerBuffer frameNodes;   // 3 texels per node: (x_i - H_i X_i, H_i row-major)
uniform isamplerBuffer vertexCells;       // per vertex: its cell (for cell fields)
uniform isamplerBuffer neighbourRanges;   // per vertex: attribute neighbours (first, count)
uniform bool attributeMethod;
uniform isamplerBuffer attributeNodes;    // attribute method: neighbour node ids
uniform samplerBuffer attributeWeights;   // and their normalised weights
uniform int fieldMode;  // 0 none, 1 per cell (cellField), 2 displacement length, 3 per node
uniform samplerBuffer cellField;
uniform samplerBuffer nodeField;  // per node, interpolated as the position is (embed/node_field.h)

out vec3 deformedPosition;  // world space, captured by transform feedback
out vec3 deformedNormal;
out float fieldValue;

// Node i's offset x_i - H_i X_i and H_i from its 3 texels (12 floats).
void nodeFrame(int node, out vec3 offset, out mat3 H) {
  vec4 a = texelFetch(frameNodes, 3 * node);
  vec4 b = texelFetch(frameNodes, 3 * node + 1);
  vec4 c = texelFetch(frameNodes, 3 * node + 2);
  offset = a.xyz;
  // Rows (a.w, b.x, b.y), (b.z, b.w, c.x), (c.y, c.z, c.w); mat3() takes columns.
  H = mat3(a.w, b.z, c.y, b.x, b.w, c.z, b.y, c.x, c.w);
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
    vec3 offset;
    mat3 Ha;
    nodeFrame(nodes[a], offset, Ha);
    vec3 model = offset + Ha * X;
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
    ivec2 neighbours = texelFetch(neighbourRanges, gl_VertexID).rg;
    for (int k = 0; k < neighbours.y; ++k) {
      int node = texelFetch(attributeNodes, neighbours.x + k).r;
      vec3 restNode = texelFetch(restNodes, node).xyz;
      vec3 offset;
      mat3 H;
      nodeFrame(node, offset, H);
      position += texelFetch(attributeWeights, neighbours.x + k).r * (offset + H * restNode - restNode);
    }
  }
  deformedPosition = position;
  fieldValue = 0.0;
  if (fieldMode == 1) {
    fieldValue = texelFetch(cellField, texelFetch(vertexCells, gl_VertexID).r).r;
  } else if (fieldMode == 2) {
    fieldValue = length(position - X);
  } else if (fieldMode == 3) {
    for (int a = 0; a < count; ++a) fieldValue += beta[a] * texelFetch(nodeField, nodes[a]).r;
  }
  gl_Position = vec4(position, 1.0);  // unused: the pass runs with rasterizer discard
}
