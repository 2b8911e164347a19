#include "tools/session_script.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>

#include "io/file_error.h"
#include "io/input_file.h"
#include "io/json_nesting.h"
#include "sim/material_point.h"
#include "tools/pin_tool.h"

namespace sculpt {

using nlohmann::json;

namespace {

std::string number(double v) {
  std::ostringstream out;
  out.precision(9);
  out << v;
  return out.str();
}

// Reads the fields of one JSON object, throwing FileError with the context and field name.
class Reader {
 public:
  Reader(const json& object, std::string context) : object_(object), context_(std::move(context)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw FileError(context_ + ": '" + field + "' " + what + ".");
  }
  [[noreturn]] void failContext(const std::string& what) const {
    throw FileError(context_ + ": " + what + ".");
  }

  bool has(const std::string& field) const { return object_.contains(field); }

  // Rejects fields outside `known` (typos would otherwise be silently ignored).
  void onlyFields(const std::set<std::string>& known) const {
    for (const auto& item : object_.items())
      if (!known.count(item.key())) failContext("unknown field '" + item.key() + "'");
  }

  double numberField(const std::string& field, double lo = -std::numeric_limits<double>::max(),
                     bool loOpen = false, const char* range = "a finite number") const {
    if (!has(field)) fail(field, "is missing (" + std::string(range) + ")");
    return checkNumber(object_.at(field), field, lo, loOpen, range);
  }
  double numberOr(const std::string& field, double fallback, double lo, bool loOpen,
                  const char* range) const {
    return has(field) ? checkNumber(object_.at(field), field, lo, loOpen, range) : fallback;
  }
  bool boolOr(const std::string& field, bool fallback) const {
    if (!has(field)) return fallback;
    if (!object_.at(field).is_boolean()) fail(field, "must be true or false");
    return object_.at(field).get<bool>();
  }
  std::string stringOr(const std::string& field, const std::string& fallback) const {
    if (!has(field)) return fallback;
    if (!object_.at(field).is_string()) fail(field, "must be a string");
    return object_.at(field).get<std::string>();
  }
  Eigen::Vector3d vector(const std::string& field) const {
    if (!has(field)) fail(field, "is missing (an array of 3 finite numbers)");
    return vectorOf(object_.at(field), field);
  }
  Eigen::Vector3d vectorOf(const json& value, const std::string& field) const {
    if (!value.is_array() || value.size() != 3) fail(field, "must be an array of 3 finite numbers");
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) {
      const json& c = value[size_t(i)];
      if (!c.is_number() || !std::isfinite(c.get<double>()))
        fail(field, "must be an array of 3 finite numbers");
      v[i] = c.get<double>();
    }
    return v;
  }
  const json& at(const std::string& field) const { return object_.at(field); }

 private:
  double checkNumber(const json& value, const std::string& field, double lo, bool loOpen,
                     const char* range) const {
    if (!value.is_number())
      fail(field, "must be " + std::string(range) + " (got " + value.dump() + ")");
    const double v = value.get<double>();
    if (!std::isfinite(v) || v < lo || (loOpen && v == lo))
      fail(field, "must be " + std::string(range) + " (got " + number(v) + ")");
    return v;
  }

