// SIGKILL at random moments while save_torture (tests/support/save_torture_main.cpp) saves and
// autosaves a real project: after every kill the project file is the previous save or the new
// one, complete; the recovery file loads and is offered at the next start whenever it holds work
// newer than the project; and the hidden temporary files a killed save leaves are removed by
// that start (findRecovery), so none pile up and none is ever visible under the project's name.
//
// SCULPT_KILL_SEED and SCULPT_KILL_ROUNDS repeat or lengthen a run.

#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "io/atomic_file.h"
#include "project/autosave.h"
#include "project/project_file.h"
#include "support/save_torture.h"
#include "support/scratch_directory.h"

extern char** environ;

namespace sculpt {
namespace {

namespace fs = std::filesystem;

unsigned envOr(const char* name, unsigned fallback) {
  const char* text = std::getenv(name);
  return text && *text ? static_cast<unsigned>(std::stoul(text)) : fallback;
}

// What a folder holds: hidden temporaries of atomic writes (".name.tmp.<pid>.<n>") and the
// names a user would see.
struct Folder {
  size_t temporaries = 0;
  std::vector<std::string> visible;
};

Folder list(const fs::path& dir) {
  Folder folder;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.front() == '.' && name.find(".tmp.") != std::string::npos)
      ++folder.temporaries;
    else
      folder.visible.push_back(name);
  }
  return folder;
}

// Starts args[0]; `closeInChild` is a descriptor the child must not keep (-1: none).
pid_t spawn(const std::vector<std::string>& args, int closeInChild = -1) {
  std::vector<char*> argv;
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (closeInChild >= 0) posix_spawn_file_actions_addclose(&actions, closeInChild);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return error == 0 ? pid : -1;
}

// Starts save_torture and returns once it has built its project and begins to save.
pid_t startTorture(const fs::path& project, uint64_t firstGeneration) {
  int ready[2];
  if (::pipe(ready) != 0) return -1;
  const pid_t pid = spawn({SCULPT_SAVE_TORTURE, project.string(), std::to_string(firstGeneration),
                           std::to_string(ready[1])},
                          ready[0]);
  ::close(ready[1]);
  pollfd wait{ready[0], POLLIN, 0};
  char byte = 0;
  const bool started = pid > 0 && ::poll(&wait, 1, 10000) == 1 && ::read(ready[0], &byte, 1) == 1;
  ::close(ready[0]);
  if (!started && pid > 0) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
  }
  return started ? pid : -1;
}

// How long one round of save_torture's work (an autosave, and a save every second round) takes
// in this build on this machine, from the generation it reaches in half a second: a sanitizer
// build or a loaded machine takes several times as long as an idle Release build.
std::chrono::microseconds tortureRound() {
  test::ScratchDirectory scratch("kill_during_save_calibration");
  const fs::path project = scratch.path() / "work.sculpt";
  const pid_t pid = startTorture(project, 1);
  if (pid <= 0) return {};
  const auto started = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  const auto elapsed = std::chrono::steady_clock::now() - started;
  uint64_t reached = 1;
  for (const fs::path& file : {project, recoveryPathFor(project)}) {
    try {
      reached = std::max(reached, test::generationOf(loadProject(file)));
    } catch (const std::exception&) {  // not written yet, or the kill's own: the other counts
    }
  }
  return std::chrono::duration_cast<std::chrono::microseconds>(elapsed / reached);
}

