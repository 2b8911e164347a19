#include "anim/glb_animation_writer.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <system_error>

#include "anim/stream_file.h"
#include "io/file_error.h"

namespace sculpt {
namespace {

using Json = nlohmann::ordered_json;

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr uint32_t kJsonChunk = 0x4E4F534A;
constexpr uint32_t kBinChunk = 0x004E4942;


// What pass 1 learns about a segment and pass 2 writes.
struct SegmentPlan {
  GlbSegmentLayout layout;
  MorphKeys keys;
  std::vector<float> base;                        // rest positions as written
  std::vector<std::array<float, 3>> lows, highs;  // per key: the bounds of its position deltas
  std::vector<float> scaleTimes, scaleValues;
};

bool sharesTexcoordIndices(const SurfaceMesh& rest) {
  if (rest.texcoords.rows() == 0 || rest.texcoords.rows() != rest.positions.rows()) return false;
  return std::all_of(rest.faces.values.begin(), rest.faces.values.end(),
                     [](const SurfaceCorner& c) { return c.texcoord == c.position; });
}

std::string keyName(const std::string& name, size_t key) {
  char digits[24];  // any size_t
  std::snprintf(digits, sizeof digits, "%04zu", key + 1);
  return name + "_key_" + digits;
}

std::string frameMismatch(const std::filesystem::path& path, uint32_t frame, size_t values,
                          const char* what, uint64_t vertices) {
  return path.string() + ": frame " + std::to_string(frame) + " has " + std::to_string(values / 3) +
         " " + what + " for " + std::to_string(vertices) + " vertices";
}

// The visibility keys of segment `s` among several: scale 0 before and after its frames, 1
// during them, from time 0 to the take's last frame.
void planScale(const AnimatedSurface& take, uint32_t s, SegmentPlan& plan) {
  const FrameRange range = take.segment(s);
  const auto add = [&](double time, float scale) {
    const float t = static_cast<float>(time);
    if (!plan.scaleTimes.empty() && t <= plan.scaleTimes.back()) return;
    plan.scaleTimes.push_back(t);
    plan.scaleValues.insert(plan.scaleValues.end(), {scale, scale, scale});
  };
  if (range.first > 0) add(0.0, 0.0f);
  add(take.frameTime(range.first), 1.0f);
  const uint32_t end = range.first + range.count;
  if (end < take.frameCount()) add(take.frameTime(end), 0.0f);
  add(take.frameTime(take.frameCount() - 1), plan.scaleValues.back());
  plan.layout.scaleChannel = true;
  plan.layout.scaleKeys = plan.scaleTimes.size();
}

// The glTF document's accessors and buffer views, one view per accessor, laid out in the order
// that writeGlbAnimation() writes the binary chunk.
class Document {
 public:
  int view(uint64_t bytes, int target = 0) {
    Json v{{"buffer", 0}, {"byteOffset", offset_}, {"byteLength", bytes}};
    if (target != 0) v["target"] = target;
    offset_ += bytes;
    views_.push_back(std::move(v));
    return static_cast<int>(views_.size() - 1);
  }
  int accessor(uint64_t count, const char* type, int componentType, int target = 0,
               Json bounds = Json()) {
    const uint64_t components = type[0] == 'S' ? 1 : static_cast<uint64_t>(type[3] - '0');
    const int size = componentType == kFloat || componentType == kUnsignedInt ? 4 : 2;
    Json a{{"bufferView", view(count * components * static_cast<uint64_t>(size), target)},
           {"componentType", componentType},
           {"count", count},
           {"type", type}};
    if (!bounds.is_null()) {
      a["min"] = bounds[0];
      a["max"] = bounds[1];
    }
    accessors_.push_back(std::move(a));
    return static_cast<int>(accessors_.size() - 1);
  }
  uint64_t binaryBytes() const { return offset_; }
  Json accessors() const { return accessors_; }
  Json views() const { return views_; }