  const json& object_;
  std::string context_;
};

constexpr double kInf = std::numeric_limits<double>::infinity();

// The "path" field: a non-empty array of keys `shape` ("[t, x, y, z]"), times non-decreasing.
std::vector<PathKey> parsePath(const Reader& r, const std::string& shape) {
  if (!r.has("path")) r.fail("path", "is missing (a non-empty array of " + shape + ")");
  const json& path = r.at("path");
  if (!path.is_array() || path.empty()) r.fail("path", "must be a non-empty array of " + shape);
  std::vector<PathKey> keys;
  for (size_t k = 0; k < path.size(); ++k) {
    const std::string field = "path[" + std::to_string(k) + "]";
    const json& key = path[k];
    if (!key.is_array() || key.size() != 4) r.fail(field, "must be an array " + shape);
    for (const json& c : key)
      if (!c.is_number() || !std::isfinite(c.get<double>()))
        r.fail(field, "must hold 4 finite numbers");
    const double t = key[0].get<double>();
    if (t < 0) r.fail(field, "must have a time >= 0 (got " + number(t) + ")");
    if (!keys.empty() && t < keys.back().time)
      r.fail(field, "must not go back in time (times must be non-decreasing)");
    keys.push_back({t, {key[1].get<double>(), key[2].get<double>(), key[3].get<double>()}});
  }
  return keys;
}

// The fields a grab and a curve share: stiffness, release and keep.
template <typename Drag>
void parseDragRelease(const Reader& r, Drag& drag) {
  drag.stiffness = r.numberOr("stiffness", 0.0, 0.0, true, "a finite number > 0 (N/m)");
  if (r.has("release")) drag.release = r.numberField("release", 0.0, false, "a finite number >= 0");
  drag.keep = r.boolOr("keep", false);
}

GrabEvent parseGrab(const Reader& r) {
  r.onlyFields({"t", "type", "point", "path", "stiffness", "release", "keep", "push"});
  GrabEvent grab;
  grab.point = r.vector("point");
  grab.path = parsePath(r, "[t, x, y, z]");
  parseDragRelease(r, grab);
  grab.push = r.boolOr("push", false);
  return grab;
}

CurveEvent parseCurve(const Reader& r) {
  r.onlyFields(
      {"t", "type", "points", "path", "profile", "stiffness", "samples", "release", "keep"});
  CurveEvent curve;
  if (!r.has("points")) r.fail("points", "is missing (a non-empty array of [x, y, z])");
  const json& points = r.at("points");
  if (!points.is_array() || points.empty())
    r.fail("points", "must be a non-empty array of [x, y, z]");
  for (size_t k = 0; k < points.size(); ++k)
    curve.points.push_back(r.vectorOf(points[k], "points[" + std::to_string(k) + "]"));
  curve.path = parsePath(r, "[t, dx, dy, dz]");
  const std::string profile = r.stringOr("profile", "rigid");
  const std::optional<CurveProfile> parsed = parseCurveProfile(profile);
  if (!parsed) r.fail("profile", "must be rigid or smooth (got \"" + profile + "\")");
  curve.profile = *parsed;
  if (r.has("samples")) {
    const json& samples = r.at("samples");
    if (!samples.is_number_integer() || samples.get<long long>() < 1 ||
        samples.get<long long>() > static_cast<long long>(kMaxCurveSamples))
      r.fail("samples", "must be an integer from 1 to " + std::to_string(kMaxCurveSamples) +
                            " (got " + samples.dump() + ")");
    curve.samples = samples.get<size_t>();
  }
  parseDragRelease(r, curve);
  return curve;
}

InflateEvent parseInflate(const Reader& r) {
  r.onlyFields({"t", "type", "centre", "radius", "pressure", "duration"});
  InflateEvent inflate;
  inflate.radius = r.numberOr("radius", kInf, 0.0, true, "a finite number > 0 (m)");
  if (r.has("centre") || std::isfinite(inflate.radius)) inflate.centre = r.vector("centre");
  inflate.pressure = r.numberField("pressure", -std::numeric_limits<double>::max(), false,
                                   "a finite number (Pa)");
  inflate.duration = r.numberField("duration", 0.0, false, "a finite number >= 0");
  return inflate;
}

PaintEvent parsePaint(const Reader& r) {
  r.onlyFields({"t", "type", "centre", "radius", "youngs", "density", "damping", "poisson",
                "falloff", "strength", "mirror", "mirrorCentre"});
  PaintEvent paint;
  paint.centre = r.vector("centre");
  MaterialBrushSettings& brush = paint.brush;
  brush.radius = r.numberField("radius", 0.0, true, "a finite number > 0 (m)");
  brush.fields = {r.has("density"), r.has("damping"), r.has("youngs"), r.has("poisson")};
  if (!r.has("density") && !r.has("damping") && !r.has("youngs") && !r.has("poisson"))
    r.failContext("a paint needs at least one of 'youngs', 'density', 'damping', 'poisson'");
  brush.target.youngs =
      r.numberOr("youngs", brush.target.youngs, 0.0, true, "a finite number > 0 (Pa)");
  brush.target.density =
      r.numberOr("density", brush.target.density, 0.0, true, "a finite number > 0 (kg/m^3)");
  brush.target.damping =
      r.numberOr("damping", brush.target.damping, 0.0, false, "a finite number >= 0");
  brush.target.poisson = r.numberOr("poisson", brush.target.poisson, -1.0, true,
                                    "a finite number in (-1, 0.5)");
  if (brush.target.poisson >= 0.5)
    r.fail("poisson",
           "must be a finite number in (-1, 0.5) (got " + number(brush.target.poisson) + ")");
  const std::string falloff = r.stringOr("falloff", "smooth");
  const std::optional<Falloff> parsed = parseFalloff(falloff);
  if (!parsed)
    r.fail("falloff",
           "must be one of smooth, sphere, linear, sharp, constant (got \"" + falloff + "\")");
  brush.falloff = *parsed;
  brush.strength = r.numberOr("strength", 1.0, 0.0, false, "a finite number in [0, 1]");
  if (brush.strength > 1)
    r.fail("strength", "must be a finite number in [0, 1] (got " + number(brush.strength) + ")");
  const std::string mirror = r.stringOr("mirror", "x");
  brush.mirror.x = brush.mirror.y = brush.mirror.z = false;
  if (mirror != "none") {
    for (char c : mirror) {
      bool* axis = c == 'x'   ? &brush.mirror.x
                   : c == 'y' ? &brush.mirror.y
                   : c == 'z' ? &brush.mirror.z
                              : nullptr;
      if (!axis || *axis)
        r.fail("mirror",
               "must be \"none\" or distinct letters from \"xyz\" (got \"" + mirror + "\")");
      *axis = true;
    }
  }
  if (r.has("mirrorCentre")) paint.mirrorCentre = r.vector("mirrorCentre");
  return paint;
}

PinEvent parsePin(const Reader& r) {
  r.onlyFields({"t", "type", "box", "centre", "radius", "unpin"});
  PinEvent pin;
  if (r.has("box")) {
    if (r.has("centre") || r.has("radius"))
      r.failContext("give either 'box' or 'centre' and 'radius'");
    const json& box = r.at("box");
    if (!box.is_array() || box.size() != 2)
      r.fail("box", "must be [[xmin, ymin, zmin], [xmax, ymax, zmax]]");
    const Eigen::Vector3d lo = r.vectorOf(box[0], "box"), hi = r.vectorOf(box[1], "box");
    if ((lo.array() > hi.array()).any()) r.fail("box", "must have min <= max on every axis");
    pin.box = Eigen::AlignedBox3d(lo, hi);
  } else {
    if (!r.has("centre") && !r.has("radius"))
      r.failContext("a pin needs 'box' or 'centre' and 'radius'");
    pin.centre = r.vector("centre");
    pin.radius = r.numberField("radius", 0.0, false, "a finite number >= 0 (m)");
  }
  pin.unpin = r.boolOr("unpin", false);
  return pin;
}

// `field` as a non-empty array of `width`-tuples of indices (width 1: plain indices), each an
// integer in [0, 2^32); `shape` describes one entry for messages ("[cell, face]", "cell index").
std::vector<std::vector<uint32_t>> indexTuples(const Reader& r, const std::string& field,
                                               size_t width, const std::string& shape) {
  const std::string entries = width == 1 ? shape + "es" : shape + " entries";
  if (!r.has(field)) r.fail(field, "is missing (a non-empty array of " + entries + ")");
  const json& list = r.at(field);
  if (!list.is_array() || list.empty()) r.fail(field, "must be a non-empty array of " + entries);
  std::vector<std::vector<uint32_t>> tuples;
  for (size_t k = 0; k < list.size(); ++k) {
    const json entry = width == 1 ? json::array({list[k]}) : list[k];
    if (!entry.is_array() || entry.size() != width)
      r.fail(field + "[" + std::to_string(k) + "]", "must be " + shape);
    std::vector<uint32_t> tuple;
    for (const json& index : entry) {
      if (!index.is_number_integer() || index.get<long long>() < 0 ||
          index.get<long long>() > static_cast<long long>(UINT32_MAX))
        r.fail(field + "[" + std::to_string(k) + "]",
               width == 1 ? "must be a " + shape + ": an integer >= 0"
                          : "must be " + shape + " with integers >= 0");
      tuple.push_back(static_cast<uint32_t>(index.get<long long>()));
    }
    tuples.push_back(std::move(tuple));
  }
  return tuples;
}

TopologyEvent parseTopology(const Reader& r) {
  static const std::string kOps = "delete, extrude, bridge, weld, subdivide, crease, corner";
  if (!r.has("op")) r.fail("op", "is missing (one of " + kOps + ")");
  const std::string name = r.stringOr("op", "");
  const std::optional<TopologyOp> op = parseTopologyOp(name);
  if (!op)
    r.fail("op", "must be one of " + kOps + " (got \"" + name + "\")");
  TopologyEvent topology;
  topology.op = *op;
  const auto faceList = [&] {
    for (const auto& f : indexTuples(r, "faces", 2, "[cell, face]"))
      topology.faces.push_back({f[0], f[1]});
  };
  switch (*op) {
    case TopologyOp::Delete:
    case TopologyOp::Subdivide:
      r.onlyFields({"t", "type", "op", "cells"});
      for (const auto& c : indexTuples(r, "cells", 1, "cell index")) topology.cells.push_back(c[0]);
      break;
    case TopologyOp::Extrude:
      r.onlyFields({"t", "type", "op", "faces", "distance"});
      faceList();
      topology.distanceM = r.numberField("distance", 0.0, true, "a finite number > 0 (m)");
      break;
    case TopologyOp::Bridge:
    case TopologyOp::Weld:
      if (*op == TopologyOp::Bridge) r.onlyFields({"t", "type", "op", "faces"});
      else r.onlyFields({"t", "type", "op", "faces", "tolerance"});
      faceList();
      if (topology.faces.size() != 2) r.fail("faces", "must hold exactly 2 faces [cell, face]");
      topology.toleranceM = r.numberOr("tolerance", topology.toleranceM, 0.0, false,
                                       "a finite number >= 0 (m)");
      break;
    case TopologyOp::Crease:
      r.onlyFields({"t", "type", "op", "edges", "untag"});
      for (const auto& e : indexTuples(r, "edges", 2, "[vertex, vertex]"))
        topology.edges.push_back({e[0], e[1]});
      topology.untag = r.boolOr("untag", false);
      break;
    case TopologyOp::Corner:
      r.onlyFields({"t", "type", "op", "vertices", "untag"});
      for (const auto& v : indexTuples(r, "vertices", 1, "vertex index"))
        topology.vertices.push_back(v[0]);
      topology.untag = r.boolOr("untag", false);
      break;
  }
  return topology;
}

}  // namespace