TEST(KillDuringSave, ProjectAndRecoveryAreWholeAfterEveryKillAndTheWorkIsOffered) {
  const unsigned seed = envOr("SCULPT_KILL_SEED", 20261202u);
  const unsigned rounds = envOr("SCULPT_KILL_ROUNDS", 300u);
  // Kills within 30 ms of the saves' start, or within three rounds where a round takes longer,
  // so that most kills find work saved since the start (the `progressed` count below).
  const auto saveRound = tortureRound();
  ASSERT_GT(saveRound.count(), 0) << "cannot start " << SCULPT_SAVE_TORTURE;
  const int windowUs = std::max(30000, static_cast<int>(3 * saveRound.count()));
  std::printf("[ kills ] seed %u (SCULPT_KILL_SEED=%u repeats the kill times), a round of saves "
              "%.1f ms, kills within %.1f ms\n",
              seed, seed, 1e-3 * static_cast<double>(saveRound.count()), 1e-3 * windowUs);
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> sleepUs(0, windowUs);

  test::ScratchDirectory scratch("kill_during_save");
  const fs::path project = scratch.path() / "work.sculpt";
  const fs::path recovery = recoveryPathFor(project);
  Project first;
  test::setGeneration(first, 0);
  saveProject(first, project);

  uint64_t projectGeneration = 0, highest = 0;
  unsigned midWrite = 0, offered = 0, progressed = 0, justSaved = 0;
  // The kills must land where they matter: at least a fifth of `rounds` while a temporary file
  // existed (a fifth to a third of the kills did on an idle machine). A loaded machine shifts
  // the share, so the test kills on, up to four times `rounds`, until that many did.
  const unsigned wantedMidWrite = rounds / 5, maxRounds = 4 * rounds;
  unsigned round = 0;
  const auto started = std::chrono::steady_clock::now();
  while (round < maxRounds && (round < rounds || midWrite < wantedMidWrite)) {
    ++round;
    SCOPED_TRACE("round " + std::to_string(round) + ", seed " + std::to_string(seed));
    const pid_t pid = startTorture(project, highest + 1);
    ASSERT_GT(pid, 0) << "cannot start " << SCULPT_SAVE_TORTURE;
    std::this_thread::sleep_for(std::chrono::microseconds(sleepUs(random)));
    ASSERT_EQ(::kill(pid, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
        << "save_torture ended by itself (status " << status << ")";

    // What the user finds: the project and at most its recovery file, each whole.
    const Folder atKill = list(scratch.path());
    if (atKill.temporaries > 0) ++midWrite;  // the kill landed between create and rename
    for (const std::string& name : atKill.visible)
      ASSERT_TRUE(name == project.filename() || name == recovery.filename()) << name;
    uint64_t generation = 0;
    try {
      generation = test::generationOf(loadProject(project));
    } catch (const std::exception& error) {
      FAIL() << "the project file is damaged: " << error.what();
    }
    ASSERT_GE(generation, projectGeneration) << "a save went back in time";
    projectGeneration = generation;
    uint64_t newest = generation;

    // The next start: findRecovery offers the autosaved work and clears the killed save's files.
    const std::optional<fs::path> offer = findRecovery(project);
    if (fs::exists(recovery)) {
      uint64_t recovered = 0;
      try {
        recovered = test::generationOf(loadProject(recovery));
      } catch (const std::exception& error) {
        FAIL() << "the recovery file is damaged: " << error.what();
      }
      ASSERT_GE(recovered, generation) << "a recovery file older than the saved project";
      if (recovered > generation) {  // unsaved work: it must be offered
        ASSERT_EQ(offer, recovery) << "generation " << recovered << " over " << generation;
        ++offered;
      } else {
        ++justSaved;  // killed between the save's rename and the recovery file's removal
      }
      newest = recovered;
    } else {
      ASSERT_FALSE(offer.has_value());
      ++justSaved;  // a clean save removed the recovery file; the next autosave had not landed
    }
    EXPECT_EQ(list(scratch.path()).temporaries, 0u) << "the start leaves no temporary behind";
    if (newest > highest) ++progressed;
    highest = std::max(highest, newest);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf(
      "[ kills ] %u kills in %.1f s: %u mid-write (a temporary file existed), %u with the "
      "recovery offered, %u just saved, %u advanced; generation %llu reached\n",
      round, seconds, midWrite, offered, justSaved, progressed,
      static_cast<unsigned long long>(highest));
  // A test that never kills a save proves nothing.
  EXPECT_GE(midWrite, wantedMidWrite) << "too few kills landed while a file was being written";
  EXPECT_GE(progressed, rounds / 4) << "save_torture rarely got to save before the kill";
  EXPECT_GE(offered, rounds / 4);
}

TEST(KillDuringSave, TheStartRemovesTemporariesOfDeadWritersAndKeepsLiveOnes) {
  test::ScratchDirectory scratch("stale_temporaries");
  const fs::path project = scratch.path() / "work.sculpt";
  saveProject(Project{}, project);
  const pid_t live = spawn({"/bin/sleep", "30"});
  ASSERT_GT(live, 0);
  const pid_t dead = spawn({"/bin/true"});
  ASSERT_GT(dead, 0);
  int status = 0;
  ASSERT_EQ(::waitpid(dead, &status, 0), dead);
  auto touch = [&](const std::string& name) {
    writeFileAtomically(scratch.path() / name, "partial");
    return scratch.path() / name;
  };
  const fs::path deadProject = touch(".work.sculpt.tmp." + std::to_string(dead) + ".0");
  const fs::path deadRecovery = touch(".work.sculpt.recovery.tmp." + std::to_string(dead) + ".7");
  const fs::path liveProject = touch(".work.sculpt.tmp." + std::to_string(live) + ".1");
  const fs::path notOurs = touch(".work.sculpt.tmp.notes");
  const fs::path otherFile = touch(".other.sculpt.tmp." + std::to_string(dead) + ".0");

  EXPECT_FALSE(findRecovery(project).has_value());
  EXPECT_FALSE(fs::exists(deadProject));
  EXPECT_FALSE(fs::exists(deadRecovery));
  EXPECT_TRUE(fs::exists(liveProject)) << "a writer that still runs may be saving now";
  EXPECT_TRUE(fs::exists(notOurs));
  EXPECT_TRUE(fs::exists(otherFile)) << "only the project's and its recovery's temporaries";
  EXPECT_EQ(removeStaleTemporaries(project), 0u);
  ::kill(live, SIGKILL);
  ::waitpid(live, &status, 0);
  EXPECT_EQ(removeStaleTemporaries(project), 1u) << "its writer is gone now";
}

}  // namespace
}  // namespace sculpt
