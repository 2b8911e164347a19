#include "tools/session_script_writer.h"

#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include <nlohmann/json.hpp>

#include "io/atomic_file.h"

namespace sculpt {
namespace {

using json = nlohmann::ordered_json;  // fields in the order the format documents them

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json path(const std::vector<PathKey>& keys) {
  json out = json::array();
  for (const PathKey& k : keys) out.push_back({k.time, k.target.x(), k.target.y(), k.target.z()});
  return out;
}

void drag(json& e, double stiffness, const std::optional<double>& release, bool keep) {
  if (stiffness > 0) e["stiffness"] = stiffness;
  if (release) e["release"] = *release;
  if (keep) e["keep"] = true;
}

json eventJson(const ScriptEvent& event) {
  json e;
  e["t"] = event.time;
  e["type"] = event.typeName();
  std::visit(
      [&e](const auto& a) {
        using T = std::decay_t<decltype(a)>;
        if constexpr (std::is_same_v<T, GrabEvent>) {
          e["point"] = vec(a.point);
          e["path"] = path(a.path);
          drag(e, a.stiffness, a.release, a.keep);
          if (a.push) e["push"] = true;
        } else if constexpr (std::is_same_v<T, CurveEvent>) {
          json points = json::array();
          for (const Eigen::Vector3d& p : a.points) points.push_back(vec(p));
          e["points"] = points;
          e["path"] = path(a.path);
          e["profile"] = curveProfileName(a.profile);
          if (a.samples > 0) e["samples"] = a.samples;
          drag(e, a.stiffness, a.release, a.keep);
        } else if constexpr (std::is_same_v<T, InflateEvent>) {
          if (std::isfinite(a.radius)) {
            e["centre"] = vec(a.centre);
            e["radius"] = a.radius;
          }
          e["pressure"] = a.pressure;
          e["duration"] = a.duration;
        } else if constexpr (std::is_same_v<T, PaintEvent>) {
          const MaterialBrushSettings& b = a.brush;
          e["centre"] = vec(a.centre);
          e["radius"] = b.radius;
          if (b.fields.youngs) e["youngs"] = b.target.youngs;
          if (b.fields.density) e["density"] = b.target.density;
          if (b.fields.damping) e["damping"] = b.target.damping;
          if (b.fields.poisson) e["poisson"] = b.target.poisson;
          e["falloff"] = falloffName(b.falloff);
          e["strength"] = b.strength;
          std::string mirror;
          if (b.mirror.x) mirror += 'x';
          if (b.mirror.y) mirror += 'y';
          if (b.mirror.z) mirror += 'z';
          e["mirror"] = mirror.empty() ? std::string("none") : mirror;
          if (a.mirrorCentre) e["mirrorCentre"] = vec(*a.mirrorCentre);
        } else if constexpr (std::is_same_v<T, PinEvent>) {
          if (a.box) {
            e["box"] = json::array({vec(a.box->min()), vec(a.box->max())});
          } else {
            e["centre"] = vec(a.centre);
            e["radius"] = a.radius;
          }
          if (a.unpin) e["unpin"] = true;
        } else {
          throw std::invalid_argument("a topology event is not written to a take's script");
        }
      },
      event.action);
  return e;
}

}  // namespace

std::string sessionScriptJson(const SessionScript& script, const std::string& description) {
  json root;
  root["format"] = "sculpt-session";
  root["version"] = 1;
  if (!description.empty()) root["description"] = description;
  json events = json::array();
  for (const ScriptEvent& event : script.events) events.push_back(eventJson(event));
  root["events"] = events;
  return root.dump(2) + "\n";
}

void saveSessionScript(const SessionScript& script, const std::filesystem::path& path,
                       const std::string& description) {
  writeFileAtomically(path, sessionScriptJson(script, description));
}

}  // namespace sculpt
