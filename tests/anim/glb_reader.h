#pragma once
// A small .glb reader for the writers' tests, independent of the writer: the header, the JSON
// chunk (nlohmann::json) and the BIN chunk, with typed access to accessors.

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/atomic_file.h"

namespace sculpt::test {

struct GlbFile {
  uint32_t version = 0;
  uint32_t length = 0;
  nlohmann::json json;
  std::string bin;

  static GlbFile read(const std::filesystem::path& path) {
    const std::string bytes = readFile(path);
    const auto word = [&](size_t at) {
      if (at + 4 > bytes.size()) throw std::runtime_error("truncated");
      uint32_t v = 0;
      std::memcpy(&v, bytes.data() + at, 4);
      return v;
    };
    if (bytes.compare(0, 4, "glTF") != 0) throw std::runtime_error("no glTF magic");
    GlbFile file;
    file.version = word(4);
    file.length = word(8);
    if (file.length != bytes.size()) throw std::runtime_error("header length != file size");
    const uint32_t jsonLength = word(12);
    if (word(16) != 0x4E4F534A) throw std::runtime_error("first chunk is not JSON");
    file.json = nlohmann::json::parse(bytes.substr(20, jsonLength));
    const size_t binAt = 20 + size_t{jsonLength};
    const uint32_t binLength = word(binAt);
    if (word(binAt + 4) != 0x004E4942) throw std::runtime_error("second chunk is not BIN");
    if (binAt + 8 + binLength != bytes.size()) throw std::runtime_error("BIN chunk length");
    file.bin = bytes.substr(binAt + 8, binLength);
    return file;
  }

  static size_t components(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    throw std::runtime_error("type " + type);
  }

  /// The accessor's elements, flattened; T must match its component type (tightly packed).
  template <class T>
  std::vector<T> values(int accessor) const {
    const nlohmann::json& a = json.at("accessors").at(static_cast<size_t>(accessor));
    const nlohmann::json& view = json.at("bufferViews").at(a.at("bufferView").get<size_t>());
    const size_t offset = view.value("byteOffset", size_t{0}) + a.value("byteOffset", size_t{0});
    const size_t count = a.at("count").get<size_t>() * components(a.at("type").get<std::string>());
    if (offset + count * sizeof(T) >
            view.value("byteOffset", size_t{0}) + view.at("byteLength").get<size_t>() ||
        offset + count * sizeof(T) > bin.size()) {
      throw std::runtime_error("accessor " + std::to_string(accessor) + " outside its view");
    }
    std::vector<T> out(count);
    std::memcpy(out.data(), bin.data() + offset, count * sizeof(T));
    return out;
  }
};

}  // namespace sculpt::test
