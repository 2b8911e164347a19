// A glTF document as the surface reader and writer use it: loading it safely (the GLB layout is
// checked before tinygltf sees it; images pass through undecoded), bounds-checked accessor views,
// the world matrices of the nodes with meshes, and the pieces of writing (serialisation, new
// buffer views and accessors). One file format, io/gltf_surface.cpp builds on it.
//
// [SECTION] index
//   1. Errors and checked arithmetic
//   2. Loading the document (GLB layout check, tinygltf, images passed through undecoded)
//   3. Accessors (bounds-checked views, component conversion)
//   4. Scene traversal (world matrices)
//   6. Writing (serialisation, buffer views and accessors)

#include "io/gltf_document.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/atomic_file.h"
#include "io/file_error.h"
#include "io/input_file.h"
#include "io/json_nesting.h"

namespace sculpt::gltf {

// -------------------------------------------------------------------------------------------
// [SECTION] 1. Errors and checked arithmetic
// -------------------------------------------------------------------------------------------

/// Throws "<path>: <element>: <problem>" (the element may be empty).
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& element,
                       const std::string& problem) {
  std::string message = path.string() + ": ";
  if (!element.empty()) message += element + ": ";
  throw FileError(message + problem);
}

namespace {

constexpr size_t kSizeMax = std::numeric_limits<size_t>::max();

/// a + b and a * b, saturating at SIZE_MAX (hostile counts must not wrap around).
size_t addSaturated(size_t a, size_t b) { return a > kSizeMax - b ? kSizeMax : a + b; }
size_t mulSaturated(size_t a, size_t b) { return b != 0 && a > kSizeMax / b ? kSizeMax : a * b; }

}  // namespace

std::string primitiveLabel(int mesh, size_t primitive) {
  return "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive);
}

// -------------------------------------------------------------------------------------------
// [SECTION] 2. Loading the document
// -------------------------------------------------------------------------------------------

