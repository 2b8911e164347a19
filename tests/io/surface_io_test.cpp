// Surface files (OBJ, glTF): every OBJ face syntax, bit-exact OBJ round trips, glTF node
// transforms to scene space and back, documents kept on write-back, fresh .glb from OBJ, and
// rejection of malformed or hostile files with messages that name the problem.
//
// glTF inputs are written by hand (JSON text plus a little-endian binary buffer) so that the
// tests do not depend on the library under test to produce them.

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/file_error.h"
#include "io/gltf_surface.h"
#include "io/obj_surface.h"
#include "io/surface_file.h"
#include "support/gltf_validator.h"

namespace sculpt {
namespace {

constexpr uint32_t kNo = SurfaceCorner::kNoIndex;

/// Runs `action`, expecting a FileError whose message contains every one of `parts`.
template <typename Action>
void expectFileError(Action action, std::initializer_list<std::string> parts) {
  try {
    action();
    ADD_FAILURE() << "no error; expected one mentioning '" << *parts.begin() << "'";
  } catch (const FileError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
  }
}

class SurfaceIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("sculpt_surface_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path file(const std::string& name) const { return dir_ / name; }
  std::filesystem::path writeText(const std::string& name, const std::string& text) const {
    writeFileAtomically(file(name), text);
    return file(name);
  }
  std::filesystem::path dir_;
};

// ---------------------------------------------------------------------------------------------
// OBJ
// ---------------------------------------------------------------------------------------------

TEST_F(SurfaceIoTest, ObjParsesEveryFaceSyntax) {
  const SurfaceMesh s = parseObjSurface(
      "# a comment\n"
      "mtllib a.mtl\no thing\ng group\ns 1\nusemtl red\n"
      "v 0 0 0\n"
      "v 1 0 0 1.0\n"             // w
      "v 1 1 0 0.5 0.25 0.125\n"  // colour
      "v\t0 1 0   # trailing comment\r\n"
      "vt 0 0\nvt 1\nvt 1 1 0\n"  // a missing v is 0, w is dropped
      "vn 0 0 1\n"
      "l 1 2\np 3\n"
      "f 1 2 3\n"
      "f 1/1 2/2 3/3\n"
      "f 1//1 2//1 3//1\n"
      "f 1/1/1 2/2/1 3/3/1 4/3/1\n"
      "f -4/-3/-1 -3/-2/-1 -2/-1/-1\n",
      "inline.obj");
  ASSERT_EQ(s.numVertices(), 4u);
  ASSERT_EQ(s.texcoords.rows(), 3);
  ASSERT_EQ(s.normals.rows(), 1);
  EXPECT_EQ(s.positions.row(2), Eigen::RowVector3d(1, 1, 0));
  EXPECT_EQ(s.texcoords.row(1), Eigen::RowVector2d(1, 0));
  ASSERT_EQ(s.numFaces(), 5u);
  auto corner = [&](uint32_t f, uint32_t k) { return s.faces.row(f)[k]; };
  EXPECT_EQ(corner(0, 2).position, 2u);
  EXPECT_EQ(corner(0, 2).texcoord, kNo);
  EXPECT_EQ(corner(0, 2).normal, kNo);
  EXPECT_EQ(corner(1, 1).texcoord, 1u);
  EXPECT_EQ(corner(1, 1).normal, kNo);
  EXPECT_EQ(corner(2, 0).texcoord, kNo);
  EXPECT_EQ(corner(2, 0).normal, 0u);
  EXPECT_EQ(s.faces.rowSize(3), 4u);
  EXPECT_EQ(corner(3, 3).position, 3u);
  EXPECT_EQ(corner(3, 3).texcoord, 2u);
  // Negative indices count back from the end of each list so far.
  EXPECT_EQ(corner(4, 0).position, 0u);
  EXPECT_EQ(corner(4, 0).texcoord, 0u);
  EXPECT_EQ(corner(4, 2).position, 2u);
  EXPECT_EQ(corner(4, 2).normal, 0u);
}

TEST_F(SurfaceIoTest, ObjRoundTripIsBitExactAndKeepsOrder) {
  SurfaceMesh s;
  s.positions.resize(4, 3);
  s.positions << 0.1, 1.0 / 3.0, -0.0, 1e-300, -2.5e17, 7.0, 0.7, 0.2, 0.3, -1.0 / 7.0, 5.0, 6.0;
  s.texcoords.resize(3, 2);
  s.texcoords << 0.1, 0.9, 2.0 / 3.0, 0.0, 1.0, 1.0;
  s.normals.resize(2, 3);
  s.normals << 0.0, 0.6, 0.8, 1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0), -1.0 / std::sqrt(3.0);
  s.faces.values = {{3, 2, 1}, {1, 0, 0}, {0, 1, 1}};
  s.faces.closeRow();
  s.faces.values.insert(s.faces.values.end(),
                        {{0, kNo, kNo}, {1, kNo, kNo}, {2, kNo, kNo}, {3, kNo, kNo}});
  s.faces.closeRow();
  s.faces.values.insert(s.faces.values.end(), {{2, kNo, 1}, {3, kNo, 0}, {1, kNo, 1}});
  s.faces.closeRow();

