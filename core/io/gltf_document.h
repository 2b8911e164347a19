#pragma once
// The parts of a glTF document that io/gltf_surface.cpp reads and writes (io/gltf_document.cpp):
// internal to io, not a file format of its own.

#include <tiny_gltf.h>  // declarations only: the implementation is in Debian's libtinygltf.so

#include <Eigen/Core>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

namespace sculpt::gltf {

/// Throws FileError "<path>: <element>: <problem>" (the element may be empty).
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& element,
                       const std::string& problem);

/// "mesh M primitive P", for messages.
std::string primitiveLabel(int mesh, size_t primitive);

/// Reads and parses the file (GLB or JSON) with its layout checked first; images stay
/// undecoded. Throws FileError with one sentence naming the file.
tinygltf::Model loadModel(const std::filesystem::path& path);

/// Where an accessor's elements lie: element i starts at buffers[buffer].data[offset + i*stride].
struct AccessorView {
  size_t buffer = 0;
  size_t offset = 0;
  size_t stride = 0;
  size_t count = 0;
  int componentType = 0;
  int components = 0;
  bool normalized = false;
};

/// Validates accessor `index` (used as `role`) and returns where its elements lie. Rejects
/// sparse accessors and any element that would fall outside its buffer view or buffer.
AccessorView accessorView(const std::filesystem::path& path, const tinygltf::Model& model,
                          int index, const std::string& role,
                          std::initializer_list<int> componentTypes, int components);

/// The elements as #count by #components doubles, rejecting non-finite values.
Eigen::MatrixXd readElements(const std::filesystem::path& path, const tinygltf::Model& model,
                             const AccessorView& view, const std::string& label);

struct MeshInstance {
  int node = -1;
  Eigen::Matrix4d world;
};

/// The nodes with a mesh in the default scene (or scene 0; or, without scenes, every root
/// node), depth first in document order, with their world matrices.
std::vector<MeshInstance> meshInstances(const std::filesystem::path& path,
                                        const tinygltf::Model& model);

/// Serialises the model (binary for .glb, else JSON with embedded buffers) and writes it
/// atomically.
void writeModel(const std::filesystem::path& path, tinygltf::Model& model);

/// Writes float values into an accessor's elements, returning their component-wise min/max.
template <typename RowFunction>
void writeFloatElements(tinygltf::Model& model, const AccessorView& view, RowFunction row,
                        std::vector<double>& minValues, std::vector<double>& maxValues) {
  unsigned char* data = model.buffers[view.buffer].data.data() + view.offset;
  minValues.assign(3, std::numeric_limits<double>::infinity());
  maxValues.assign(3, -std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < view.count; ++i) {
    const Eigen::Vector3d value = row(static_cast<Eigen::Index>(i));
    for (size_t k = 0; k < 3; ++k) {
      const auto component = static_cast<float>(value[static_cast<Eigen::Index>(k)]);
      std::memcpy(data + i * view.stride + k * sizeof(float), &component, sizeof component);
      minValues[k] = std::min(minValues[k], static_cast<double>(component));
      maxValues[k] = std::max(maxValues[k], static_cast<double>(component));
    }
  }
}


/// Appends raw bytes to buffer 0 as a new buffer view (4-byte aligned); returns its index.
template <typename T>
int appendBufferView(tinygltf::Model& model, const std::vector<T>& values, int target) {
  std::vector<unsigned char>& bytes = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = bytes.size();
  view.byteLength = values.size() * sizeof(T);
  view.target = target;
  bytes.resize(bytes.size() + view.byteLength);
  std::memcpy(bytes.data() + view.byteOffset, values.data(), view.byteLength);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size() - 1);
}


int appendAccessor(tinygltf::Model& model, int bufferView, int componentType, int type,
                   size_t count);

}  // namespace sculpt::gltf