namespace {

uint32_t readLittleEndian32(const std::string& bytes, size_t at) {
  uint32_t value = 0;
  for (size_t k = 0; k < 4; ++k) {
    value |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
  }
  return value;
}

/// Checks the GLB header and chunk sizes against the file size before tinygltf sees them
/// (tinygltf 2.7 trusts the BIN chunk length by 8 bytes too many). Returns the GLB length.
size_t checkGlbLayout(const std::filesystem::path& path, const std::string& bytes) {
  constexpr size_t kHeader = 12, kChunkHeader = 8;
  if (bytes.size() < kHeader + kChunkHeader) {
    fail(path, "",
         "truncated .glb: " + std::to_string(bytes.size()) +
             " bytes, the header and JSON chunk header need 20");
  }
  if (const uint32_t version = readLittleEndian32(bytes, 4); version != 2) {
    fail(path, "", "glTF binary version " + std::to_string(version) + ", only 2 is supported");
  }
  const size_t length = readLittleEndian32(bytes, 8);
  if (length > bytes.size()) {
    fail(path, "",
         "truncated .glb: the header gives " + std::to_string(length) + " bytes, the file has " +
             std::to_string(bytes.size()));
  }
  const size_t jsonLength = readLittleEndian32(bytes, 12);
  if (readLittleEndian32(bytes, 16) != 0x4E4F534Au)
    fail(path, "", "the first .glb chunk is not JSON");
  const size_t jsonEnd = kHeader + kChunkHeader + jsonLength;
  if (jsonEnd > length) {
    fail(path, "",
         "truncated .glb: the JSON chunk of " + std::to_string(jsonLength) +
             " bytes ends past the end of the data (" + std::to_string(length) + " bytes)");
  }
  if (jsonEnd == length) return length;
  if (jsonEnd + kChunkHeader > length)
    fail(path, "", "truncated .glb: incomplete BIN chunk header");
  const size_t binLength = readLittleEndian32(bytes, jsonEnd);
  if (jsonEnd + kChunkHeader + binLength > length) {
    fail(path, "",
         "truncated .glb: the BIN chunk of " + std::to_string(binLength) +
             " bytes ends past the end of the data (" + std::to_string(length) + " bytes)");
  }
  return length;
}

/// Image loader that decodes nothing: the geometry is all we need, and images must be written
/// back exactly as they were. Only data-URI images keep their (decoded base64) bytes, to be
/// embedded again on writing; images in buffer views stay there and external files keep their
/// URI. Never reads `bytes` for buffer-view images, whose range tinygltf does not check.
bool keepImageUndecoded(tinygltf::Image* image, int /*index*/, std::string* /*err*/,
                        std::string* /*warn*/, int /*width*/, int /*height*/,
                        const unsigned char* bytes, int size, void* /*user*/) {
  if (image->bufferView != -1 || !image->uri.empty() || size <= 0) return true;
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

std::string base64(const std::vector<unsigned char>& data) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((data.size() + 2) / 3 * 4);
  for (size_t i = 0; i < data.size(); i += 3) {
    const size_t n = std::min<size_t>(3, data.size() - i);
    uint32_t triple = uint32_t{data[i]} << 16;
    if (n > 1) triple |= uint32_t{data[i + 1]} << 8;
    if (n > 2) triple |= uint32_t{data[i + 2]};
    for (size_t k = 0; k < 4; ++k) {
      out += k <= n ? kDigits[(triple >> (18 - 6 * k)) & 63u] : '=';
    }
  }
  return out;
}

/// Image writer matching keepImageUndecoded: external URIs and buffer views are left as they
/// are (returning false keeps the original URI), data-URI images are embedded again unchanged.
bool writeImageAsLoaded(const std::string* /*baseDir*/, const std::string* /*fileName*/,
                        const tinygltf::Image* image, bool /*embed*/, std::string* outUri,
                        void* /*user*/) {
  if (!image->uri.empty() || !image->as_is || image->image.empty()) return false;
  const std::string mime = image->mimeType.empty() ? "application/octet-stream" : image->mimeType;
  *outUri = "data:" + mime + ";base64," + base64(image->image);
  return true;
}

// The files that a .gltf names by uri (buffers, images) are read through readInputFile, like
// the document itself: tinygltf's own reader opens a directory, a device or a FIFO and then
// allocates what seeking reports (bad_alloc) or blocks. A relative uri is taken relative to the
// document only, as glTF specifies, so that a missing file is named rather than looked for in
// the working directory.
struct ResourceReads {
  std::vector<std::pair<std::string, std::string>> refusals;  // (path as tinygltf gave it, why)
};

bool resourcePathGiven(const std::string& /*path*/, void* /*user*/) { return true; }

bool readResource(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                  void* user) {
  try {
    const std::string bytes = readInputFile(path, kGltfResourceInput);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const FileError& error) {
    static_cast<ResourceReads*>(user)->refusals.emplace_back(path, error.what());
    if (err != nullptr) *err += error.what();
    return false;
  }
}

/// The refusal behind a failed load, if a buffer's file was refused: tinygltf stops at the first
/// buffer it cannot read (so it is buffer `model.buffers.size()`) and, unlike an image, reports
/// it as an error, naming the path.
void failOnRefusedBuffer(const std::filesystem::path& path, const tinygltf::Model& model,
                         const ResourceReads& reads, const std::string& error) {
  for (const auto& [resource, why] : reads.refusals) {
    if (error.find("File read error : " + resource) == std::string::npos) continue;
    fail(path, "buffer " + std::to_string(model.buffers.size()), why);
  }
}

std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line.empty() ? "no reason given" : line;
}

}  // namespace

// Far deeper than any glTF's own structure needs (about 10) and far from what overflows the
// parser's stack (tens of thousands of levels).
constexpr int kMaxJsonNesting = 512;

tinygltf::Model loadModel(const std::filesystem::path& path) {
  const std::string bytes = readInputFile(path, kSurfaceInput);  // below 4 GiB, as GLB's lengths
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  const size_t length = binary ? checkGlbLayout(path, bytes) : bytes.size();
  // tinygltf's JSON parser recurses once per level: a hostile file could overflow the stack.
  const std::string_view json =
      binary ? std::string_view(bytes).substr(20, readLittleEndian32(bytes, 12))
             : std::string_view(bytes);
  if (const size_t at = excessiveJsonNesting(json, kMaxJsonNesting); at != std::string_view::npos)
    fail(path, "",
         "not valid glTF (its JSON nests deeper than " + std::to_string(kMaxJsonNesting) +
             " levels, at byte " + std::to_string(binary ? at + 20 : at) + ")");

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keepImageUndecoded, nullptr);
  ResourceReads reads;
  loader.SetFsCallbacks({&resourcePathGiven, &tinygltf::ExpandFilePath, &readResource,
                         &tinygltf::WriteWholeFile, &reads});
  tinygltf::Model model;
  std::string error, warning;
  const std::string baseDir = path.parent_path().string();
  bool loaded = false;
  try {
    loaded = binary
                 ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                               reinterpret_cast<const unsigned char*>(bytes.data()),
                                               static_cast<unsigned int>(length), baseDir)
                 : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                              static_cast<unsigned int>(length), baseDir);
  } catch (const std::exception& exception) {  // tinygltf 2.7 can throw on empty buffers
    error = exception.what();
  }
  if (!loaded) {
    failOnRefusedBuffer(path, model, reads, error);
    fail(path, "", "not valid glTF (" + firstLine(error) + ")");
  }
  for (const std::string& extension : model.extensionsRequired) {
    if (extension == "KHR_draco_mesh_compression" || extension == "EXT_meshopt_compression") {
      fail(path, "", "requires " + extension + ": compressed geometry is not supported");
    }
  }
  return model;
}

