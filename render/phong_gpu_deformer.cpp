#include "render/phong_gpu_deformer.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

#include "embed/cell_coordinates.h"
#include "render/gl_buffers.h"
#include "shader_sources.h"

namespace sculpt::render {
namespace {

constexpr size_t kFloatsPerNode = 12;  ///< offset x_i - H_i X_i and H_i, in 3 RGBA texels

constexpr std::array<const char*, 3> kFeedback = {"deformedPosition", "deformedNormal",
                                                  "fieldValue"};
constexpr size_t kFeedbackFloats = 7;  ///< per vertex: position, normal, field value

/// The surface fragment shader: lighting and the colour map prepended.
std::string surfaceFragmentSource() {
  return shaderSource({shaders::kLightingGlsl, shaders::kColourMapGlsl},
                      shaders::kPhongSurfaceFrag);
}

/// Replaces the contents of a texture buffer.
void uploadBuffer(GLuint buffer, const void* data, size_t bytes, GLenum usage) {
  glBindBuffer(GL_TEXTURE_BUFFER, buffer);
  glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(bytes), data, usage);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

/// A buffer texture over a new buffer with `bytes` of `data`.
void makeBufferTexture(GLuint& buffer, GLuint& texture, GLenum format, const void* data,
                       size_t bytes, GLenum usage) {
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_TEXTURE_BUFFER, buffer);
  glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(bytes), data, usage);
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_BUFFER, texture);
  glTexBuffer(GL_TEXTURE_BUFFER, format, buffer);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

GLuint makeVertexBuffer(const void* data, size_t bytes) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
  return buffer;
}

}  // namespace

