#include "project/preferences.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <system_error>
#include <type_traits>
#include <utility>

#include "io/atomic_file.h"
#include "io/file_error.h"
#include "io/input_file.h"

namespace sculpt {
namespace {

using nlohmann::json;

constexpr const char* kFormatName = "sculpt-preferences";
constexpr int kFormatVersion = 1;

/// Whether get<int>() is defined for the value: nlohmann converts numbers with a plain cast,
/// which is undefined for a float outside int's range (1e300) and wraps a large integer.
bool convertsToInt(const json& value) {
  if (value.is_number_unsigned()) return value.get<uint64_t>() <= uint64_t{INT_MAX};
  if (value.is_number_integer()) {
    const int64_t v = value.get<int64_t>();
    return v >= INT_MIN && v <= INT_MAX;
  }
  if (value.is_number_float()) {
    const double v = value.get<double>();
    return v > INT_MIN - 1.0 && v < INT_MAX + 1.0;  // false for NaN
  }
  return true;  // not a number: get<int>() throws (or reads a bool)
}

// Reads one field if present and of the right kind; otherwise keeps the default and notes it.
class FieldReader {
 public:
  /// `path` names the object read in messages ("brushRadii." for its fields); empty: the root.
  FieldReader(const json& root, std::string& problem, std::string path = {})
      : root_(root), problem_(problem), path_(std::move(path)) {}

  /// True when the field was there and taken.
  template <typename T, typename Check>
  bool read(const char* key, T& out, Check valid) {
    const auto it = root_.find(key);
    if (it == root_.end()) return false;
    try {
      if constexpr (std::is_same_v<T, int>) {
        if (!convertsToInt(*it)) {
          notice(key);
          return false;
        }
      }
      // nlohmann reads true as 1.0: a boolean where a number belongs is a mistake.
      if constexpr (std::is_floating_point_v<T>) {
        if (!it->is_number()) {
          notice(key);
          return false;
        }
      }
      T value = it->get<T>();
      if (valid(value)) {
        out = value;
        return true;
      }
    } catch (const json::exception&) {
    }
    notice(key);
    return false;
  }

 private:
  void notice(const char* key) {
    if (problem_.empty()) problem_ = "\"" + path_ + key + "\" has an unusable value";
  }