// -------------------------------------------------------------------------------------------
// [SECTION] 3. Accessors
// -------------------------------------------------------------------------------------------


/// Validates accessor `index` (used as `role`) and returns where its elements lie. Rejects
/// sparse accessors and any element that would fall outside its buffer view or buffer.
AccessorView accessorView(const std::filesystem::path& path, const tinygltf::Model& model,
                          int index, const std::string& role,
                          std::initializer_list<int> componentTypes, int components) {
  const std::string label = "accessor " + std::to_string(index) + " (" + role + ")";
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) {
    fail(path, role, "accessor " + std::to_string(index) + " does not exist");
  }
  const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(index)];
  if (accessor.sparse.isSparse) fail(path, label, "sparse accessors are not supported");
  if (std::find(componentTypes.begin(), componentTypes.end(), accessor.componentType) ==
      componentTypes.end()) {
    fail(path, label,
         "component type " + std::to_string(accessor.componentType) +
             " is not supported here (quantized geometry is not)");
  }
  const int typeComponents = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
  if (typeComponents != components) {
    fail(path, label,
         "has " + std::to_string(typeComponents) + " components, expected " +
             std::to_string(components));
  }
  if (accessor.bufferView < 0 ||
      static_cast<size_t>(accessor.bufferView) >= model.bufferViews.size()) {
    fail(path, label, "buffer view " + std::to_string(accessor.bufferView) + " does not exist");
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(accessor.bufferView)];
  const std::string viewLabel = "buffer view " + std::to_string(accessor.bufferView);
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
    fail(path, viewLabel, "buffer " + std::to_string(view.buffer) + " does not exist");
  }
  const size_t bufferSize = model.buffers[static_cast<size_t>(view.buffer)].data.size();
  if (addSaturated(view.byteOffset, view.byteLength) > bufferSize) {
    fail(path, viewLabel,
         "bytes " + std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
             " exceed buffer " + std::to_string(view.buffer) + " of " + std::to_string(bufferSize) +
             " bytes");
  }
  const auto elementSize = static_cast<size_t>(
      tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType)) *
      components);
  const size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
  if (accessor.count > 0) {
    const size_t needed = addSaturated(
        addSaturated(accessor.byteOffset, mulSaturated(accessor.count - 1, stride)), elementSize);
    if (needed > view.byteLength) {
      fail(path, label,
           "count " + std::to_string(accessor.count) + " with stride " + std::to_string(stride) +
               " from offset " + std::to_string(accessor.byteOffset) + " needs " +
               std::to_string(needed) + " bytes, " + viewLabel + " has " +
               std::to_string(view.byteLength));
    }
  }
  return {static_cast<size_t>(view.buffer),
          view.byteOffset + accessor.byteOffset,
          stride,
          accessor.count,
          accessor.componentType,
          components,
          accessor.normalized};
}

namespace {

template <typename T>
T load(const unsigned char* at) {
  T value;
  std::memcpy(&value, at, sizeof value);
  return value;
}

/// One component as a double, normalized integers mapped as the glTF specification says.
double readComponent(const unsigned char* at, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return load<float>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? load<uint8_t>(at) / 255.0 : load<uint8_t>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return normalized ? load<uint16_t>(at) / 65535.0 : load<uint16_t>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return load<uint32_t>(at);
    default:
      return 0.0;  // accessorView admits only the types above
  }
}

}  // namespace

/// The elements as #count by #components doubles, rejecting non-finite values.
Eigen::MatrixXd readElements(const std::filesystem::path& path, const tinygltf::Model& model,
                             const AccessorView& view, const std::string& label) {
  const unsigned char* data = model.buffers[view.buffer].data.data() + view.offset;
  const auto componentSize = static_cast<size_t>(
      tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(view.componentType)));
  Eigen::MatrixXd values(static_cast<Eigen::Index>(view.count), view.components);
  for (size_t i = 0; i < view.count; ++i) {
    for (int k = 0; k < view.components; ++k) {
      const double value =
          readComponent(data + i * view.stride + static_cast<size_t>(k) * componentSize,
                        view.componentType, view.normalized);
      if (!std::isfinite(value)) {
        fail(path, label, "element " + std::to_string(i) + " is not finite");
      }
      values(static_cast<Eigen::Index>(i), k) = value;
    }
  }
  return values;
}

