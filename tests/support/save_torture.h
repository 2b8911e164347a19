#pragma once
// The generation number that save_torture (save_torture_main.cpp) stores in each project it
// writes, and that kill_during_save_test.cpp reads back: a tool setting, which round-trips.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>

#include "project/project.h"

namespace sculpt::test {

inline constexpr char kGenerationKey[] = "torture.generation";

inline void setGeneration(Project& project, uint64_t generation) {
  project.tools[kGenerationKey] = static_cast<double>(generation);  // exact below 2^53
}

inline uint64_t generationOf(const Project& project) {
  const auto it = project.tools.find(kGenerationKey);
  if (it == project.tools.end() || !std::holds_alternative<double>(it->second))
    throw std::runtime_error("the project has no generation number");
  return static_cast<uint64_t>(std::get<double>(it->second));
}

}  // namespace sculpt::test