Eigen::Vector3d GrabEvent::targetAt(double time) const { return pathAt(path, time, point); }

Eigen::Vector3d pathAt(const std::vector<PathKey>& path, double time,
                       const Eigen::Vector3d& empty) {
  if (path.empty()) return empty;
  if (time <= path.front().time) return path.front().target;
  for (size_t k = 1; k < path.size(); ++k) {
    if (time > path[k].time) continue;
    const double span = path[k].time - path[k - 1].time;
    if (span <= 0) return path[k].target;
    const double s = (time - path[k - 1].time) / span;
    return path[k - 1].target + s * (path[k].target - path[k - 1].target);
  }
  return path.back().target;
}

const char* ScriptEvent::typeName() const {
  static const char* const kNames[] = {"grab", "inflate", "paint", "pin", "curve", "topology"};
  return kNames[action.index()];
}

double ScriptEvent::endTime() const {
  if (const auto* grab = std::get_if<GrabEvent>(&action))
    return time + (grab->release ? *grab->release : grab->path.back().time);
  if (const auto* curve = std::get_if<CurveEvent>(&action))
    return time + (curve->release ? *curve->release : curve->path.back().time);
  if (const auto* inflate = std::get_if<InflateEvent>(&action)) return time + inflate->duration;
  return time;
}