  const auto path = file("round.obj");
  writeObjSurface(path, s);
  const LoadedSurface loaded = readSurfaceFile(path);
  const SurfaceMesh& r = loaded.surface();
  ASSERT_EQ(r.positions.rows(), s.positions.rows());
  ASSERT_EQ(r.texcoords.rows(), s.texcoords.rows());
  ASSERT_EQ(r.normals.rows(), s.normals.rows());
  auto bits = [](double x) { return std::bit_cast<uint64_t>(x); };
  for (Eigen::Index i = 0; i < s.positions.size(); ++i) {
    EXPECT_EQ(bits(r.positions.data()[i]), bits(s.positions.data()[i])) << i;
  }
  for (Eigen::Index i = 0; i < s.texcoords.size(); ++i) {
    EXPECT_EQ(bits(r.texcoords.data()[i]), bits(s.texcoords.data()[i])) << i;
  }
  for (Eigen::Index i = 0; i < s.normals.size(); ++i) {
    EXPECT_EQ(bits(r.normals.data()[i]), bits(s.normals.data()[i])) << i;
  }
  ASSERT_EQ(r.faces.offsets, s.faces.offsets);
  for (size_t c = 0; c < s.faces.values.size(); ++c) {
    EXPECT_EQ(r.faces.values[c].position, s.faces.values[c].position) << c;
    EXPECT_EQ(r.faces.values[c].texcoord, s.faces.values[c].texcoord) << c;
    EXPECT_EQ(r.faces.values[c].normal, s.faces.values[c].normal) << c;
  }
  // Writing the deformed surface through writeSurfaceFile keeps faces and texcoords.
  SurfaceMesh deformed = r;
  deformed.positions.array() += 1.0;
  writeSurfaceFile(file("moved.obj"), loaded, deformed);
  const SurfaceMesh moved = readSurfaceFile(file("moved.obj")).surface();
  EXPECT_EQ(moved.positions, deformed.positions);
  EXPECT_EQ(moved.texcoords, s.texcoords);
  EXPECT_EQ(moved.faces.offsets, s.faces.offsets);
}

TEST_F(SurfaceIoTest, ObjFloatPrecisionReadsBackAsTheSameFloats) {
  SurfaceMesh s = parseObjSurface("v 0.1 0.2 0.3\nv 1 2 3\nv 4 5 6.000001\nf 1 2 3\n", "f.obj");
  const std::string text = objSurfaceText(s, NumberPrecision::kFloat);
  EXPECT_NE(text.find("v 0.1 0.2 0.3\n"), std::string::npos) << text;
  const SurfaceMesh r = parseObjSurface(text, "f.obj");
  for (Eigen::Index i = 0; i < s.positions.size(); ++i) {
    EXPECT_EQ(static_cast<float>(r.positions.data()[i]), static_cast<float>(s.positions.data()[i]));
  }
}

TEST_F(SurfaceIoTest, NormalAnchorsAreTheFirstCornerPositions) {
  const SurfaceMesh s = parseObjSurface(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0 0 1\nvn 1 0 0\n"
      "f 2//2 3//1 1//2\nf 2//1 4//1 3//1\n",
      "a.obj");
  EXPECT_EQ(normalAnchors(s), (std::vector<uint32_t>{2, 1, kNo}));
}

TEST_F(SurfaceIoTest, ObjRejectsMalformedFilesWithLineNumbers) {
  auto parse = [](const std::string& text) { return [text] { parseObjSurface(text, "bad.obj"); }; };
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expectFileError(parse(tri + "f 1 2 4\n"),
                  {"bad.obj: line 4:", "face corner 3", "vertex index 4 is out of range"});
  expectFileError(parse(tri + "f 1 2 -4\n"), {"line 4", "vertex index -4 is out of range"});
  expectFileError(parse(tri + "vt 0 0\nf 1/1 2/2 3/1\n"),
                  {"line 5", "texture coordinate index 2 is out of range"});
  expectFileError(parse(tri + "f 1 0 3\n"), {"line 4", "face corner 2", "index 0 is invalid"});
  expectFileError(parse(tri + "f 1//0 2//1 3//1\n"), {"line 4", "normal index 0 is invalid"});
  expectFileError(parse("v 0 0 0\nv 1 0x 0\n"), {"bad.obj: line 2:", "'0x' is not a number"});
  expectFileError(parse("v 0 0 0\nv 1 , 0\n"), {"line 2", "',' is not a number"});
  expectFileError(parse("v 0 nan 0\n"), {"line 1", "'nan' is not finite"});
  expectFileError(parse("v 0 0 inf\n"), {"line 1", "'inf' is not finite"});
  expectFileError(parse("vn 0 1e999 0\n"), {"line 1", "normal", "'1e999' is not a number"});
  expectFileError(parse("v 0 0\n"), {"line 1", "vertex has 2 numbers, expected at least 3"});
  expectFileError(parse(tri + "f 1 2\n"), {"line 4", "face has 2 corners"});
  expectFileError(parse(tri + "f\n"), {"line 4", "face has 0 corners"});
  expectFileError(parse(tri + "f 1/2/3/4 2 3\n"), {"line 4", "more than three '/' fields"});
  expectFileError(parse(tri + "f 1/ 2 3\n"), {"line 4", "texture coordinate index '' is not"});
  expectFileError(parse(tri + "f 1 2 3.0\n"), {"line 4", "'3.0' is not an integer"});
  expectFileError(parse(tri + "f 1 2 99999999999999999999999\n"), {"line 4", "not an integer"});
  expectFileError(parse(tri), {"bad.obj: no faces"});
  expectFileError(parse(""), {"bad.obj: no faces"});
}

TEST_F(SurfaceIoTest, ObjParserSurvivesRandomBytes) {
  const std::string valid =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\nf -1 -2 -3\n";
  std::mt19937 random(7);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string text = valid;
    for (int k = 0; k < 3; ++k) {
      text[random() % text.size()] = static_cast<char>(random() % 256);
    }
    try {
      const SurfaceMesh s = parseObjSurface(text, "fuzz.obj");
      for (const SurfaceCorner& c : s.faces.values) ASSERT_LT(c.position, s.numVertices());
    } catch (const FileError&) {
    }
  }
}

