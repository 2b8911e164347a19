#pragma once
// Consistency of a Project: what saving refuses and loading rejects, in one place
// (project_file.h uses it both ways).

#include <cstddef>
#include <string>
#include <string_view>

#include "project/project.h"

namespace sculpt {

/// The largest subdivision level a project file may claim (levels are small; this only bounds
/// what a file can make the program allocate).
inline constexpr int kMaxProjectLevel = 1000;
/// Longest piece of user text quoted in a message.
inline constexpr size_t kMaxQuoted = 40;

/// User text made safe for a one-line message: printable ASCII, at most kMaxQuoted characters.
std::string printable(std::string_view text);

/// Empty when the project is consistent (offsets, indices, finite numbers); otherwise one sentence
/// naming the first problem.
std::string projectProblem(const Project& project);

}  // namespace sculpt