double SessionScript::duration() const {
  const ScriptEvent* last = lastEvent();
  return last ? std::max(0.0, last->endTime()) : 0.0;
}

const ScriptEvent* SessionScript::lastEvent() const {
  const ScriptEvent* last = nullptr;
  for (const ScriptEvent& e : events)
    if (!last || e.endTime() > last->endTime()) last = &e;
  return last;
}

SessionScript parseSessionScript(std::string_view text, std::string_view sourceName) {
  const std::string source(sourceName);
  // Scripts are shallow; a hostile file must not make the parser recurse deep.
  constexpr int kMaxNesting = 16;
  if (const size_t at = excessiveJsonNesting(text, kMaxNesting); at != std::string_view::npos)
    throw FileError(source + ": not valid JSON (nested deeper than " + std::to_string(kMaxNesting) +
                    " levels at byte " + std::to_string(at) + ").");
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    throw FileError(source + ": not valid JSON (error at byte " + std::to_string(e.byte) +
                    "; truncated or malformed).");
  } catch (const json::exception&) {  // out_of_range: a number beyond double's range
    throw FileError(source + ": not valid JSON (a number is out of range, not finite).");
  }
  if (!root.is_object()) throw FileError(source + ": the top level must be a JSON object.");
  const Reader top(root, source);
  top.onlyFields({"format", "version", "events", "description"});
  if (top.stringOr("format", "") != "sculpt-session")
    top.fail("format", "must be \"sculpt-session\"");
  if (!top.has("version") || !root.at("version").is_number_integer())
    top.fail("version", "must be the integer 1");
  if (root.at("version").get<long long>() != 1)
    top.fail("version", "is " + root.at("version").dump() + "; this program reads version 1");
  if (!top.has("events") || !root.at("events").is_array()) top.fail("events", "must be an array");

  SessionScript script;
  const json& events = root.at("events");
  for (size_t i = 0; i < events.size(); ++i) {
    const std::string context = source + ": events[" + std::to_string(i) + "]";
    if (!events[i].is_object()) throw FileError(context + ": must be a JSON object.");
    const Reader bare(events[i], context);
    const std::string type = bare.stringOr("type", "");
    if (type.empty())
      bare.fail("type", "must be one of grab, inflate, paint, pin, curve, topology");
    const Reader r(events[i], context + " (" + type + ")");
    ScriptEvent event;
    event.index = i;
    event.time = r.numberField("t", 0.0, false, "a finite number >= 0 (s)");
    if (type == "grab") {
      event.action = parseGrab(r);
    } else if (type == "inflate") {
      event.action = parseInflate(r);
    } else if (type == "paint") {
      event.action = parsePaint(r);
    } else if (type == "pin") {
      event.action = parsePin(r);
    } else if (type == "curve") {
      event.action = parseCurve(r);
    } else if (type == "topology") {
      if (event.time != 0)
        r.fail("t", "must be 0 (topology edits are applied before the simulation starts)");
      event.action = parseTopology(r);
    } else {
      bare.fail("type",
                "must be one of grab, inflate, paint, pin, curve, topology (got \"" + type + "\")");
    }
    script.events.push_back(std::move(event));
  }
  return script;
}