PhongGpuDeformer::PhongGpuDeformer(const VolumeMesh& rest, std::span<const uint32_t> cells,
                                   std::span<const float> local,
                                   std::span<const float> restNormals)
    : program_("phong_deform", shaders::kPhongDeformVert, nullptr, kFeedback),
      drawProgram_("phong_surface", shaders::kDeformedSurfaceVert, surfaceFragmentSource().c_str()),
      numVertices_(static_cast<uint32_t>(cells.size())),
      numCells_(rest.numCells()),
      restNodes_(rest.positions) {
  if (local.size() != 3 * cells.size() || restNormals.size() != 3 * cells.size())
    throw std::invalid_argument("PhongGpuDeformer: per-vertex arrays differ in length");
  for (const uint32_t c : cells)
    if (c >= rest.numCells())
      throw std::invalid_argument("PhongGpuDeformer: a vertex lies in cell " + std::to_string(c) +
                                  " of " + std::to_string(rest.numCells()));
  // 8 node ids per cell, -1 padding for tetrahedra.
  std::vector<int32_t> cellNodes(8 * static_cast<size_t>(rest.numCells()), -1);
  for (uint32_t c = 0; c < rest.numCells(); ++c) {
    const auto nodes = rest.cells.row(c);
    for (size_t k = 0; k < nodes.size(); ++k) cellNodes[8 * c + k] = static_cast<int32_t>(nodes[k]);
  }
  std::vector<float> restNodes(4 * static_cast<size_t>(rest.numNodes()), 0.0f);
  for (uint32_t i = 0; i < rest.numNodes(); ++i)
    for (int d = 0; d < 3; ++d) restNodes[4 * i + d] = static_cast<float>(rest.positions(i, d));
  makeBufferTexture(restNodesBuffer_, restNodesTexture_, GL_RGBA32F, restNodes.data(),
                    restNodes.size() * sizeof(float), GL_STATIC_DRAW);
  makeBufferTexture(frameBuffer_, frameTexture_, GL_RGBA32F, nullptr,
                    kFloatsPerNode * sizeof(float) * rest.numNodes(), GL_STREAM_DRAW);
  // Per vertex by gl_VertexID: the cell (cell fields) and the attribute neighbours (none yet).
  makeBufferTexture(cellBuffer_, cellTexture_, GL_R32I, cells.data(), cells.size_bytes(),
                    GL_STATIC_DRAW);
  const std::vector<int32_t> noNeighbours(2 * static_cast<size_t>(numVertices_), 0);
  makeBufferTexture(neighbourRangeBuffer_, neighbourRangeTexture_, GL_RG32I, noNeighbours.data(),
                    noNeighbours.size() * sizeof(int32_t), GL_STATIC_DRAW);
  // Until a field or the attribute neighbours arrive: zero cell values, one dummy neighbour.
  const std::vector<float> zeros(std::max<size_t>(numCells_, 1), 0.0f);
  makeBufferTexture(cellFieldBuffer_, cellFieldTexture_, GL_R32F, zeros.data(),
                    zeros.size() * sizeof(float), GL_DYNAMIC_DRAW);
  const std::vector<float> nodeZeros(std::max<uint32_t>(rest.numNodes(), 1), 0.0f);
  makeBufferTexture(nodeFieldBuffer_, nodeFieldTexture_, GL_R32F, nodeZeros.data(),
                    nodeZeros.size() * sizeof(float), GL_DYNAMIC_DRAW);
  const int32_t noNode = 0;
  makeBufferTexture(attributeNodesBuffer_, attributeNodesTexture_, GL_R32I, &noNode,
                    sizeof noNode, GL_STATIC_DRAW);
  makeBufferTexture(attributeWeightsBuffer_, attributeWeightsTexture_, GL_R32F, zeros.data(),
                    sizeof(float), GL_STATIC_DRAW);

  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  localBuffer_ = floatAttribute(1, 3, makeVertexBuffer(local.data(), local.size_bytes()));
  normalBuffer_ =
      floatAttribute(2, 3, makeVertexBuffer(restNormals.data(), restNormals.size_bytes()));
  // Static per-vertex rest point X and inverse rest Jacobian d xi / d X (columns), so that the
  // shader needs no rest node positions and no matrix inverse.
  std::vector<float> restPoint(3 * static_cast<size_t>(numVertices_));
  std::vector<float> inverseJacobian(9 * static_cast<size_t>(numVertices_));
  for (uint32_t v = 0; v < numVertices_; ++v) {
    const Eigen::Vector3d xi(local[3 * v], local[3 * v + 1], local[3 * v + 2]);
    const Eigen::Vector3d X = cellPoint(rest, cells[v], xi);
    const Eigen::Matrix3d inverse = cellJacobian(rest, cells[v], xi).inverse();
    for (int d = 0; d < 3; ++d) restPoint[3 * v + d] = static_cast<float>(X(d));
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r)
        inverseJacobian[9 * v + 3 * c + r] = static_cast<float>(inverse(r, c));
  }
  restPointBuffer_ =
      floatAttribute(4, 3, makeVertexBuffer(restPoint.data(), restPoint.size() * sizeof(float)));
  inverseJacobianBuffer_ =
      makeVertexBuffer(inverseJacobian.data(), inverseJacobian.size() * sizeof(float));
  for (int c = 0; c < 3; ++c) {
    glEnableVertexAttribArray(static_cast<GLuint>(5 + c));
    glVertexAttribPointer(
        static_cast<GLuint>(5 + c), 3, GL_FLOAT, GL_FALSE, 9 * sizeof(float),
        reinterpret_cast<const void*>(3 * sizeof(float) * static_cast<size_t>(c)));
  }
  // The cell's 8 node ids per vertex (two ivec4; -1 padding for tetrahedra): attributes are
  // cheaper for the vertex shader than fetches from the cell table.
  std::vector<int32_t> vertexNodes(8 * static_cast<size_t>(numVertices_));
  for (uint32_t v = 0; v < numVertices_; ++v)
    std::copy_n(cellNodes.begin() + 8 * static_cast<std::ptrdiff_t>(cells[v]), 8,
                vertexNodes.begin() + 8 * static_cast<std::ptrdiff_t>(v));
  vertexNodesBuffer_ = makeVertexBuffer(vertexNodes.data(), vertexNodes.size() * sizeof(int32_t));
  for (int half = 0; half < 2; ++half) {
    glEnableVertexAttribArray(static_cast<GLuint>(8 + half));
    glVertexAttribIPointer(
        static_cast<GLuint>(8 + half), 4, GL_INT, 8 * sizeof(int32_t),
        reinterpret_cast<const void*>(4 * sizeof(int32_t) * static_cast<size_t>(half)));
  }
  glBindVertexArray(0);

  // The deformed vertices (transform feedback output) are the draw pass's vertex buffer.
  glGenBuffers(1, &feedbackBuffer_);
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, feedbackBuffer_);
  glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER,
               static_cast<GLsizeiptr>(kFeedbackFloats * sizeof(float) * numVertices_), nullptr,
               GL_DYNAMIC_COPY);
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
  glGenVertexArrays(1, &drawVao_);
  glBindVertexArray(drawVao_);
  glBindBuffer(GL_ARRAY_BUFFER, feedbackBuffer_);
  constexpr GLsizei stride = kFeedbackFloats * sizeof(float);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(6 * sizeof(float)));
  glGenBuffers(1, &indexBuffer_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

PhongGpuDeformer::~PhongGpuDeformer() {
  const GLuint buffers[] = {cellBuffer_,
                            localBuffer_,
                            normalBuffer_,
                            restNodesBuffer_,
                            frameBuffer_,
                            feedbackBuffer_,
                            indexBuffer_,
                            neighbourRangeBuffer_,
                            attributeNodesBuffer_,
                            attributeWeightsBuffer_,
                            cellFieldBuffer_,
                            restPointBuffer_,
                            inverseJacobianBuffer_,
                            vertexNodesBuffer_,
                            nodeFieldBuffer_};
  glDeleteBuffers(static_cast<GLsizei>(std::size(buffers)), buffers);
  const GLuint textures[] = {restNodesTexture_,        frameTexture_,     attributeNodesTexture_,
                             attributeWeightsTexture_, cellFieldTexture_, cellTexture_,
                             neighbourRangeTexture_,   nodeFieldTexture_};
  glDeleteTextures(static_cast<GLsizei>(std::size(textures)), textures);
  glDeleteVertexArrays(1, &vao_);
  glDeleteVertexArrays(1, &drawVao_);
}

void PhongGpuDeformer::setFrame(
    const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& nodes,
    const std::vector<Eigen::Matrix3d>& gradients, InterpolationMethod method) {
  if (method == InterpolationMethod::Attribute && !hasAttribute_)
    throw std::logic_error("PhongGpuDeformer: the attribute method needs its neighbours first");
  attribute_ = method == InterpolationMethod::Attribute;
  // The attribute method keeps the Phong normal (it has no useful gradient of its own).
  alpha_ = attribute_ ? 0.5f : static_cast<float>(gradientBlend(method));
  if (nodes.rows() != restNodes_.rows())
    throw std::invalid_argument("PhongGpuDeformer: " + std::to_string(nodes.rows()) +
                                " node positions for " + std::to_string(restNodes_.rows()) +
                                " nodes");
  // 3 texels per node: x_i - H_i X_i, then H_i = alpha F_i row by row (H_i = 0 when gradients
  // are not given).
  std::vector<float> data(kFloatsPerNode * static_cast<size_t>(nodes.rows()), 0.0f);
  for (Eigen::Index i = 0; i < nodes.rows(); ++i) {
    float* node = data.data() + kFloatsPerNode * static_cast<size_t>(i);
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    if (static_cast<size_t>(i) < gradients.size()) H = alpha_ * gradients[static_cast<size_t>(i)];
    const Eigen::Vector3d offset = nodes.row(i).transpose() - H * restNodes_.row(i).transpose();
    for (int d = 0; d < 3; ++d) node[d] = static_cast<float>(offset(d));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) node[3 + 3 * r + c] = static_cast<float>(H(r, c));
  }
  frameUploadBytes_ = data.size() * sizeof(float);
  feedbackCurrent_ = false;
  uploadBuffer(frameBuffer_, data.data(), frameUploadBytes_, GL_STREAM_DRAW);
}