// -------------------------------------------------------------------------------------------
// [SECTION] 4. Scene traversal
// -------------------------------------------------------------------------------------------

namespace {

Eigen::Matrix4d localMatrix(const std::filesystem::path& path, const tinygltf::Node& node,
                            int index) {
  const std::string label = "node " + std::to_string(index);
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16) fail(path, label, "matrix must have 16 numbers");
    return Eigen::Map<const Eigen::Matrix4d>(node.matrix.data());  // column-major, as glTF
  }
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();
  if (!node.translation.empty()) {
    if (node.translation.size() != 3) fail(path, label, "translation must have 3 numbers");
    transform.translate(
        Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4) fail(path, label, "rotation must have 4 numbers");
    Eigen::Quaterniond rotation(node.rotation[3], node.rotation[0], node.rotation[1],
                                node.rotation[2]);
    if (!(rotation.norm() > 0.0)) fail(path, label, "rotation is a zero quaternion");
    transform.rotate(rotation.normalized());
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3) fail(path, label, "scale must have 3 numbers");
    transform.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
  }
  return transform.matrix();
}

}  // namespace

/// The nodes with a mesh in the default scene (or scene 0; or, without scenes, every root
/// node), depth first in document order, with their world matrices.
std::vector<MeshInstance> meshInstances(const std::filesystem::path& path,
                                        const tinygltf::Model& model) {
  const auto numNodes = static_cast<int>(model.nodes.size());
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<size_t>(scene) >= model.scenes.size()) {
      fail(path, "", "default scene " + std::to_string(scene) + " does not exist");
    }
    roots = model.scenes[static_cast<size_t>(scene)].nodes;
  } else {
    std::vector<char> isChild(model.nodes.size(), 0);
    for (const tinygltf::Node& node : model.nodes) {
      for (int child : node.children) {
        if (child >= 0 && child < numNodes) isChild[static_cast<size_t>(child)] = 1;
      }
    }
    for (int n = 0; n < numNodes; ++n) {
      if (!isChild[static_cast<size_t>(n)]) roots.push_back(n);
    }
  }

  // Iterative depth-first walk: hostile files may nest nodes deeper than the call stack allows.
  std::vector<MeshInstance> instances;
  std::vector<char> visited(model.nodes.size(), 0);
  std::vector<MeshInstance> stack;
  for (auto root = roots.rbegin(); root != roots.rend(); ++root) {
    stack.push_back({*root, Eigen::Matrix4d::Identity()});
  }
  while (!stack.empty()) {
    const MeshInstance parent = stack.back();
    stack.pop_back();
    if (parent.node < 0 || parent.node >= numNodes) {
      fail(path, "", "node " + std::to_string(parent.node) + " does not exist");
    }
    const auto n = static_cast<size_t>(parent.node);
    if (visited[n]) {
      fail(path, "node " + std::to_string(parent.node),
           "reached twice in the scene (a node must have at most one parent, without cycles)");
    }
    visited[n] = 1;
    const tinygltf::Node& node = model.nodes[n];
    const Eigen::Matrix4d world = parent.world * localMatrix(path, node, parent.node);
    if (node.mesh >= 0) instances.push_back({parent.node, world});
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
      stack.push_back({*child, world});
    }
  }
  return instances;
}

// -------------------------------------------------------------------------------------------
// [SECTION] 6. Writing
// -------------------------------------------------------------------------------------------

namespace {

bool endsWithGlb(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".glb";
}

}  // namespace

/// Serialises the model (binary for .glb, else JSON with embedded buffers) and writes it
/// atomically.
void writeModel(const std::filesystem::path& path, tinygltf::Model& model) {
  const bool binary = endsWithGlb(path);
  // In a .glb, buffer 0 without a URI is the BIN chunk; other buffers become data URIs.
  if (binary && !model.buffers.empty()) model.buffers[0].uri.clear();
  tinygltf::TinyGLTF writer;
  writer.SetImageWriter(&writeImageAsLoaded, nullptr);
  std::ostringstream stream;
  bool written = false;
  try {
    written = writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/true, binary);
  } catch (const std::exception& exception) {
    fail(path, "", std::string("cannot serialise glTF (") + exception.what() + ")");
  }
  if (!written || !stream) fail(path, "", "cannot serialise glTF");
  writeFileAtomically(path, stream.str());
}



int appendAccessor(tinygltf::Model& model, int bufferView, int componentType, int type,
                   size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = bufferView;
  accessor.componentType = componentType;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size() - 1);
}

}  // namespace sculpt::gltf
