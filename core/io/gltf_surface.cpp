// [SECTION] index (the document's loading, accessors, traversal and writing pieces are in
// io/gltf_document.cpp)
//   5. Gathering the surface (vertex blocks, triangles from triangles, strips and fans)
//   6. Writing (deformed write-back, fresh files)

#include "io/gltf_surface.h"

#include "io/gltf_document.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "io/atomic_file.h"
#include "io/file_error.h"

namespace sculpt {
namespace {

using namespace gltf;  // the document pieces (io/gltf_document.h)

constexpr uint32_t kNoIndex = SurfaceCorner::kNoIndex;

// -------------------------------------------------------------------------------------------
// [SECTION] 5. Gathering the surface
// -------------------------------------------------------------------------------------------

/// Consecutive SurfaceMesh vertices [first, first + count) that come from one node's POSITION
/// accessor (with its NORMAL and TEXCOORD_0 accessors, -1 when absent).
struct VertexBlock {
  int node = -1;
  int positionAccessor = -1;
  int normalAccessor = -1;
  int texcoordAccessor = -1;
  uint32_t first = 0;
  uint32_t count = 0;
  Eigen::Matrix4d world;

  bool sameSource(const VertexBlock& other) const {
    return node == other.node && positionAccessor == other.positionAccessor &&
           normalAccessor == other.normalAccessor && texcoordAccessor == other.texcoordAccessor;
  }
};

int attribute(const tinygltf::Primitive& primitive, const char* name) {
  const auto it = primitive.attributes.find(name);
  return it == primitive.attributes.end() ? -1 : it->second;
}

/// Triangles of a primitive as glTF vertex indices (triangle lists, strips and fans).
std::vector<std::array<uint32_t, 3>> primitiveTriangles(const std::vector<uint32_t>& indices,
                                                        int mode) {
  std::vector<std::array<uint32_t, 3>> triangles;
  const size_t n = indices.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    for (size_t i = 0; i + 2 < n; i += 3)
      triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < n; ++i) {
      if (i % 2 == 0)
        triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
      else
        triangles.push_back({indices[i], indices[i + 2], indices[i + 1]});
    }
  } else {  // TINYGLTF_MODE_TRIANGLE_FAN
    for (size_t i = 1; i + 1 < n; ++i)
      triangles.push_back({indices[i], indices[i + 1], indices[0]});
  }
  return triangles;
}

/// Builds the surface from the scene and records the vertex blocks for writing back.
class SurfaceGatherer {
 public:
  SurfaceGatherer(const std::filesystem::path& path, const tinygltf::Model& model)
      : path_(path), model_(model) {}

  void gather(SurfaceMesh& surface, std::vector<VertexBlock>& blocks) {
    std::map<int, int> meshNode;  // mesh -> the node instancing it
    for (const MeshInstance& instance : meshInstances(path_, model_)) {
      const int mesh = model_.nodes[static_cast<size_t>(instance.node)].mesh;
      if (static_cast<size_t>(mesh) >= model_.meshes.size()) {
        fail(path_, "node " + std::to_string(instance.node),
             "mesh " + std::to_string(mesh) + " does not exist");
      }
      if (const auto [it, isNew] = meshNode.emplace(mesh, instance.node); !isNew) {
        fail(path_, "mesh " + std::to_string(mesh),
             "instanced by nodes " + std::to_string(it->second) + " and " +
                 std::to_string(instance.node) +
                 "; writing back needs one instance per mesh (duplicate the mesh)");
      }
      const double determinant = instance.world.topLeftCorner<3, 3>().determinant();
      if (!std::isfinite(determinant) || determinant == 0.0) {
        fail(path_, "node " + std::to_string(instance.node),
             "world matrix is singular (a zero scale?)");
      }
      const auto& primitives = model_.meshes[static_cast<size_t>(mesh)].primitives;
      for (size_t p = 0; p < primitives.size(); ++p) {
        addPrimitive(instance, mesh, p, determinant < 0.0);
      }
    }
    if (faces_.numRows() == 0) fail(path_, "", "no triangle primitives in the scene");
    finish(surface);
    blocks = std::move(blocks_);
  }

