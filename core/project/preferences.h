#pragma once
// Preferences: what belongs to the user rather than to a project (key map, UI scale, window
// geometry, recent files), in a small JSON file under $XDG_CONFIG_HOME/sculpt (or
// ~/.config/sculpt). Written atomically; a damaged file gives the defaults and a warning, never
// a failure to start.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sculpt {

struct WindowGeometry {
  int x = -1, y = -1;  ///< screen position; -1 lets the window system choose
  int width = 1280, height = 800;
  bool maximized = false;
  bool operator==(const WindowGeometry&) const = default;
};

/// The sculpting brushes' radii the user last used, in screen pixels, by the app's tool names
/// ("paint", ...), and its unified-radius switch. Read values are clamped to [kMinPixels,
/// kMaxPixels].
struct BrushRadii {
  static constexpr double kMinPixels = 2.0, kMaxPixels = 1000.0;

  std::map<std::string, double> byTool;  ///< a tool not named keeps the app's default
  bool unified = false;
  double unifiedPixels = 50.0;
  bool operator==(const BrushRadii&) const = default;
};

struct Preferences {
  static constexpr size_t kMaxRecentFiles = 10;

  std::string keyMap;  ///< opaque text owned by the app's key bindings
  double uiScale = 0.0;  ///< the user's UI scale override; 0: from the monitor's content scale
  WindowGeometry window;
  std::vector<std::string> recentFiles;  ///< most recent first, no repeats, at most 10
  BrushRadii brushRadii;

  /// Moves (or adds) `path` to the front of recentFiles and drops the oldest beyond 10.
  void addRecentFile(const std::string& path);
  bool operator==(const Preferences&) const = default;
};

struct LoadedPreferences {
  Preferences preferences;
  std::string warning;  ///< empty, or one sentence on why defaults (or some of them) were used
};

/// $XDG_CONFIG_HOME/sculpt/preferences.json when XDG_CONFIG_HOME is set and absolute, else
/// $HOME/.config/sculpt/preferences.json, else ./sculpt-preferences.json.
std::filesystem::path preferencesPath();
/// The same rule with the variables given (null when unset), for tests.
std::filesystem::path preferencesPath(const char* xdgConfigHome, const char* home);

/// A missing file gives the defaults without a warning; an unreadable or malformed one gives the
/// defaults (keeping the fields that were readable) and a warning. Never throws.
LoadedPreferences loadPreferences(const std::filesystem::path& path);
/// Creates the directory if needed and writes atomically. Throws FileError.
void savePreferences(const Preferences& preferences, const std::filesystem::path& path);

}  // namespace sculpt
