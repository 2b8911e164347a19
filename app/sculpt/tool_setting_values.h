#pragma once
// Reading values back from a project's tool settings (project/project.h): a key that is missing
// or holds another kind of value keeps the default, and a number outside its range is clamped
// (a non-finite one keeps the default), so that a hand-edited or damaged project still opens.

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "project/project.h"

namespace sculpt::app {

template <typename T>
T settingOr(const ToolSettings& settings, const std::string& key, T fallback) {
  const auto it = settings.find(key);
  if (it == settings.end() || !std::holds_alternative<T>(it->second)) return fallback;
  return std::get<T>(it->second);
}

inline double clampFinite(double value, double lo, double hi, double fallback) {
  return std::isfinite(value) ? std::clamp(value, lo, hi) : fallback;
}

}  // namespace sculpt::app