 private:
  void addPrimitive(const MeshInstance& instance, int mesh, size_t p, bool mirrored) {
    const tinygltf::Primitive& primitive = model_.meshes[static_cast<size_t>(mesh)].primitives[p];
    const std::string label = primitiveLabel(mesh, p);
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode > TINYGLTF_MODE_TRIANGLE_FAN) {
      fail(path_, label, "mode " + std::to_string(mode) + " is not a glTF primitive mode");
    }
    if (mode < TINYGLTF_MODE_TRIANGLES) return;  // points and lines
    VertexBlock source;
    source.node = instance.node;
    source.positionAccessor = attribute(primitive, "POSITION");
    if (source.positionAccessor < 0) return;  // no geometry of its own
    source.normalAccessor = attribute(primitive, "NORMAL");
    source.texcoordAccessor = attribute(primitive, "TEXCOORD_0");
    source.world = instance.world;
    const VertexBlock& block = blockFor(source, label);

    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
      const std::string role = "indices of " + label;
      AccessorView view = accessorView(
          path_, model_, primitive.indices, role,
          {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
           TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
          1);
      view.normalized = false;  // meaningless for indices
      const Eigen::MatrixXd values = readElements(path_, model_, view, role);
      indices.resize(view.count);
      for (size_t i = 0; i < view.count; ++i) {
        const double index = values(static_cast<Eigen::Index>(i), 0);
        if (index >= block.count) {
          fail(path_, "accessor " + std::to_string(primitive.indices) + " (" + role + ")",
               "index " + std::to_string(static_cast<uint64_t>(index)) + " at element " +
                   std::to_string(i) + " is not below the vertex count " +
                   std::to_string(block.count));
        }
        indices[i] = static_cast<uint32_t>(index);
      }
    } else {
      indices.resize(block.count);
      for (uint32_t i = 0; i < block.count; ++i) indices[i] = i;
    }
    if (mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0) {
      fail(path_, label, std::to_string(indices.size()) + " vertices, not a multiple of 3");
    }