 private:
  uint64_t offset_ = 0;
  Json views_ = Json::array(), accessors_ = Json::array();
};

Json bounds3(const std::array<float, 3>& low, const std::array<float, 3>& high) {
  return Json::array(
      {Json::array({low[0], low[1], low[2]}), Json::array({high[0], high[1], high[2]})});
}

Json boundsOf(const std::vector<float>& values) {
  std::array<float, 3> low{}, high{};
  low.fill(std::numeric_limits<float>::max());
  high.fill(std::numeric_limits<float>::lowest());
  for (size_t i = 0; i < values.size(); ++i) {
    low[i % 3] = std::min(low[i % 3], values[i]);
    high[i % 3] = std::max(high[i % 3], values[i]);
  }
  return bounds3(low, high);
}

std::string buildJson(const AnimatedSurface& take, const std::vector<SegmentPlan>& plans,
                      const GlbAnimationOptions& options, uint64_t binaryBytes) {
  Document doc;
  Json meshes = Json::array(), nodes = Json::array(), samplers = Json::array(),
       channels = Json::array(), sceneNodes = Json::array();
  const bool several = plans.size() > 1;
  for (size_t s = 0; s < plans.size(); ++s) {
    const SegmentPlan& plan = plans[s];
    const GlbSegmentLayout& layout = plan.layout;
    const std::string label =
        several ? options.name + "_segment_" + std::to_string(s + 1) : options.name;
    Json attributes{{"POSITION", doc.accessor(layout.vertices, "VEC3", kFloat, kArrayBuffer,
                                              boundsOf(plan.base))}};
    if (layout.normals) {
      attributes["NORMAL"] = doc.accessor(layout.vertices, "VEC3", kFloat, kArrayBuffer);
    }
    if (layout.texcoords) {
      attributes["TEXCOORD_0"] = doc.accessor(layout.vertices, "VEC2", kFloat, kArrayBuffer);
    }
    Json primitive{{"attributes", attributes},
                   {"indices", doc.accessor(3 * layout.triangles, "SCALAR", kUnsignedInt,
                                            kElementArrayBuffer)}};
    Json targets = Json::array(), names = Json::array();
    for (size_t k = 0; k < layout.keys; ++k) {
      Json target{{"POSITION", doc.accessor(layout.vertices, "VEC3", kFloat, kArrayBuffer,
                                            bounds3(plan.lows[k], plan.highs[k]))}};
      if (layout.normals) {
        target["NORMAL"] = doc.accessor(layout.vertices, "VEC3", kFloat, kArrayBuffer);
      }
      targets.push_back(std::move(target));
      names.push_back(keyName(options.name, k));
    }
    primitive["targets"] = std::move(targets);
    meshes.push_back(Json{{"name", label},
                          {"primitives", Json::array({std::move(primitive)})},
                          {"weights", std::vector<float>(layout.keys, 0.0f)},
                          {"extras", {{"targetNames", std::move(names)}}}});

    Json node{{"name", label}, {"mesh", s}};
    if (take.segment(static_cast<uint32_t>(s)).first > 0) node["scale"] = {0.0, 0.0, 0.0};
    nodes.push_back(std::move(node));
    sceneNodes.push_back(s);

    const float firstTime = static_cast<float>(take.frameTime(plan.keys.frames.front()));
    const float lastTime = static_cast<float>(take.frameTime(plan.keys.frames.back()));
    const int times =
        doc.accessor(layout.keys, "SCALAR", kFloat, 0, Json::array({{firstTime}, {lastTime}}));
    const int weights = doc.accessor(layout.keys * layout.keys, "SCALAR", kFloat);
    samplers.push_back({{"input", times}, {"interpolation", "LINEAR"}, {"output", weights}});
    channels.push_back(
        {{"sampler", samplers.size() - 1}, {"target", {{"node", s}, {"path", "weights"}}}});
    if (layout.scaleChannel) {
      const int input =
          doc.accessor(layout.scaleKeys, "SCALAR", kFloat, 0,
                       Json::array({{plan.scaleTimes.front()}, {plan.scaleTimes.back()}}));
      const int output = doc.accessor(layout.scaleKeys, "VEC3", kFloat);
      samplers.push_back({{"input", input}, {"interpolation", "STEP"}, {"output", output}});
      channels.push_back(
          {{"sampler", samplers.size() - 1}, {"target", {{"node", s}, {"path", "scale"}}}});
    }
  }
  const Json document{
      {"asset", {{"generator", "sculpt record"}, {"version", "2.0"}}},
      {"scene", 0},
      {"scenes", Json::array({{{"name", options.name}, {"nodes", sceneNodes}}})},
      {"nodes", nodes},
      {"meshes", meshes},
      {"animations",
       Json::array({{{"name", options.name}, {"channels", channels}, {"samplers", samplers}}})},
      {"accessors", doc.accessors()},
      {"bufferViews", doc.views()},
      {"buffers", Json::array({{{"byteLength", doc.binaryBytes()}}})}};
  if (doc.binaryBytes() != binaryBytes) {
    throw std::logic_error("writeGlbAnimation: the document's layout disagrees with its size");
  }
  return document.dump();
}

}  // namespace

uint64_t glbBinaryBytes(const std::vector<GlbSegmentLayout>& segments) {
  uint64_t bytes = 0;
  for (const GlbSegmentLayout& s : segments) {
    const uint64_t perVertex = 12 + (s.normals ? 12 : 0) + (s.texcoords ? 8 : 0);
    const uint64_t perKey = s.vertices * (12 + (s.normals ? 12 : 0));
    bytes += s.vertices * perVertex + 12 * s.triangles + s.keys * perKey;
    bytes += 4 * s.keys + 4 * s.keys * s.keys;  // key times, one-hot weights
    if (s.scaleChannel) bytes += 16 * s.scaleKeys;
  }
  return bytes;
}

void checkGlbSize(const std::filesystem::path& path, uint64_t totalBytes,
                  const std::vector<GlbSegmentLayout>& segments) {
  if (totalBytes <= kGlbMaxBytes) return;
  uint64_t keys = 0, vertices = 0;
  for (const GlbSegmentLayout& s : segments) {
    keys += s.keys;
    vertices = std::max(vertices, s.vertices);
  }
  char gib[32];
  std::snprintf(gib, sizeof gib, "%.1f", static_cast<double>(totalBytes) / double(1ull << 30));
  throw FileError(path.string() + ": " + std::to_string(keys) + " keys of " +
                  std::to_string(vertices) + " vertices need " + gib +
                  " GiB, over glTF binary's 4 GiB limit; raise --key-tolerance or record fewer "
                  "frames");
}

ExportResult writeGlbAnimation(const AnimatedSurface& take, const std::filesystem::path& path,
                               const GlbAnimationOptions& options, ProgressReporter* progress,
                               std::vector<MorphKeys>* keysOut) {
  ExportResult result;
  const uint32_t frames = take.frameCount();
  if (frames == 0 || take.segmentCount() == 0)
    throw FileError(path.string() + ": the take has no frames");
  if (options.maxKeySpan < 1)
    throw FileError(path.string() + ": the key span must be at least 1 frame");
  ProgressReporter silent;
  ProgressReporter& reporter = progress ? *progress : silent;

  // Pass 1: choose the keys, evaluating every frame once.
  std::vector<SegmentPlan> plans(take.segmentCount());
  for (uint32_t s = 0; s < take.segmentCount(); ++s) {
    SegmentPlan& plan = plans[s];
    const SurfaceMesh& rest = take.restSurface(s);
    GlbSegmentLayout& layout = plan.layout;
    layout.vertices = rest.numVertices();
    layout.triangles = take.triangles(s).size() / 3;
    layout.normals = take.restVertexNormals(s).size() == 3 * layout.vertices;
    layout.texcoords = sharesTexcoordIndices(rest);
    plan.base.resize(3 * layout.vertices);
    for (size_t i = 0; i < plan.base.size(); ++i) {
      plan.base[i] = static_cast<float>(
          rest.positions(static_cast<Eigen::Index>(i / 3), static_cast<Eigen::Index>(i % 3)));
    }
    MorphKeyOptions keyOptions;
    keyOptions.tolerance = morphKeyTolerance(rest, options.keyTolerance);
    keyOptions.maxSpan = options.maxKeySpan;
    const auto onFrame = [&](uint32_t frame) {
      return reporter.report(0.5 * (frame + 1) / frames, "choosing key frames");
    };
    const auto onKey = [&](uint32_t frame, const SurfaceFrameData& surface) {
      if (surface.positions.size() != plan.base.size()) {
        throw FileError(
            frameMismatch(path, frame, surface.positions.size(), "positions", layout.vertices));
      }
      std::array<float, 3> low{}, high{};
      low.fill(std::numeric_limits<float>::max());
      high.fill(std::numeric_limits<float>::lowest());
      for (size_t i = 0; i < plan.base.size(); ++i) {
        const float d = surface.positions[i] - plan.base[i];
        low[i % 3] = std::min(low[i % 3], d);
        high[i % 3] = std::max(high[i % 3], d);
      }
      plan.lows.push_back(low);
      plan.highs.push_back(high);
    };
    plan.keys = chooseMorphKeys(take, s, keyOptions, onFrame, onKey);
    if (reporter.cancelled()) {
      result.cancelled = true;
      return result;
    }
    layout.keys = plan.keys.frames.size();
    if (take.segmentCount() > 1) planScale(take, s, plan);
  }
  std::vector<GlbSegmentLayout> layouts;
  uint64_t totalKeys = 0;
  for (const SegmentPlan& plan : plans) {
    layouts.push_back(plan.layout);
    totalKeys += plan.layout.keys;
  }
  const uint64_t binBytes = glbBinaryBytes(layouts);
  checkGlbSize(path, 28 + binBytes, layouts);  // before building a JSON text that large
  std::string json = buildJson(take, plans, options, binBytes);
  json.append((4 - json.size() % 4) % 4, ' ');
  const uint64_t total = 28 + json.size() + binBytes;
  checkGlbSize(path, total, layouts);

  // Pass 2: write, evaluating the key frames again for their deltas.
  StreamFile file(path);
  const auto word = [&](uint64_t value) {
    const uint32_t v = static_cast<uint32_t>(value);
    file.write(&v, 4);
  };
  file.write("glTF", 4);
  word(2);
  word(total);
  word(json.size());
  word(kJsonChunk);
  file.write(json.data(), json.size());
  word(binBytes);
  word(kBinChunk);

  SurfaceFrameData surface;
  std::vector<float> delta, weights;
  uint64_t written = 0;
  for (uint32_t s = 0; s < take.segmentCount(); ++s) {
    const SegmentPlan& plan = plans[s];
    const GlbSegmentLayout& layout = plan.layout;
    const std::vector<float>& restNormals = take.restVertexNormals(s);
    file.write(plan.base);
    if (layout.normals) file.write(restNormals);
    if (layout.texcoords) {
      const TexCoords& uv = take.restSurface(s).texcoords;
      std::vector<float> texcoords(2 * layout.vertices);
      for (Eigen::Index v = 0; v < uv.rows(); ++v) {
        texcoords[2 * size_t(v)] = static_cast<float>(uv(v, 0));
        texcoords[2 * size_t(v) + 1] = static_cast<float>(1.0 - uv(v, 1));  // glTF v grows down
      }
      file.write(texcoords);
    }
    file.write(take.triangles(s).data(), 12 * layout.triangles);
    for (size_t k = 0; k < layout.keys; ++k) {
      const uint32_t frame = plan.keys.frames[k];
      take.evaluateSurface(frame, surface);
      if (surface.positions.size() != plan.base.size()) {
        throw FileError(
            frameMismatch(path, frame, surface.positions.size(), "positions", layout.vertices));
      }
      delta.resize(plan.base.size());
      for (size_t i = 0; i < delta.size(); ++i) delta[i] = surface.positions[i] - plan.base[i];
      // The bounds in the JSON came from the first evaluation; they must describe these values.
      const Json expected = bounds3(plan.lows[k], plan.highs[k]);
      if (boundsOf(delta) != expected) {
        throw FileError(path.string() + ": frame " + std::to_string(frame) +
                        " evaluated differently the second time");
      }
      file.write(delta);
      if (layout.normals) {
        if (surface.normals.size() != restNormals.size()) {
          throw FileError(
              frameMismatch(path, frame, surface.normals.size(), "normals", layout.vertices));
        }
        for (size_t i = 0; i < delta.size(); ++i) delta[i] = surface.normals[i] - restNormals[i];
        file.write(delta);
      }
      ++written;
      if (!reporter.report(0.5 + 0.5 * double(written) / double(totalKeys), "writing key frames")) {
        result.cancelled = true;
        return result;
      }
    }
    std::vector<float> times;
    for (const uint32_t frame : plan.keys.frames)
      times.push_back(static_cast<float>(take.frameTime(frame)));
    file.write(times);
    weights.assign(layout.keys, 0.0f);
    for (size_t k = 0; k < layout.keys; ++k) {
      weights[k] = 1.0f;
      file.write(weights);
      weights[k] = 0.0f;
    }
    if (layout.scaleChannel) {
      file.write(plan.scaleTimes);
      file.write(plan.scaleValues);
    }
  }
  if (file.written() != total) {
    throw std::logic_error("writeGlbAnimation: wrote " + std::to_string(file.written()) +
                           " bytes, not the " + std::to_string(total) + " the header declares");
  }
  file.commit();

  result.files.push_back(path);
  result.bytes = total;
  result.frames = frames;
  result.keys = static_cast<uint32_t>(totalKeys);
  if (keysOut) {
    keysOut->clear();
    for (SegmentPlan& plan : plans) keysOut->push_back(std::move(plan.keys));
  }
  return result;
}

}  // namespace sculpt
