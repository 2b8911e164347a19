#include "project/autosave.h"

#include <stdexcept>
#include <system_error>

#include "io/atomic_file.h"
#include "project/project_file.h"

namespace sculpt {

std::filesystem::path recoveryPathFor(const std::filesystem::path& projectPath) {
  std::filesystem::path result = projectPath;
  result += ".recovery";
  return result;
}

std::optional<std::filesystem::path> findRecovery(const std::filesystem::path& projectPath) {
  const std::filesystem::path recovery = recoveryPathFor(projectPath);
  removeStaleTemporaries(projectPath);
  removeStaleTemporaries(recovery);
  std::error_code error;
  if (!std::filesystem::is_regular_file(recovery, error)) return std::nullopt;
  const auto recoveryTime = std::filesystem::last_write_time(recovery, error);
  if (error) return std::nullopt;
  const auto projectTime = std::filesystem::last_write_time(projectPath, error);
  if (error) return recovery;  // the project file is gone: the recovery file is all there is
  // "Not older" rather than "newer": file times are coarse (a few ms), and a clean save removes
  // the recovery file, so one that is present and as new as the project came after it.
  if (recoveryTime < projectTime) return std::nullopt;
  return recovery;
}

Autosave::Autosave(std::filesystem::path recoveryPath, double intervalS, Clock clock)
    : recoveryPath_(std::move(recoveryPath)), intervalS_(intervalS), clock_(std::move(clock)) {
  if (!(intervalS_ > 0.0)) throw std::invalid_argument("the autosave interval must be positive");
  if (!clock_) throw std::invalid_argument("autosave needs a clock");
  lastWriteS_ = clock_();
}

bool Autosave::tick(const Project& project, bool dirty) {
  const double now = clock_();
  if (!dirty || now - lastWriteS_ < intervalS_) return false;
  lastWriteS_ = now;  // also after a failure: retry at the next interval, not every frame
  // The recovery folder of a fresh configuration does not exist until the first autosave.
  std::error_code ignored;  // a folder that cannot be made fails the save below, with its reason
  if (recoveryPath_.has_parent_path())
    std::filesystem::create_directories(recoveryPath_.parent_path(), ignored);
  saveProject(project, recoveryPath_);
  return true;
}

void Autosave::savedCleanly() {
  std::error_code error;
  std::filesystem::remove(recoveryPath_, error);
  lastWriteS_ = clock_();
}

void Autosave::setRecoveryPath(std::filesystem::path recoveryPath) {
  std::error_code error;
  std::filesystem::remove(recoveryPath_, error);
  recoveryPath_ = std::move(recoveryPath);
}

}  // namespace sculpt