    for (std::array<uint32_t, 3> triangle : primitiveTriangles(indices, mode)) {
      // A triangle repeating a vertex has no area or orientation (strips use them as joins).
      if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2]) {
        continue;
      }
      if (mirrored) std::swap(triangle[1], triangle[2]);  // keep faces counter-clockwise
      for (uint32_t v : triangle) {
        SurfaceCorner corner;
        corner.position = block.first + v;
        if (block.texcoordAccessor >= 0) corner.texcoord = corner.position;
        if (block.normalAccessor >= 0) corner.normal = corner.position;
        faces_.values.push_back(corner);
      }
      faces_.closeRow();
    }
  }

  /// The block holding `source`'s vertices, read now if no earlier primitive used them.
  const VertexBlock& blockFor(const VertexBlock& source, const std::string& label) {
    for (const VertexBlock& block : blocks_) {
      if (block.sameSource(source)) return block;
    }
    // POSITION and NORMAL accessors are written back, so each must belong to one block.
    for (const int accessor : {source.positionAccessor, source.normalAccessor}) {
      if (accessor < 0) continue;
      if (const auto [it, isNew] = writtenAccessorUser_.emplace(accessor, label); !isNew) {
        fail(path_, "accessor " + std::to_string(accessor),
             "shared by " + it->second + " and " + label +
                 " with different attributes or nodes; shared vertex data must come with the "
                 "same POSITION, NORMAL and TEXCOORD_0 under the same node");
      }
    }
    VertexBlock block = source;
    block.first = static_cast<uint32_t>(positions_.size() / 3);
    readVertices(block, label);
    blocks_.push_back(block);
    return blocks_.back();
  }

  void readVertices(VertexBlock& block, const std::string& label) {
    const std::string positionRole = "POSITION of " + label;
    const AccessorView positionView = accessorView(
        path_, model_, block.positionAccessor, positionRole, {TINYGLTF_COMPONENT_TYPE_FLOAT}, 3);
    if (positionView.count >= kNoIndex - block.first) {
      fail(path_, label, "more than 2^32-2 vertices in the scene");
    }
    block.count = static_cast<uint32_t>(positionView.count);
    const Eigen::MatrixXd local = readElements(
        path_, model_, positionView,
        "accessor " + std::to_string(block.positionAccessor) + " (" + positionRole + ")");
    const Eigen::Matrix3d linear = block.world.topLeftCorner<3, 3>();
    const Eigen::Vector3d translation = block.world.topRightCorner<3, 1>();
    for (Eigen::Index i = 0; i < local.rows(); ++i) {
      const Eigen::Vector3d p = linear * local.row(i).transpose() + translation;
      positions_.insert(positions_.end(), {p.x(), p.y(), p.z()});
    }

    const auto vertexEnd = static_cast<size_t>(block.first) + block.count;
    if (block.normalAccessor >= 0) {
      const Eigen::MatrixXd normals =
          readAttribute(block.normalAccessor, "NORMAL of " + label, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                        3, block.count);
      const Eigen::Matrix3d normalMatrix = linear.inverse().transpose();
      normals_.resize(3 * vertexEnd, 0.0);
      for (Eigen::Index i = 0; i < normals.rows(); ++i) {
        Eigen::Vector3d n = normalMatrix * normals.row(i).transpose();
        if (n.norm() > 0.0) n.normalize();
        std::copy(n.data(), n.data() + 3, normals_.begin() + 3 * (block.first + i));
      }
    }
    if (block.texcoordAccessor >= 0) {
      const Eigen::MatrixXd uv =
          readAttribute(block.texcoordAccessor, "TEXCOORD_0 of " + label,
                        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                        2, block.count);
      texcoords_.resize(2 * vertexEnd, 0.0);
      for (Eigen::Index i = 0; i < uv.rows(); ++i) {
        texcoords_[2 * (block.first + i)] = uv(i, 0);
        texcoords_[2 * (block.first + i) + 1] = 1.0 - uv(i, 1);  // glTF v grows downwards
      }
    }
  }

  Eigen::MatrixXd readAttribute(int accessor, const std::string& role,
                                std::initializer_list<int> componentTypes, int components,
                                uint32_t vertexCount) {
    const AccessorView view =
        accessorView(path_, model_, accessor, role, componentTypes, components);
    const std::string label = "accessor " + std::to_string(accessor) + " (" + role + ")";
    if (view.count != vertexCount) {
      fail(path_, label,
           "count " + std::to_string(view.count) + " differs from the POSITION count " +
               std::to_string(vertexCount));
    }
    return readElements(path_, model_, view, label);
  }

  void finish(SurfaceMesh& surface) {
    const auto numVertices = static_cast<Eigen::Index>(positions_.size() / 3);
    surface.positions = Eigen::Map<const Points>(positions_.data(), numVertices, 3);
    // Blocks without normals (or texcoords) keep zero rows that no corner uses.
    if (!normals_.empty()) {
      normals_.resize(positions_.size(), 0.0);
      surface.normals = Eigen::Map<const Points>(normals_.data(), numVertices, 3);
    }
    if (!texcoords_.empty()) {
      texcoords_.resize(2 * positions_.size() / 3, 0.0);
      surface.texcoords = Eigen::Map<const TexCoords>(texcoords_.data(), numVertices, 2);
    }
    surface.faces = std::move(faces_);
  }

  const std::filesystem::path& path_;
  const tinygltf::Model& model_;
  std::vector<VertexBlock> blocks_;
  std::map<int, std::string> writtenAccessorUser_;  // POSITION/NORMAL accessor -> its primitive
  std::vector<double> positions_, normals_, texcoords_;
  CompressedRows<SurfaceCorner> faces_;
};

