#pragma once
// Phong Deformation in a vertex shader (shaders/phong_deform.vert): the embedded surface stays on
// the GPU as static per-vertex data (local coordinates, rest point, rest normal, inverse rest
// Jacobian, cell nodes); each frame uploads only node positions and node gradients (O(nodes)).
// The shader runs once per vertex per new frame with transform feedback into a vertex buffer,
// which draw() then renders (shaders/deformed_surface.vert): every draw of the same frame (the
// wireframe pass, screenshots) reuses it, and each vertex is deformed once however many
// triangles share it. The CPU deformer of core/embed is the reference: capture() reads that
// buffer back.
// Methods: linear, vertex and phong from the node gradients; attribute (for comparison) from
// per-vertex metaball neighbours uploaded once when first needed.

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "embed/attribute_transfer.h"
#include "embed/interpolation_method.h"
#include "mesh/volume_mesh.h"
#include "render/gl.h"
#include "render/shader_program.h"

namespace sculpt::render {

/// A scalar shown on the surface through the colour map: flat per cell, the displacement length,
/// or node values interpolated over each cell like the position (smooth across cells).
enum class SurfaceField { None = 0, PerCell = 1, Displacement = 2, PerNode = 3 };

/// How draw() shades the deformed surface.
struct SurfaceStyle {
  glm::vec3 colour{0.80f, 0.62f, 0.45f};
  bool flatShading = false;  ///< facet normals instead of the analytic ones
  bool wireframe = false;    ///< overlay the triangle edges
  glm::vec3 wireColour{0.08f, 0.08f, 0.10f};
  SurfaceField field = SurfaceField::None;
  float fieldLow = 0.0f, fieldHigh = 1.0f;  ///< values at the ends of the colour map
  bool clip = false;                        ///< keep only dot(clipPlane.xyz, x) <= clipPlane.w
  glm::vec4 clipPlane{0.0f, 0.0f, 1.0f, 0.0f};
  /// Skip the filled triangles that face away from the eye: the same picture for a closed surface
  /// whose triangles face out, seen from outside and not clipped, in about half the rasterising.
  bool cullBackFaces = false;
};

class PhongGpuDeformer {
 public:
  /// @param cells        per vertex: its cell
  /// @param local        per vertex: 3 local coordinates (tet barycentric 1..3, hex s,t,u)
  /// @param restNormals  per vertex: 3 components
  PhongGpuDeformer(const VolumeMesh& rest, std::span<const uint32_t> cells,
                   std::span<const float> local, std::span<const float> restNormals);
  ~PhongGpuDeformer();
  PhongGpuDeformer(const PhongGpuDeformer&) = delete;
  PhongGpuDeformer& operator=(const PhongGpuDeformer&) = delete;

  /// Uploads node positions (#nodes by 3) and node gradients F_i (O(nodes)); `method` picks the
  /// interpolation (a change of method needs a new setFrame). Attribute needs
  /// setAttributeNeighbours() first (std::logic_error otherwise).
  void setFrame(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& nodes,
                const std::vector<Eigen::Matrix3d>& gradients, InterpolationMethod method);
  /// Per vertex, its attribute-method neighbour nodes and weights (attributeTransferWeights).
  void setAttributeNeighbours(const CompressedRows<NodeWeight>& neighbours);
  bool hasAttributeNeighbours() const { return hasAttribute_; }
  /// One value per cell for SurfaceField::PerCell (O(cells)).
  void setCellField(std::span<const float> values);
  /// One value per node for SurfaceField::PerNode (O(nodes)), e.g. from nodeFieldFromCells.
  void setNodeField(std::span<const float> values);
  /// Bytes sent by the last setFrame (the per-frame upload).
  size_t frameUploadBytes() const { return frameUploadBytes_; }
  /// Runs the vertex shader over all vertices with transform feedback: 3 position and 3 normal
  /// floats per vertex.
  void capture(std::vector<float>& positions, std::vector<float>& normals) const;
  /// The same pass with `field`: the field value per vertex that draw() colours.
  void captureField(SurfaceField field, std::vector<float>& values) const;
  /// Triangle indices (3 per triangle) of the embedded surface, uploaded once.
  void setTriangles(std::span<const uint32_t> indices);
  /// Draws the deformed surface (the vertex shader deforms, the fragment shader lights).
  void draw(const glm::mat4& modelView, const glm::mat4& projection,
            const SurfaceStyle& style) const;
  uint32_t numVertices() const { return numVertices_; }

 private:
  void bindFrameTextures(const ShaderProgram& program) const;
  /// Runs the deformation pass into feedbackBuffer_ unless it holds this frame with this field.
  void deform(SurfaceField field) const;
  /// The feedback buffer: per vertex its position, normal and field value (7 floats).
  std::vector<float> readFeedback() const;
  void drawTriangles(const glm::mat4& modelView, const glm::mat4& projection) const;

  ShaderProgram program_;      ///< the deformation pass (transform feedback)
  ShaderProgram drawProgram_;  ///< draws the deformed buffer with lighting
  GLuint indexBuffer_ = 0;
  GLsizei indexCount_ = 0;
  GLuint vao_ = 0, localBuffer_ = 0, normalBuffer_ = 0;
  GLuint drawVao_ = 0;  ///< the deformed vertices and the triangles
  GLuint cellBuffer_ = 0, cellTexture_ = 0;  ///< per vertex, read by vertex id
  GLuint restNodesBuffer_ = 0, restNodesTexture_ = 0;
  GLuint frameBuffer_ = 0, frameTexture_ = 0;
  GLuint feedbackBuffer_ = 0;
  GLuint restPointBuffer_ = 0, inverseJacobianBuffer_ = 0, vertexNodesBuffer_ = 0;
  GLuint neighbourRangeBuffer_ = 0,
         neighbourRangeTexture_ = 0;  ///< per vertex (first, count) of the attribute method
  GLuint attributeNodesBuffer_ = 0, attributeNodesTexture_ = 0;
  GLuint attributeWeightsBuffer_ = 0, attributeWeightsTexture_ = 0;
  GLuint cellFieldBuffer_ = 0, cellFieldTexture_ = 0;
  GLuint nodeFieldBuffer_ = 0, nodeFieldTexture_ = 0;
  uint32_t numVertices_ = 0, numCells_ = 0;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> restNodes_;
  float alpha_ = 0.5f;
  bool attribute_ = false, hasAttribute_ = false;
  size_t frameUploadBytes_ = 0;
  mutable bool feedbackCurrent_ = false;  ///< feedbackBuffer_ holds the current frame
  mutable SurfaceField feedbackField_ = SurfaceField::None;
};

}  // namespace sculpt::render
