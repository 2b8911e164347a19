// glTF JSON from hostile files: nesting deep enough to overflow the JSON parser's stack (tens of
// thousands of levels in an "extras") is one sentence naming the file, for .glb and .gltf alike,
// and ordinary depths still parse.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/file_error.h"
#include "io/surface_file.h"
#include "support/scratch_directory.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

// A glTF document with no meshes whose asset "extras" nests `depth` arrays.
std::string nestedDocument(int depth) {
  return R"({"asset": {"version": "2.0", "extras": )" + std::string(depth, '[') +
         std::string(depth, ']') + "}}";
}

void appendU32(std::string& out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out += static_cast<char>((v >> (8 * k)) & 0xFF);
}

// The document as a .glb with its JSON chunk only.
std::string glbOf(std::string json) {
  while (json.size() % 4 != 0) json += ' ';
  std::string out = "glTF";
  appendU32(out, 2);
  appendU32(out, static_cast<uint32_t>(20 + json.size()));
  appendU32(out, static_cast<uint32_t>(json.size()));
  appendU32(out, 0x4E4F534Au);  // "JSON"
  return out + json;
}

// The message of reading `path` (empty when it reads).
std::string readError(const fs::path& path) {
  try {
    readSurfaceFile(path);
  } catch (const FileError& error) {
    return error.what();
  }
  return {};
}

TEST(GltfNesting, DeepNestingIsOneSentenceAndOrdinaryDepthsParse) {
  test::ScratchDirectory scratch("gltf_nesting");
  const auto write = [&](const std::string& name, const std::string& bytes) {
    const fs::path path = scratch.path() / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  };
  for (const char* name : {"deep.glb", "deep.gltf"}) {
    const std::string json = nestedDocument(20000);
    const fs::path path = write(name, std::string(name).ends_with(".glb") ? glbOf(json) : json);
    const std::string error = readError(path);
    EXPECT_NE(
        error.find(std::string(name) + ": not valid glTF (its JSON nests deeper than 512 levels"),
        std::string::npos)
        << error;
  }
  // 300 levels reach the parser and then the reader, which finds no surface in the document.
  for (const char* name : {"ok.glb", "ok.gltf"}) {
    const std::string json = nestedDocument(300);
    const std::string error =
        readError(write(name, std::string(name).ends_with(".glb") ? glbOf(json) : json));
    EXPECT_EQ(error.find("nests deeper"), std::string::npos) << error;
    std::printf("[ %s, 300 levels ] %s\n", name, error.empty() ? "read" : error.c_str());
  }
}

}  // namespace
}  // namespace sculpt