  const json& root_;
  std::string& problem_;
  std::string path_;
};

double clampedRadius(double pixels) {
  return std::clamp(pixels, BrushRadii::kMinPixels, BrushRadii::kMaxPixels);
}

// "brushRadii": {"unified": false, "unifiedPixels": 50, "byTool": {"paint": 40, ...}}; a value of
// the wrong kind loses only itself, a number out of range is clamped.
void readBrushRadii(const json& object, BrushRadii& radii, std::string& problem) {
  if (!object.is_object()) {
    if (problem.empty()) problem = "\"brushRadii\" has an unusable value";
    return;
  }
  const auto finite = [](double v) { return std::isfinite(v); };
  FieldReader fields(object, problem, "brushRadii.");
  fields.read("unified", radii.unified, [](bool) { return true; });
  fields.read("unifiedPixels", radii.unifiedPixels, finite);
  radii.unifiedPixels = clampedRadius(radii.unifiedPixels);
  const auto byTool = object.find("byTool");
  if (byTool == object.end()) return;
  if (!byTool->is_object()) {
    if (problem.empty()) problem = "\"brushRadii.byTool\" has an unusable value";
    return;
  }
  FieldReader tools(*byTool, problem, "brushRadii.byTool.");
  for (const auto& item : byTool->items()) {
    double pixels = 0;
    if (tools.read(item.key().c_str(), pixels, finite))
      radii.byTool[item.key()] = clampedRadius(pixels);
  }
}

}  // namespace

void Preferences::addRecentFile(const std::string& path) {
  recentFiles.erase(std::remove(recentFiles.begin(), recentFiles.end(), path), recentFiles.end());
  recentFiles.insert(recentFiles.begin(), path);
  if (recentFiles.size() > kMaxRecentFiles) recentFiles.resize(kMaxRecentFiles);
}

std::filesystem::path preferencesPath(const char* xdgConfigHome, const char* home) {
  // The XDG base-directory spec says relative values are to be ignored.
  if (xdgConfigHome && xdgConfigHome[0] == '/') {
    return std::filesystem::path(xdgConfigHome) / "sculpt" / "preferences.json";
  }
  if (home && home[0] != '\0') {
    return std::filesystem::path(home) / ".config" / "sculpt" / "preferences.json";
  }
  return "sculpt-preferences.json";
}

std::filesystem::path preferencesPath() {
  return preferencesPath(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"));
}

LoadedPreferences loadPreferences(const std::filesystem::path& path) {
  LoadedPreferences result;
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return result;
  const std::string where = path.string() + ": ";
  const std::string suffix = "; using the defaults";
  json root;
  try {
    const std::string text = readInputFile(path, kPreferencesInput);
    root = json::parse(text);
  } catch (const FileError& e) {
    result.warning = std::string(e.what()) + suffix;
    return result;
  } catch (const json::exception&) {
    result.warning = where + "not valid JSON" + suffix;
    return result;
  }
  if (!root.is_object() || root.value("format", json()) != kFormatName) {
    result.warning = where + "not a sculpt preferences file" + suffix;
    return result;
  }
  if (!root["version"].is_number_integer() || root["version"].get<int64_t>() > kFormatVersion) {
    result.warning = where + "written by a newer sculpt or of unknown version" + suffix;
    return result;
  }
  // Field by field: one bad value loses only itself.
  Preferences& p = result.preferences;
  std::string problem;
  FieldReader fields(root, problem);
  fields.read("keyMap", p.keyMap, [](const std::string&) { return true; });
  fields.read("uiScale", p.uiScale,
              [](double s) { return s == 0.0 || (std::isfinite(s) && s >= 0.25 && s <= 8); });
  if (const auto it = root.find("window"); it != root.end()) {
    if (it->is_object()) {
      FieldReader window(*it, problem);
      auto any = [](int) { return true; };
      auto size = [](int s) { return s >= 64 && s <= 100000; };
      window.read("x", p.window.x, any);
      window.read("y", p.window.y, any);
      window.read("width", p.window.width, size);
      window.read("height", p.window.height, size);
      window.read("maximized", p.window.maximized, [](bool) { return true; });
    } else if (problem.empty()) {
      problem = "\"window\" is not an object";
    }
  }
  std::vector<std::string> recent;
  fields.read("recentFiles", recent, [](const std::vector<std::string>&) { return true; });
  for (auto it = recent.rbegin(); it != recent.rend(); ++it) p.addRecentFile(*it);
  if (const auto it = root.find("brushRadii"); it != root.end())
    readBrushRadii(*it, p.brushRadii, problem);
  if (!problem.empty()) result.warning = where + problem + "; using the default for it";
  return result;
}

void savePreferences(const Preferences& preferences, const std::filesystem::path& path) {
  if (path.has_parent_path()) {
    std::error_code error;
    std::filesystem::create_directories(path.parent_path(), error);
    if (error) {
      throw FileError(path.parent_path().string() + ": cannot create the directory (" +
                      error.message() + ")");
    }
  }
  const json root = {
      {"format", kFormatName},
      {"version", kFormatVersion},
      {"keyMap", preferences.keyMap},
      {"uiScale", preferences.uiScale},
      {"window",
       {{"x", preferences.window.x},
        {"y", preferences.window.y},
        {"width", preferences.window.width},
        {"height", preferences.window.height},
        {"maximized", preferences.window.maximized}}},
      {"recentFiles", preferences.recentFiles},
      {"brushRadii",
       {{"unified", preferences.brushRadii.unified},
        {"unifiedPixels", preferences.brushRadii.unifiedPixels},
        {"byTool", preferences.brushRadii.byTool}}},
  };
  std::string text;
  try {
    text = root.dump(2) + "\n";
  } catch (const json::exception&) {
    throw FileError(path.string() + ": cannot write preferences (a file name is not valid UTF-8)");
  }
  writeFileAtomically(path, text);
}

}  // namespace sculpt
