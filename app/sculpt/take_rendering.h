#pragma once
// Names of a take's rendered frames: name_####.png numbers its frames from 1 in the run of '#'
// (zero-padded to the run's length, longer when the number needs it).

#include <cstdint>
#include <filesystem>

namespace sculpt::app {

/// `pattern` with the last run of '#' in its file name replaced by `number`.
std::filesystem::path sequenceFrameName(const std::filesystem::path& pattern, uint32_t number);

}  // namespace sculpt::app
