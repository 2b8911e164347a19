#pragma once
// Strict JSON objects: the first field of an object that is not among the known ones (a
// misspelt field would otherwise be ignored silently), and the known ones as a list for the
// message that says so.

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace sculpt {

inline std::optional<std::string> unknownJsonField(const nlohmann::json& object,
                                                   std::initializer_list<const char*> known) {
  for (const auto& item : object.items())
    if (std::none_of(known.begin(), known.end(), [&](const char* k) { return item.key() == k; }))
      return item.key();
  return std::nullopt;
}

/// "a, b, c".
inline std::string jsonFieldList(std::initializer_list<const char*> known) {
  std::string list;
  for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
  return list;
}

}  // namespace sculpt