void PhongGpuDeformer::setAttributeNeighbours(const CompressedRows<NodeWeight>& neighbours) {
  if (neighbours.numRows() != numVertices_)
    throw std::invalid_argument("PhongGpuDeformer: attribute neighbours for " +
                                std::to_string(neighbours.numRows()) + " vertices, expected " +
                                std::to_string(numVertices_));
  std::vector<int32_t> ranges(2 * static_cast<size_t>(numVertices_));
  for (uint32_t v = 0; v < numVertices_; ++v) {
    ranges[2 * v] = static_cast<int32_t>(neighbours.offsets[v]);
    ranges[2 * v + 1] = static_cast<int32_t>(neighbours.rowSize(v));
  }
  std::vector<int32_t> nodes;
  std::vector<float> weights;
  nodes.reserve(neighbours.values.size());
  weights.reserve(neighbours.values.size());
  for (const NodeWeight& w : neighbours.values) {
    nodes.push_back(static_cast<int32_t>(w.node));
    weights.push_back(static_cast<float>(w.weight));
  }
  if (nodes.empty()) nodes.push_back(0), weights.push_back(0.0f);  // keep the buffers non-empty
  uploadBuffer(neighbourRangeBuffer_, ranges.data(), ranges.size() * sizeof(int32_t),
               GL_STATIC_DRAW);
  uploadBuffer(attributeNodesBuffer_, nodes.data(), nodes.size() * sizeof(int32_t), GL_STATIC_DRAW);
  uploadBuffer(attributeWeightsBuffer_, weights.data(), weights.size() * sizeof(float),
               GL_STATIC_DRAW);
  hasAttribute_ = true;
  feedbackCurrent_ = false;
}

