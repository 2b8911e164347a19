#pragma once
// Where scripts/install-gltf-validator.sh put the Khronos glTF validator's wrapper (validate.js):
// $SCULPT_GLTF_VALIDATOR_DIR, else ${XDG_CACHE_HOME:-~/.cache}/sculpt/gltf-validator. Empty when
// it is not there.

#include <cstdlib>
#include <filesystem>

namespace sculpt::test {

inline std::filesystem::path gltfValidatorScript() {
  std::filesystem::path dir;
  if (const char* chosen = std::getenv("SCULPT_GLTF_VALIDATOR_DIR")) {
    dir = chosen;
  } else if (const char* cache = std::getenv("XDG_CACHE_HOME")) {
    dir = std::filesystem::path(cache) / "sculpt" / "gltf-validator";
  } else if (const char* home = std::getenv("HOME")) {
    dir = std::filesystem::path(home) / ".cache" / "sculpt" / "gltf-validator";
  }
  const auto script = dir / "validate.js";
  return !dir.empty() && std::filesystem::exists(script) ? script : std::filesystem::path();
}

}  // namespace sculpt::test