SessionScript loadSessionScript(const std::filesystem::path& path) {
  return parseSessionScript(readInputFile(path, kSessionScriptInput), path.string());
}

// ---------------------------------------------------------------------------------------------

ScriptPlayer::ScriptPlayer(Simulator& simulator, SessionScript script, ToolContext* context)
    : simulator_(simulator), script_(std::move(script)), runners_(script_.events.size()) {
  if (!context) {
    ownContext_ = std::make_unique<SimulatorToolContext>(simulator_);
    context = ownContext_.get();
  }
  context_ = context;
  order_.resize(script_.events.size());
  std::iota(order_.begin(), order_.end(), size_t(0));
  std::stable_sort(order_.begin(), order_.end(), [&](size_t a, size_t b) {
    return script_.events[a].time < script_.events[b].time;
  });
  for (size_t i = 0; i < script_.events.size(); ++i) {
    if (std::holds_alternative<TopologyEvent>(script_.events[i].action))
      throw std::invalid_argument(
          "events[" + std::to_string(script_.events[i].index) +
          "] (topology): a topology edit cannot be replayed on a running simulation; apply the "
          "script's topology events to the control mesh before building the model.");
    const auto* grab = std::get_if<GrabEvent>(&script_.events[i].action);
    const auto* curve = std::get_if<CurveEvent>(&script_.events[i].action);
    if (!grab && !curve) continue;
    const MaterialPointLocator& locator = context_->locator();
    if (curve) {
      try {
        runners_[i].curve =
            sampleCurve(simulator_.model(), locator, curve->points, curve->samples);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("events[" + std::to_string(script_.events[i].index) +
                                    "] (curve): " + e.what());
      }
      continue;
    }
    runners_[i].point = locator.locate(grab->point);
    if (!runners_[i].point)
      throw std::invalid_argument("events[" + std::to_string(script_.events[i].index) +
                                  "] (grab): the point cannot be located in the solid.");
  }
}