void PhongGpuDeformer::setCellField(std::span<const float> values) {
  if (values.size() != numCells_)
    throw std::invalid_argument("PhongGpuDeformer: " + std::to_string(values.size()) +
                                " cell field values for " + std::to_string(numCells_) + " cells");
  if (values.empty()) return;
  uploadBuffer(cellFieldBuffer_, values.data(), values.size_bytes(), GL_DYNAMIC_DRAW);
  feedbackCurrent_ = false;
}

void PhongGpuDeformer::setNodeField(std::span<const float> values) {
  if (values.size() != static_cast<size_t>(restNodes_.rows()))
    throw std::invalid_argument("PhongGpuDeformer: " + std::to_string(values.size()) +
                                " node field values for " + std::to_string(restNodes_.rows()) +
                                " nodes");
  if (values.empty()) return;
  uploadBuffer(nodeFieldBuffer_, values.data(), values.size_bytes(), GL_DYNAMIC_DRAW);
  feedbackCurrent_ = false;
}

void PhongGpuDeformer::bindFrameTextures(const ShaderProgram& program) const {
  program.use();
  const GLuint textures[] = {restNodesTexture_,      frameTexture_,
                             cellTexture_,           neighbourRangeTexture_,
                             attributeNodesTexture_, attributeWeightsTexture_,
                             cellFieldTexture_,      nodeFieldTexture_};
  const char* samplers[] = {"restNodes",      "frameNodes",       "vertexCells", "neighbourRanges",
                            "attributeNodes", "attributeWeights", "cellField",   "nodeField"};
  static_assert(std::size(textures) == std::size(samplers));
  for (int unit = 0; unit < static_cast<int>(std::size(textures)); ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_BUFFER, textures[unit]);
    glUniform1i(program.uniform(samplers[unit]), unit);
  }
  glActiveTexture(GL_TEXTURE0);
  glUniform1i(program.uniform("attributeMethod"), attribute_ ? 1 : 0);
}