/// The corner tuple a fresh file's vertex stands for (absent attributes as kNoIndex).
struct CornerKey {
  uint32_t position, texcoord, normal;
  bool operator==(const CornerKey&) const = default;
};
struct CornerKeyHash {
  size_t operator()(const CornerKey& key) const {
    uint64_t h = key.position;
    h = h * 0x9E3779B97F4A7C15ull ^ key.texcoord;
    h = h * 0x9E3779B97F4A7C15ull ^ key.normal;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

}  // namespace

struct GltfSurfaceFile::Document {
  tinygltf::Model model;
  SurfaceMesh surface;
  std::vector<VertexBlock> blocks;
};

GltfSurfaceFile::GltfSurfaceFile(std::unique_ptr<Document> document)
    : document_(std::move(document)) {}
GltfSurfaceFile::GltfSurfaceFile(GltfSurfaceFile&&) noexcept = default;
GltfSurfaceFile& GltfSurfaceFile::operator=(GltfSurfaceFile&&) noexcept = default;
GltfSurfaceFile::~GltfSurfaceFile() = default;

GltfSurfaceFile GltfSurfaceFile::read(const std::filesystem::path& path) {
  auto document = std::make_unique<Document>();
  document->model = loadModel(path);
  SurfaceGatherer(path, document->model).gather(document->surface, document->blocks);
  return GltfSurfaceFile(std::move(document));
}

const SurfaceMesh& GltfSurfaceFile::surface() const { return document_->surface; }

void GltfSurfaceFile::writeDeformed(const std::filesystem::path& path,
                                    const SurfaceMesh& deformed) const {
  const SurfaceMesh& original = document_->surface;
  if (deformed.positions.rows() != original.positions.rows()) {
    fail(path, "",
         "the deformed surface has " + std::to_string(deformed.positions.rows()) +
             " vertices, the glTF input has " + std::to_string(original.positions.rows()));
  }
  // Normals are optional in the deformed surface: without them the file keeps its own (and a
  // file without normals gets none).
  const bool writeNormals = deformed.normals.rows() != 0 && original.normals.rows() != 0;
  if (writeNormals && deformed.normals.rows() != original.normals.rows()) {
    fail(path, "",
         "the deformed surface has " + std::to_string(deformed.normals.rows()) +
             " normals, the glTF input has " + std::to_string(original.normals.rows()));
  }
  if (!deformed.positions.allFinite() || !deformed.normals.allFinite()) {
    fail(path, "", "cannot write a surface with non-finite coordinates");
  }

  tinygltf::Model model = document_->model;
  for (const VertexBlock& block : document_->blocks) {
    // Scene space back to the node's local space: positions by the inverse world matrix,
    // normals by the transpose of its linear part (the inverse of the inverse transpose).
    const Eigen::Matrix4d toLocal = block.world.inverse();
    const Eigen::Matrix3d normalToLocal = block.world.topLeftCorner<3, 3>().transpose();
    const auto first = static_cast<Eigen::Index>(block.first);

    tinygltf::Accessor& positions = model.accessors[static_cast<size_t>(block.positionAccessor)];
    const AccessorView positionView = accessorView(path, model, block.positionAccessor, "POSITION",
                                                   {TINYGLTF_COMPONENT_TYPE_FLOAT}, 3);
    writeFloatElements(
        model, positionView,
        [&](Eigen::Index i) -> Eigen::Vector3d {
          return (toLocal * deformed.positions.row(first + i).transpose().homogeneous()).head<3>();
        },
        positions.minValues, positions.maxValues);

    if (!writeNormals || block.normalAccessor < 0) continue;
    tinygltf::Accessor& normals = model.accessors[static_cast<size_t>(block.normalAccessor)];
    const bool hadBounds = !normals.minValues.empty();
    const AccessorView normalView = accessorView(path, model, block.normalAccessor, "NORMAL",
                                                 {TINYGLTF_COMPONENT_TYPE_FLOAT}, 3);
    writeFloatElements(
        model, normalView,
        [&](Eigen::Index i) -> Eigen::Vector3d {
          Eigen::Vector3d n = normalToLocal * deformed.normals.row(first + i).transpose();
          return n.norm() > 0.0 ? n.normalized() : n;
        },
        normals.minValues, normals.maxValues);
    if (!hadBounds) {
      normals.minValues.clear();
      normals.maxValues.clear();
    }
  }
  writeModel(path, model);
}

void writeSurfaceGltf(const std::filesystem::path& path, const SurfaceMesh& surface) {
  if (surface.numFaces() == 0) fail(path, "", "nothing to write: the surface has no faces");
  if (!surface.positions.allFinite() || !surface.normals.allFinite() ||
      !surface.texcoords.allFinite()) {
    fail(path, "", "cannot write a surface with non-finite coordinates");
  }
  // An attribute is written only when every corner has one (glTF attributes cover all vertices).
  bool withNormals = surface.normals.rows() > 0, withTexcoords = surface.texcoords.rows() > 0;
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    if (surface.faces.rowSize(f) < 3) {
      fail(path, "face " + std::to_string(f), "has fewer than 3 corners");
    }
    for (const SurfaceCorner& c : surface.faces.row(f)) {
      if (c.position >= surface.positions.rows() ||
          (c.normal != kNoIndex && c.normal >= surface.normals.rows()) ||
          (c.texcoord != kNoIndex && c.texcoord >= surface.texcoords.rows())) {
        fail(path, "face " + std::to_string(f), "corner index out of range");
      }
      withNormals = withNormals && c.normal != kNoIndex;
      withTexcoords = withTexcoords && c.texcoord != kNoIndex;
    }
  }
  // Vertex i can be position i when every written attribute list lines up with the positions.
  bool sameIndices = (!withNormals || surface.normals.rows() == surface.positions.rows()) &&
                     (!withTexcoords || surface.texcoords.rows() == surface.positions.rows());
  for (const SurfaceCorner& c : surface.faces.values) {
    sameIndices = sameIndices && (!withNormals || c.normal == c.position) &&
                  (!withTexcoords || c.texcoord == c.position);
  }