// ---------------------------------------------------------------------------------------------
// glTF, built by hand
// ---------------------------------------------------------------------------------------------

/// A little-endian binary buffer under construction, 4-byte aligned between parts.
struct BinaryBuffer {
  std::string bytes;
  template <typename T>
  size_t add(std::initializer_list<T> values) {
    while (bytes.size() % 4 != 0) bytes += '\0';
    const size_t offset = bytes.size();
    for (T v : values) bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
    return offset;
  }
};

std::string base64(const std::string& data) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < data.size(); i += 3) {
    uint32_t n = static_cast<uint32_t>(static_cast<unsigned char>(data[i])) << 16;
    if (i + 1 < data.size())
      n |= static_cast<uint32_t>(static_cast<unsigned char>(data[i + 1])) << 8;
    if (i + 2 < data.size()) n |= static_cast<unsigned char>(data[i + 2]);
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += i + 1 < data.size() ? digits[(n >> 6) & 63] : '=';
    out += i + 2 < data.size() ? digits[n & 63] : '=';
  }
  return out;
}

void appendU32(std::string& out, uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); }

/// A .glb from a JSON document (its "buffers" given the BIN length) and a binary chunk.
std::string glbBytes(nlohmann::json document, std::string bin) {
  document["buffers"] = {{{"byteLength", bin.size()}}};
  std::string json = document.dump();
  while (json.size() % 4 != 0) json += ' ';
  while (bin.size() % 4 != 0) bin += '\0';
  std::string out = "glTF";
  appendU32(out, 2);
  appendU32(out, static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  appendU32(out, static_cast<uint32_t>(json.size()));
  appendU32(out, 0x4E4F534Au);
  out += json;
  appendU32(out, static_cast<uint32_t>(bin.size()));
  appendU32(out, 0x004E4942u);
  return out + bin;
}

/// The JSON chunk of a .glb file.
nlohmann::json glbJson(const std::string& glb) {
  uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  return nlohmann::json::parse(glb.substr(20, length));
}

/// A 1 by 1 PNG image as a data URI.
const std::string kPngDataUri =
    "data:image/"
    "png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAQAAAC1HAwCAAAAC0lEQVR42mNkYAAAAAYAAjCB0C8A"
    "AAAASUVORK5CYII=";

/// A unit quad (two triangles, NORMAL, TEXCOORD_0, a material and a data-URI image) under
/// node 1 (translation (1, 2, 3), scale 2), child of node 0 (translation (10, 0, 0)).
struct QuadModel {
  nlohmann::json document;
  BinaryBuffer bin;

  QuadModel() {
    const size_t positions = bin.add<float>({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    const size_t normals = bin.add<float>({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
    const size_t uvs = bin.add<float>({0, 1, 1, 1, 1, 0, 0, 0});
    const size_t indices = bin.add<uint16_t>({0, 1, 2, 0, 2, 3});
    document = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes",
         {{{"name", "parent"}, {"translation", {10, 0, 0}}, {"children", {1}}},
          {{"name", "quad"}, {"mesh", 0}, {"translation", {1, 2, 3}}, {"scale", {2, 2, 2}}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
              {"indices", 3},
              {"material", 0}}}}}}},
        {"materials",
         {{{"name", "red paint"},
           {"pbrMetallicRoughness",
            {{"baseColorFactor", {1, 0, 0, 1}}, {"baseColorTexture", {{"index", 0}}}}}}}},
        {"textures", {{{"source", 0}}}},
        {"images", {{{"uri", kPngDataUri}}}},
        {"accessors",
         {{{"bufferView", 0},
           {"componentType", 5126},
           {"count", 4},
           {"type", "VEC3"},
           {"min", {0, 0, 0}},
           {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
          {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
          {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", positions}, {"byteLength", 48}},
          {{"buffer", 0}, {"byteOffset", normals}, {"byteLength", 48}},
          {{"buffer", 0}, {"byteOffset", uvs}, {"byteLength", 32}},
          {{"buffer", 0}, {"byteOffset", indices}, {"byteLength", 12}}}}};
  }

  std::string glb() const { return glbBytes(document, bin.bytes); }
  std::string gltfWithDataUri() const {
    nlohmann::json d = document;
    d["buffers"] = {{{"byteLength", bin.bytes.size()},
                     {"uri", "data:application/octet-stream;base64," + base64(bin.bytes)}}};
    return d.dump(1);
  }
  std::string gltfWithExternalBuffer(const std::string& binName) const {
    nlohmann::json d = document;
    d["buffers"] = {{{"byteLength", bin.bytes.size()}, {"uri", binName}}};
    return d.dump(1);
  }
};

/// Scene space of the quad: p -> (10, 0, 0) + (1, 2, 3) + 2 p.
Eigen::RowVector3d quadScenePosition(double x, double y) { return {11 + 2 * x, 2 + 2 * y, 3}; }

void expectQuadInSceneSpace(const SurfaceMesh& s) {
  ASSERT_EQ(s.numVertices(), 4u);
  EXPECT_EQ(s.positions.row(0), quadScenePosition(0, 0));
  EXPECT_EQ(s.positions.row(1), quadScenePosition(1, 0));
  EXPECT_EQ(s.positions.row(2), quadScenePosition(1, 1));
  EXPECT_EQ(s.positions.row(3), quadScenePosition(0, 1));
  ASSERT_EQ(s.normals.rows(), 4);
  EXPECT_EQ(s.normals.row(2), Eigen::RowVector3d(0, 0, 1));
  ASSERT_EQ(s.texcoords.rows(), 4);
  EXPECT_EQ(s.texcoords.row(0), Eigen::RowVector2d(0, 0));  // glTF (0, 1): v flipped
  EXPECT_EQ(s.texcoords.row(2), Eigen::RowVector2d(1, 1));
  ASSERT_EQ(s.numFaces(), 2u);
  EXPECT_EQ(s.faces.row(1)[2].position, 3u);
  EXPECT_EQ(s.faces.row(1)[2].normal, 3u);
  EXPECT_EQ(s.faces.row(1)[2].texcoord, 3u);
}

TEST_F(SurfaceIoTest, GltfReadsGlbDataUriAndExternalBuffersInSceneSpace) {
  const QuadModel quad;
  writeText("quad.glb", quad.glb());
  writeText("quad_embedded.gltf", quad.gltfWithDataUri());
  writeText("quad.bin", quad.bin.bytes);
  writeText("quad_external.GLTF", quad.gltfWithExternalBuffer("quad.bin"));
  for (const char* name : {"quad.glb", "quad_embedded.gltf", "quad_external.GLTF"}) {
    SCOPED_TRACE(name);
    const LoadedSurface loaded = readSurfaceFile(file(name));
    ASSERT_NE(loaded.gltf(), nullptr);
    expectQuadInSceneSpace(loaded.surface());
  }
}

TEST_F(SurfaceIoTest, GltfWriteBackMovesPositionsAndKeepsTheDocument) {
  const QuadModel quad;
  const LoadedSurface loaded = readSurfaceFile(writeText("quad.glb", quad.glb()));
  SurfaceMesh deformed = loaded.surface();
  deformed.positions.col(2).array() += 1.0;  // lift by 1 in scene space
  deformed.normals.row(0) << 0.0, 0.6, 0.8;  // tilt one normal

  for (const char* name : {"out.glb", "out.gltf"}) {
    SCOPED_TRACE(name);
    writeSurfaceFile(file(name), loaded, deformed);
    const SurfaceMesh again = readSurfaceFile(file(name)).surface();
    ASSERT_EQ(again.numVertices(), 4u);
    EXPECT_TRUE(again.positions.isApprox(deformed.positions, 1e-7)) << again.positions;
    EXPECT_NEAR((again.normals.row(0) - Eigen::RowVector3d(0, 0.6, 0.8)).norm(), 0.0, 1e-7);
    EXPECT_EQ(again.texcoords, loaded.surface().texcoords);
    EXPECT_EQ(again.faces.offsets, loaded.surface().faces.offsets);

    const std::string bytes = readFile(file(name));
    const nlohmann::json out =
        std::string(name).ends_with(".glb") ? glbJson(bytes) : nlohmann::json::parse(bytes);
    // Local z of the lifted quad: (3 + 1 - 3) / 2 = 0.5.
    EXPECT_EQ(out["accessors"][0]["max"], nlohmann::json({1.0, 1.0, 0.5}));
    EXPECT_EQ(out["accessors"][0]["min"], nlohmann::json({0.0, 0.0, 0.5}));
    EXPECT_EQ(out["materials"][0]["name"], "red paint");
    EXPECT_EQ(out["nodes"][1]["translation"], nlohmann::json({1.0, 2.0, 3.0}));
    EXPECT_EQ(out["images"][0]["uri"], kPngDataUri);
  }
}

TEST_F(SurfaceIoTest, GltfRotationsMirrorsAndNonIndexedStripsAndFans) {
  // Node 0: rotation of 90 degrees about z; node 1: mirror in x (scale -1), so its triangles
  // are wound the other way in scene space. Mesh 0 is a non-indexed strip, mesh 1 a fan.
  BinaryBuffer bin;
  const size_t strip = bin.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
  const size_t stripNormals = bin.add<float>({1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0});
  const size_t fan = bin.add<float>({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  const double s = std::sqrt(0.5);
  const nlohmann::json document = {
      {"asset", {{"version", "2.0"}}},
      {"scenes", {{{"nodes", {0, 1}}}}},
      {"nodes", {{{"mesh", 0}, {"rotation", {0, 0, s, s}}}, {{"mesh", 1}, {"scale", {-1, 1, 1}}}}},
      {"meshes", nlohmann::json::array(
                     {{{"primitives",
                        nlohmann::json::array(
                            {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"mode", 5}}})}},
                      {{"primitives", nlohmann::json::array(
                                          {{{"attributes", {{"POSITION", 2}}}, {"mode", 6}},
                                           {{"attributes", {{"POSITION", 2}}}, {"mode", 1}}})}}})},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", strip}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", stripNormals}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", fan}, {"byteLength", 48}}}}};
  const SurfaceMesh surface =
      readSurfaceFile(writeText("modes.glb", glbBytes(document, bin.bytes))).surface();
  ASSERT_EQ(surface.numVertices(), 8u);
  EXPECT_TRUE(surface.positions.row(1).isApprox(Eigen::RowVector3d(0, 1, 0), 1e-12));
  EXPECT_TRUE(surface.normals.row(1).isApprox(Eigen::RowVector3d(0, 1, 0), 1e-12));
  EXPECT_EQ(surface.normals.rows(), 8);  // rows 4-7 (the fan has no normals) unused
  EXPECT_EQ(surface.positions.row(5), Eigen::RowVector3d(-1, 0, 0));
  ASSERT_EQ(surface.numFaces(), 4u);  // strip 2 + fan 2, the line primitive skipped
  auto positions = [&](uint32_t f) {
    std::vector<uint32_t> p;
    for (const SurfaceCorner& c : surface.faces.row(f)) p.push_back(c.position);
    return p;
  };
  EXPECT_EQ(positions(0), (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(positions(1), (std::vector<uint32_t>{1, 3, 2}));
  // Fan triangles (v1, v2, v0) and (v2, v3, v0), reversed by the mirror.
  EXPECT_EQ(positions(2), (std::vector<uint32_t>{5, 4, 6}));
  EXPECT_EQ(positions(3), (std::vector<uint32_t>{6, 4, 7}));
  EXPECT_EQ(surface.faces.row(2)[0].normal, kNo);
  // Every face is counter-clockwise seen from +z (all lie in z = 0, normal +z after the mirror).
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    const auto p = positions(f);
    const Eigen::Vector3d a = surface.positions.row(p[0]), b = surface.positions.row(p[1]),
                          c = surface.positions.row(p[2]);
    EXPECT_GT((b - a).cross(c - a).z(), 0.0) << f;
  }
}

TEST_F(SurfaceIoTest, GltfSharedVertexAccessorsShareOneBlock) {
  // Two primitives (say, two materials) over the same vertex accessors.
  QuadModel quad;
  quad.document["meshes"][0]["primitives"] = {
      {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 3}},
      {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 4}}};
  quad.document["accessors"][3]["count"] = 3;
  quad.document["accessors"].push_back({{"bufferView", 3},
                                        {"byteOffset", 6},
                                        {"componentType", 5123},
                                        {"count", 3},
                                        {"type", "SCALAR"}});
  const LoadedSurface loaded = readSurfaceFile(writeText("shared.glb", quad.glb()));
  EXPECT_EQ(loaded.surface().numVertices(), 4u);
  EXPECT_EQ(loaded.surface().numFaces(), 2u);
  SurfaceMesh deformed = loaded.surface();
  deformed.positions.array() += 0.5;
  writeSurfaceFile(file("out.glb"), loaded, deformed);
  EXPECT_TRUE(readSurfaceFile(file("out.glb")).surface().positions.isApprox(deformed.positions));
}

TEST_F(SurfaceIoTest, ObjToFreshGlbKeepsVertexOrderWhenIndicesAgree) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.5\nv 2 2 2\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
      "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0.6 0.8\nvn 1 0 0\n"
      "f 1/1/1 2/2/2 3/3/3 4/4/4\n";
  const LoadedSurface loaded = readSurfaceFile(writeText("quad.obj", obj));
  writeSurfaceFile(file("quad.glb"), loaded, loaded.surface());
  const SurfaceMesh glb = readSurfaceFile(file("quad.glb")).surface();
  EXPECT_EQ(glb.positions, loaded.surface().positions);  // all values are exact floats
  EXPECT_EQ(glb.texcoords, loaded.surface().texcoords);
  EXPECT_TRUE(glb.normals.isApprox(loaded.surface().normals, 1e-7));
  ASSERT_EQ(glb.numFaces(), 2u);  // the quad fanned into two triangles
  EXPECT_EQ(glb.faces.row(1)[0].position, 0u);
  EXPECT_EQ(glb.faces.row(1)[2].position, 3u);
}

TEST_F(SurfaceIoTest, ObjToFreshGltfSplitsVerticesByCornerTuple) {
  // A cube with 8 positions and 6 face normals: 24 distinct (v, vn) corners.
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n"
      "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 2//3 6//3 5//3\n"
      "f 2//4 3//4 7//4 6//4\nf 3//5 4//5 8//5 7//5\nf 4//6 1//6 5//6 8//6\n";
  const LoadedSurface loaded = readSurfaceFile(writeText("cube.obj", obj));
  writeSurfaceFile(file("cube.gltf"), loaded, loaded.surface());
  const SurfaceMesh gltf = readSurfaceFile(file("cube.gltf")).surface();
  EXPECT_EQ(gltf.numVertices(), 24u);
  EXPECT_EQ(gltf.numFaces(), 12u);
  EXPECT_EQ(gltf.texcoords.rows(), 0);
  // First use order: face 0's corners come first.
  EXPECT_EQ(gltf.positions.row(1), Eigen::RowVector3d(0, 1, 0));
  EXPECT_EQ(gltf.normals.row(1), Eigen::RowVector3d(0, 0, -1));
  // Each corner keeps its position and normal.
  const SurfaceMesh& in = loaded.surface();
  for (uint32_t f = 0; f < 6; ++f) {
    const SurfaceCorner first = in.faces.row(f)[0];
    const SurfaceCorner written = gltf.faces.row(2 * f)[0];
    EXPECT_EQ(gltf.positions.row(written.position), in.positions.row(first.position));
    EXPECT_EQ(gltf.normals.row(written.normal), in.normals.row(first.normal));
  }
}

TEST_F(SurfaceIoTest, GltfOutputOfGltfInputAsObj) {
  const QuadModel quad;
  const LoadedSurface loaded = readSurfaceFile(writeText("quad.glb", quad.glb()));
  writeSurfaceFile(file("quad.obj"), loaded, loaded.surface());
  expectQuadInSceneSpace(readSurfaceFile(file("quad.obj")).surface());
}


TEST_F(SurfaceIoTest, WrittenFilesPassTheKhronosValidator) {
  const auto script = test::gltfValidatorScript();
  ASSERT_FALSE(script.empty())
      << "the glTF validator is missing: run scripts/install-gltf-validator.sh";
  ASSERT_EQ(std::system("node --version > /dev/null 2>&1"), 0)
      << "node is missing: scripts/install-deps.sh installs it";

  const LoadedSurface quad = readSurfaceFile(writeText("quad.glb", QuadModel().glb()));
  SurfaceMesh deformed = quad.surface();
  deformed.positions.col(0).array() *= 1.5;
  writeSurfaceFile(file("quad_out.glb"), quad, deformed);
  writeSurfaceFile(file("quad_out.gltf"), quad, deformed);
  const LoadedSurface cube = readSurfaceFile(
      writeText("cube.obj",
                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 -1\nvn 0 0 1\n"
                "f 1/1/1 4/4/1 3/3/1 2/2/1\nf 5/1/2 6/2/2 7/3/2 8/4/2\nf 1/1 2/2 6/3 5/4\n"));
  writeSurfaceFile(file("cube.glb"), cube, cube.surface());
  for (const char* name : {"quad_out.glb", "quad_out.gltf", "cube.glb"}) {
    const auto report = file(std::string(name) + ".report");
    const std::string command = "node '" + script.string() + "' '" + file(name).string() + "' > '" +
                                report.string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << name << ":\n" << readFile(report);
  }
}

// ---------------------------------------------------------------------------------------------
// Rejections
// ---------------------------------------------------------------------------------------------

TEST_F(SurfaceIoTest, RejectsTruncatedGlb) {
  const std::string glb = QuadModel().glb();
  for (const size_t size : {size_t{0}, size_t{10}, size_t{30}, glb.size() - 4, glb.size() / 2}) {
    SCOPED_TRACE(size);
    const auto path = writeText("cut.glb", glb.substr(0, size));
    if (size < 4) {
      expectFileError([&] { readSurfaceFile(path); }, {"cut.glb: not valid glTF"});
    } else {
      expectFileError([&] { readSurfaceFile(path); }, {"cut.glb: truncated"});
    }
  }
  // The BIN chunk claiming more bytes than the file has (tinygltf alone reads past the end).
  std::string longer = glb;
  uint32_t jsonLength = 0, binLength = 0;
  std::memcpy(&jsonLength, glb.data() + 12, 4);
  std::memcpy(&binLength, glb.data() + 20 + jsonLength, 4);
  const uint32_t tooLong = binLength + 4;
  std::memcpy(longer.data() + 20 + jsonLength, &tooLong, 4);
  expectFileError([&] { readSurfaceFile(writeText("long.glb", longer)); },
                  {"long.glb: truncated .glb: the BIN chunk"});
}

TEST_F(SurfaceIoTest, RejectsAccessorsOutsideTheirBufferView) {
  QuadModel quad;
  quad.document["accessors"][0]["count"] = 5;  // 5 * 12 bytes > 48
  expectFileError([&] { readSurfaceFile(writeText("a.glb", quad.glb())); },
                  {"a.glb: accessor 0 (POSITION of mesh 0 primitive 0)", "count 5 with stride 12",
                   "needs 60 bytes, buffer view 0 has 48"});
  quad = QuadModel();
  quad.document["bufferViews"][1]["byteStride"] = 16;  // 3 * 16 + 12 > 48
  expectFileError([&] { readSurfaceFile(writeText("b.glb", quad.glb())); },
                  {"accessor 1 (NORMAL of mesh 0 primitive 0)", "needs 60 bytes"});
  quad = QuadModel();
  quad.document["accessors"][0]["byteOffset"] = 4000000000u;
  expectFileError([&] { readSurfaceFile(writeText("c.glb", quad.glb())); },
                  {"accessor 0", "needs"});
  quad = QuadModel();
  quad.document["accessors"][0]["count"] = 9223372036854775807u;  // saturates, never wraps
  expectFileError([&] { readSurfaceFile(writeText("d.glb", quad.glb())); },
                  {"accessor 0", "needs"});
  quad = QuadModel();
  quad.document["bufferViews"][2]["byteLength"] = 5000;
  expectFileError([&] { readSurfaceFile(writeText("e.glb", quad.glb())); },
                  {"buffer view 2", "exceed buffer 0"});
}

TEST_F(SurfaceIoTest, RejectsIndicesBeyondTheVertexCount) {
  QuadModel quad;
  BinaryBuffer& bin = quad.bin;
  const size_t indices = bin.add<uint16_t>({0, 1, 2, 0, 2, 7});
  quad.document["bufferViews"][3]["byteOffset"] = indices;
  expectFileError([&] { readSurfaceFile(writeText("i.glb", quad.glb())); },
                  {"i.glb: accessor 3 (indices of mesh 0 primitive 0)", "index 7 at element 5",
                   "vertex count 4"});
}

TEST_F(SurfaceIoTest, RejectsWhatCannotBeWrittenBack) {
  QuadModel quad;
  quad.document["nodes"][0]["mesh"] = 0;  // mesh 0 now instanced by nodes 0 and 1
  expectFileError([&] { readSurfaceFile(writeText("twice.glb", quad.glb())); },
                  {"twice.glb: mesh 0: instanced by nodes 0 and 1"});

  quad = QuadModel();
  quad.document["accessors"][0]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", 3}, {"componentType", 5123}}},
      {"values", {{"bufferView", 0}}}};
  expectFileError([&] { readSurfaceFile(writeText("sparse.glb", quad.glb())); },
                  {"accessor 0 (POSITION", "sparse accessors are not supported"});

  quad = QuadModel();
  quad.document["meshes"][0]["primitives"].push_back(
      {{"attributes", {{"POSITION", 0}}}, {"indices", 3}});  // POSITION 0 without NORMAL
  expectFileError([&] { readSurfaceFile(writeText("shared.glb", quad.glb())); },
                  {"accessor 0: shared by mesh 0 primitive 0 and mesh 0 primitive 1"});

  quad = QuadModel();
  quad.document["nodes"][1]["scale"] = {0, 1, 1};
  expectFileError([&] { readSurfaceFile(writeText("flat.glb", quad.glb())); },
                  {"node 1: world matrix is singular"});

  quad = QuadModel();
  quad.document["nodes"][1]["children"] = {0};  // a cycle
  expectFileError([&] { readSurfaceFile(writeText("cycle.glb", quad.glb())); },
                  {"node 0: reached twice"});

  quad = QuadModel();
  quad.document["accessors"][0]["componentType"] = 5123;
  expectFileError([&] { readSurfaceFile(writeText("quantized.glb", quad.glb())); },
                  {"accessor 0 (POSITION", "component type 5123 is not supported"});

  quad = QuadModel();
  quad.document["meshes"][0]["primitives"][0]["mode"] = 1;
  expectFileError([&] { readSurfaceFile(writeText("lines.glb", quad.glb())); },
                  {"lines.glb: no triangle primitives"});

  quad = QuadModel();
  quad.document["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  expectFileError([&] { readSurfaceFile(writeText("draco.glb", quad.glb())); },
                  {"requires KHR_draco_mesh_compression"});

  const LoadedSurface loaded = readSurfaceFile(writeText("quad.glb", QuadModel().glb()));
  SurfaceMesh fewer = loaded.surface();
  fewer.positions.conservativeResize(3, 3);
  expectFileError([&] { writeSurfaceFile(file("out.glb"), loaded, fewer); },
                  {"out.glb: the deformed surface has 3 vertices"});
}

TEST_F(SurfaceIoTest, RejectsUnsupportedExtensionsAndInvalidJson) {
  expectFileError([&] { readSurfaceFile(writeText("model.stl", "solid x\n")); },
                  {"model.stl: unsupported surface file extension '.stl'"});
  expectFileError([&] { readSurfaceFile(file("model")); },
                  {"unsupported surface file extension ''"});
  const LoadedSurface loaded =
      readSurfaceFile(writeText("q.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  expectFileError([&] { writeSurfaceFile(file("q.ply"), loaded, loaded.surface()); },
                  {"q.ply: unsupported surface file extension '.ply'"});
  expectFileError([&] { readSurfaceFile(writeText("bad.gltf", "{\"asset\": ")); },
                  {"bad.gltf: not valid glTF"});
  expectFileError([&] { readSurfaceFile(file("missing.gltf")); }, {"missing.gltf: cannot open"});
  QuadModel quad;
  expectFileError(
      [&] { readSurfaceFile(writeText("ext.gltf", quad.gltfWithExternalBuffer("nothing.bin"))); },
      {"ext.gltf: buffer 0: ", "nothing.bin: cannot open (No such file or directory)"});
}

TEST_F(SurfaceIoTest, GltfReaderSurvivesRandomBytes) {
  const std::string glb = QuadModel().glb();
  std::mt19937 random(11);
  int accepted = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string bytes = glb;
    const int flips = 1 + static_cast<int>(random() % 4);
    for (int k = 0; k < flips; ++k)
      bytes[random() % bytes.size()] = static_cast<char>(random() % 256);
    const auto path = writeText("fuzz.glb", bytes);
    try {
      const SurfaceMesh s = readSurfaceFile(path).surface();
      for (const SurfaceCorner& c : s.faces.values) ASSERT_LT(c.position, s.numVertices());
      ++accepted;
    } catch (const FileError&) {
    }
  }
  EXPECT_GT(accepted, 0);  // flips in the float data leave valid files
}

TEST_F(SurfaceIoTest, GltfReaderSurvivesHostileNumbersInTheDocument) {
  // Every number of the JSON document (indices, counts, offsets, strides, modes, transforms)
  // replaced in turn by awkward values: each read either succeeds or throws FileError.
  const QuadModel quad;
  const nlohmann::json flat = quad.document.flatten();
  const std::vector<double> awkward = {-1,           0,    1,  3, 5, 7, 255, 65536, 4294967295.0,
                                       4294967297.0, 1e19, 0.5};
  int cases = 0;
  for (const auto& [pointer, value] : flat.items()) {
    if (!value.is_number()) continue;
    for (const double replacement : awkward) {
      nlohmann::json document = quad.document;
      if (replacement == std::floor(replacement) && replacement >= 0 && replacement < 1e19) {
        document[nlohmann::json::json_pointer(pointer)] = static_cast<uint64_t>(replacement);
      } else if (replacement == std::floor(replacement) && replacement < 0) {
        document[nlohmann::json::json_pointer(pointer)] = static_cast<int64_t>(replacement);
      } else {
        document[nlohmann::json::json_pointer(pointer)] = replacement;
      }
      QuadModel hostile = quad;
      hostile.document = document;
      try {
        const SurfaceMesh s = readSurfaceFile(writeText("hostile.glb", hostile.glb())).surface();
        for (const SurfaceCorner& c : s.faces.values) ASSERT_LT(c.position, s.numVertices());
      } catch (const FileError&) {
      }
      ++cases;
    }
  }
  EXPECT_GT(cases, 100);
}

}  // namespace
}  // namespace sculpt