void PhongGpuDeformer::deform(SurfaceField field) const {
  if (feedbackCurrent_ && feedbackField_ == field) return;
  bindFrameTextures(program_);
  glUniform1i(program_.uniform("fieldMode"), static_cast<int>(field));
  glBindVertexArray(vao_);
  glEnable(GL_RASTERIZER_DISCARD);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedbackBuffer_);
  glBeginTransformFeedback(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(numVertices_));
  glEndTransformFeedback();
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  glDisable(GL_RASTERIZER_DISCARD);
  glBindVertexArray(0);
  feedbackCurrent_ = true;
  feedbackField_ = field;
}

void PhongGpuDeformer::drawTriangles(const glm::mat4& modelView,
                                     const glm::mat4& projection) const {
  glUniformMatrix4fv(drawProgram_.uniform("modelView"), 1, GL_FALSE, &modelView[0][0]);
  glUniformMatrix4fv(drawProgram_.uniform("projection"), 1, GL_FALSE, &projection[0][0]);
  glBindVertexArray(drawVao_);
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

void PhongGpuDeformer::setTriangles(std::span<const uint32_t> indices) {
  indexCount_ = uploadTriangleIndices(drawVao_, indexBuffer_, indices);
}

void PhongGpuDeformer::draw(const glm::mat4& modelView, const glm::mat4& projection,
                            const SurfaceStyle& style) const {
  deform(style.field);
  const ShaderProgram& program = drawProgram_;
  program.use();
  glUniform3f(program.uniform("baseColour"), style.colour.x, style.colour.y, style.colour.z);
  glUniform1i(program.uniform("fieldMode"), static_cast<int>(style.field));
  glUniform2f(program.uniform("fieldRange"), style.fieldLow, style.fieldHigh);
  glUniform1i(program.uniform("flatShading"), style.flatShading ? 1 : 0);
  glUniform4f(program.uniform("solidColour"), 0.0f, 0.0f, 0.0f, 0.0f);
  // Without clipping the plane keeps everything (llvmpipe clips on written distances anyway).
  const glm::vec4 plane = style.clip ? style.clipPlane : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  glUniform4f(program.uniform("clipPlane"), plane.x, plane.y, plane.z, plane.w);
  if (style.clip) glEnable(GL_CLIP_DISTANCE0);
  if (style.wireframe) {  // push the fill back so the edges drawn next win the depth test
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
  }
  if (style.cullBackFaces) glEnable(GL_CULL_FACE);  // counter-clockwise triangles face the eye
  drawTriangles(modelView, projection);
  if (style.cullBackFaces) glDisable(GL_CULL_FACE);
  if (style.wireframe) {
    glDisable(GL_POLYGON_OFFSET_FILL);
    glUniform4f(program.uniform("solidColour"), style.wireColour.x, style.wireColour.y,
                style.wireColour.z, 1.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    drawTriangles(modelView, projection);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
  if (style.clip) glDisable(GL_CLIP_DISTANCE0);
}

std::vector<float> PhongGpuDeformer::readFeedback() const {
  std::vector<float> interleaved(kFeedbackFloats * static_cast<size_t>(numVertices_));
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, feedbackBuffer_);
  glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0,
                     static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                     interleaved.data());
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
  return interleaved;
}

void PhongGpuDeformer::captureField(SurfaceField field, std::vector<float>& values) const {
  deform(field);
  const std::vector<float> interleaved = readFeedback();
  values.resize(numVertices_);
  for (uint32_t v = 0; v < numVertices_; ++v) values[v] = interleaved[kFeedbackFloats * v + 6];
}

void PhongGpuDeformer::capture(std::vector<float>& positions, std::vector<float>& normals) const {
  deform(feedbackCurrent_ ? feedbackField_ : SurfaceField::None);
  const std::vector<float> interleaved = readFeedback();
  positions.resize(3 * static_cast<size_t>(numVertices_));
  normals.resize(3 * static_cast<size_t>(numVertices_));
  for (uint32_t v = 0; v < numVertices_; ++v)
    for (int d = 0; d < 3; ++d) {
      positions[3 * v + d] = interleaved[kFeedbackFloats * v + d];
      normals[3 * v + d] = interleaved[kFeedbackFloats * v + 3 + d];
    }
}

}  // namespace sculpt::render