  // Vertices: the positions themselves, or one per distinct corner tuple in order of first use.
  std::vector<CornerKey> vertices;
  std::vector<uint32_t> cornerVertex(surface.faces.values.size());
  if (sameIndices) {
    for (uint32_t v = 0; v < surface.numVertices(); ++v) vertices.push_back({v, v, v});
    for (size_t i = 0; i < cornerVertex.size(); ++i)
      cornerVertex[i] = surface.faces.values[i].position;
  } else {
    std::unordered_map<CornerKey, uint32_t, CornerKeyHash> vertexOf;
    for (size_t i = 0; i < cornerVertex.size(); ++i) {
      const SurfaceCorner& c = surface.faces.values[i];
      const CornerKey key{c.position, withTexcoords ? c.texcoord : kNoIndex,
                          withNormals ? c.normal : kNoIndex};
      const auto [it, isNew] = vertexOf.emplace(key, static_cast<uint32_t>(vertices.size()));
      if (isNew) vertices.push_back(key);
      cornerVertex[i] = it->second;
    }
  }

  // Triangles: each polygon fanned from its first corner.
  std::vector<uint32_t> indices;
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    const uint32_t begin = surface.faces.offsets[f];
    for (uint32_t k = 1; k + 1 < surface.faces.rowSize(f); ++k) {
      indices.insert(indices.end(),
                     {cornerVertex[begin], cornerVertex[begin + k], cornerVertex[begin + k + 1]});
    }
  }

  std::vector<float> positions, normals, texcoords;
  for (const CornerKey& vertex : vertices) {
    const auto p = static_cast<Eigen::Index>(vertex.position);
    for (Eigen::Index k = 0; k < 3; ++k)
      positions.push_back(static_cast<float>(surface.positions(p, k)));
    if (withNormals) {
      Eigen::Vector3d n = surface.normals.row(static_cast<Eigen::Index>(vertex.normal)).transpose();
      if (n.norm() > 0.0) n.normalize();  // glTF normals are unit vectors
      for (Eigen::Index k = 0; k < 3; ++k) normals.push_back(static_cast<float>(n[k]));
    }
    if (withTexcoords) {
      const auto t = static_cast<Eigen::Index>(vertex.texcoord);
      texcoords.push_back(static_cast<float>(surface.texcoords(t, 0)));
      texcoords.push_back(static_cast<float>(1.0 - surface.texcoords(t, 1)));  // v downwards
    }
  }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Subdivision Sculpt";
  model.buffers.emplace_back();
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  const int position =
      appendAccessor(model, appendBufferView(model, positions, TINYGLTF_TARGET_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices.size());
  primitive.attributes["POSITION"] = position;
  {
    const auto rows = Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor>>(
        positions.data(), static_cast<Eigen::Index>(vertices.size()), 3);
    const Eigen::Vector3f low = rows.colwise().minCoeff(), high = rows.colwise().maxCoeff();
    model.accessors[static_cast<size_t>(position)].minValues = {low[0], low[1], low[2]};
    model.accessors[static_cast<size_t>(position)].maxValues = {high[0], high[1], high[2]};
  }
  if (withNormals) {
    primitive.attributes["NORMAL"] =
        appendAccessor(model, appendBufferView(model, normals, TINYGLTF_TARGET_ARRAY_BUFFER),
                       TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices.size());
  }
  if (withTexcoords) {
    primitive.attributes["TEXCOORD_0"] =
        appendAccessor(model, appendBufferView(model, texcoords, TINYGLTF_TARGET_ARRAY_BUFFER),
                       TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, vertices.size());
  }
  primitive.indices =
      appendAccessor(model, appendBufferView(model, indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());

  model.meshes.emplace_back().primitives.push_back(primitive);
  model.nodes.emplace_back().mesh = 0;
  model.scenes.emplace_back().nodes.push_back(0);
  model.defaultScene = 0;
  writeModel(path, model);
}

}  // namespace sculpt