ScriptPlayer::~ScriptPlayer() = default;

std::optional<MaterialPoint> ScriptPlayer::grabPoint(size_t index) const {
  return index < runners_.size() ? runners_[index].point : std::nullopt;
}

const PullTool* ScriptPlayer::pullTool(size_t index) const {
  if (index >= runners_.size()) return nullptr;
  const auto* stroke = dynamic_cast<const PullStroke*>(runners_[index].tool.get());
  return stroke ? stroke->pull() : nullptr;
}

const CurveTool* ScriptPlayer::curveTool(size_t index) const {
  if (index >= runners_.size()) return nullptr;
  const auto* stroke = dynamic_cast<const CurveStroke*>(runners_[index].tool.get());
  return stroke ? stroke->curve() : nullptr;
}

void ScriptPlayer::springs(std::vector<ToolSpring>& out) const {
  for (const Runner& runner : runners_)
    if (runner.tool && runner.phase == Phase::Active) runner.tool->springs(simulator_, out);
}

std::vector<std::string> ScriptPlayer::takeLog() { return std::exchange(log_, {}); }

void ScriptPlayer::start(size_t i) {
  const ScriptEvent& event = script_.events[i];
  Runner& runner = runners_[i];
  const std::string name =
      "t=" + number(time_) + " s: events[" + std::to_string(event.index) + "] " + event.typeName();
  // Each event is a stroke of the tool it names, driven like any other input (tools/tool.h).
  ToolInput input;
  try {
    if (const auto* grab = std::get_if<GrabEvent>(&event.action)) {
      runner.tool = std::make_unique<PullStroke>(
          PullStroke::Settings{grab->stiffness, grab->keep, runner.point});
      input.position = grab->targetAt(time_ - event.time);
      if (grab->push) input.modifiers |= kToolInvert;
      runner.tool->begin(*context_, input);
      log_.push_back(name + " started");
    } else if (const auto* curve = std::get_if<CurveEvent>(&event.action)) {
      CurveStroke::Settings settings;
      settings.profile = curve->profile;
      settings.stiffness = curve->stiffness;
      settings.keep = curve->keep;
      settings.sampled = runner.curve;
      settings.dragOrigin = Eigen::Vector3d::Zero();
      runner.tool = std::make_unique<CurveStroke>(std::move(settings));
      input.position = curve->offsetAt(time_ - event.time);
      runner.tool->begin(*context_, input);
      log_.push_back(name + " started (" + std::to_string(runner.curve.size()) + " points)");
    } else if (const auto* inflate = std::get_if<InflateEvent>(&event.action)) {
      auto stroke = std::make_unique<InflateStroke>(
          InflateStroke::Settings{inflate->radius, inflate->pressure});
      input.restPoint = inflate->centre;
      stroke->begin(*context_, input);
      log_.push_back(name + " started (" + std::to_string(stroke->inflate()->numTriangles()) +
                     " triangles)");
      runner.tool = std::move(stroke);
    } else if (const auto* paint = std::get_if<PaintEvent>(&event.action)) {
      PaintStroke stroke(PaintStroke::Settings{paint->brush, paint->mirrorCentre});
      input.restPoint = paint->centre;
      stroke.begin(*context_, input);
      stroke.end(*context_, input);
      log_.push_back(name + ": " + std::to_string(stroke.samplesPainted()) + " samples painted");
    } else if (const auto* pin = std::get_if<PinEvent>(&event.action)) {
      PinStroke stroke(PinStroke::Settings{pin->radius, pin->box});
      input.restPoint = pin->centre;
      if (pin->unpin) input.modifiers |= kToolInvert;
      stroke.begin(*context_, input);
      stroke.end(*context_, input);
      log_.push_back(name + ": " + std::to_string(stroke.pointsTouched()) + " control points " +
                     (pin->unpin ? "unpinned" : "pinned"));
    }
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("events[" + std::to_string(event.index) + "] (" + event.typeName() +
                                "): " + e.what());
  }
  runner.phase = runner.tool ? Phase::Active : Phase::Done;
}

