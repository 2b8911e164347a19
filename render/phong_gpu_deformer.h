#pragma once
// Phong Deformation in the vertex shader (shaders/phong_deform.vert): the embedded surface stays
// on the GPU as static per-vertex cell index, local coordinates and rest normal; each frame
// uploads only node positions and node gradients (O(nodes)). The CPU deformer of core/embed is
// the reference: capture() reads the shader's results back through transform feedback.

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "mesh/volume_mesh.h"
#include "render/gl.h"
#include "render/shader_program.h"

namespace sculpt::render {

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

  /// Uploads node positions (#nodes by 3) and node gradients F_i; alpha = 0 linear, 1/2 Phong,
  /// 1 vertex model.
  void setFrame(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& nodes,
                const std::vector<Eigen::Matrix3d>& gradients, float alpha);
  /// Runs the vertex shader over all vertices with transform feedback: 3 position and 3 normal
  /// floats per vertex.
  void capture(std::vector<float>& positions, std::vector<float>& normals) const;
  /// Triangle indices (3 per triangle) of the embedded surface, uploaded once.
  void setTriangles(std::span<const uint32_t> indices);
  /// Draws the deformed surface (the vertex shader deforms, the fragment shader lights).
  void draw(const glm::mat4& modelView, const glm::mat4& projection, const glm::vec3& colour) const;
  uint32_t numVertices() const { return numVertices_; }

 private:
  void bindFrameTextures(const ShaderProgram& program) const;

  ShaderProgram program_;      ///< transform feedback (capture)
  ShaderProgram drawProgram_;  ///< the same vertex shader with lighting
  GLuint indexBuffer_ = 0;
  GLsizei indexCount_ = 0;
  GLuint vao_ = 0, cellBuffer_ = 0, localBuffer_ = 0, normalBuffer_ = 0;
  GLuint cellNodesBuffer_ = 0, cellNodesTexture_ = 0;
  GLuint restNodesBuffer_ = 0, restNodesTexture_ = 0;
  GLuint frameBuffer_ = 0, frameTexture_ = 0;
  GLuint feedbackBuffer_ = 0;
  uint32_t numVertices_ = 0;
  float alpha_ = 0.5f;
};

}  // namespace sculpt::render