void ScriptPlayer::finish(size_t i) {
  Runner& runner = runners_[i];
  const ScriptEvent& event = script_.events[i];
  if (runner.tool) runner.tool->end(*context_, ToolInput{});
  runner.phase = Phase::Done;
  log_.push_back("t=" + number(time_) + " s: events[" + std::to_string(event.index) + "] " +
                 event.typeName() + " ended");
}

StepReport ScriptPlayer::step() {
  const double h = simulator_.settings().timeStep;
  const double due = time_ + 0.5 * h;  // events are rounded to the nearest step
  for (size_t i : order_) {
    const ScriptEvent& event = script_.events[i];
    Runner& runner = runners_[i];
    if (runner.phase == Phase::Pending && event.time <= due) start(i);
    if (runner.phase != Phase::Active) continue;
    const auto* grab = std::get_if<GrabEvent>(&event.action);
    const auto* curve = std::get_if<CurveEvent>(&event.action);
    const bool held = (grab && !grab->release) || (curve && !curve->release);
    if (!held && event.endTime() <= due) {
      finish(i);
    } else if (grab || curve) {
      ToolInput input;
      input.position = grab ? grab->targetAt(time_ + h - event.time)
                            : curve->offsetAt(time_ + h - event.time);
      runner.tool->update(*context_, input);
    }
  }
  const StepReport report = simulator_.step();
  if (report.ok) {
    ++steps_;
    time_ = static_cast<double>(steps_) * h;
  }
  return report;
}

}  // namespace sculpt
