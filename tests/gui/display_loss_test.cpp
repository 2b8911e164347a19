// A lost display (sculpt/display_loss.h) ends the program at once, with a message and the
// unsaved work kept in the recovery file, instead of Xlib's exit(): that ran static destructors
// under the simulation thread and could hang the program for good.

#include "render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <thread>

#include "gui/installed_xlib_handler.h"
#include "gui/sculpt_session.h"
#include "project/project_file.h"
#include "sculpt/display_loss.h"
#include "support/child_exit.h"

extern char** environ;

namespace sculpt::app {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `command` run by /bin/sh; with `stderrFd`, that descriptor as its standard error.
pid_t spawnShell(const std::string& command, int stderrFd = -1) {
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stderrFd >= 0) posix_spawn_file_actions_adddup2(&actions, stderrFd, 2);
  pid_t pid = -1;
  const int spawned =
      posix_spawn(&pid, "/bin/sh", &actions, nullptr, const_cast<char**>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? pid : -1;
}

// An X server of the test's own (Xvfb on a free display), so that it can be taken away.
class OwnXServer {
 public:
  OwnXServer() {
    int fds[2];
    if (::pipe(fds) != 0) return;
    // The write end is inherited by Xvfb, which writes its display number there when ready.
    pid_ = spawnShell("exec Xvfb -displayfd " + std::to_string(fds[1]) +
                      " -screen 0 1280x1024x24 -nolisten tcp 2>/dev/null");
    ::close(fds[1]);
    std::string number;
    char c = 0;
    while (pid_ > 0 && ::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (!number.empty()) display_ = ":" + number;
  }
  ~OwnXServer() { stop(); }
  const std::string& display() const { return display_; }  // empty: Xvfb did not start
  void stop() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    test::waitForExit(pid_, 10s);
    pid_ = -1;
  }

 private:
  pid_t pid_ = -1;
  std::string display_;
};

// The real program on the default scene, simulating, when its X server ends. `err` empty: its
// standard error is a pipe whose reader is gone, as when a logout ends `sculpt 2>&1 | tee log`.
// Returns how it ended (nullopt: it did not end within 10 s).
std::optional<int> loseTheDisplayOfARunningProgram(const fs::path& folder, const fs::path& err) {
  OwnXServer server;
  EXPECT_FALSE(server.display().empty()) << "Xvfb (scripts/install-deps.sh) did not start";
  if (server.display().empty()) return std::nullopt;
  const fs::path out = folder / "out.txt";
  int pipeFds[2] = {-1, -1};
  if (err.empty() && ::pipe(pipeFds) == 0) ::close(pipeFds[0]);  // no reader
  const pid_t pid = spawnShell("DISPLAY=" + server.display() + " XDG_CONFIG_HOME=" +
                                   folder.string() + " exec " SCULPT_BINARY_DIR "/bin/sculpt > " +
                                   out.string() + (err.empty() ? "" : " 2> " + err.string()),
                               pipeFds[1]);
  if (pipeFds[1] >= 0) ::close(pipeFds[1]);
  EXPECT_GT(pid, 0);
  if (pid <= 0) return std::nullopt;
  const auto started = std::chrono::steady_clock::now();
  while (readText(out).find("simulation running") == std::string::npos &&
         std::chrono::steady_clock::now() - started < 60s)
    std::this_thread::sleep_for(50ms);
  EXPECT_NE(readText(out).find("simulation running"), std::string::npos) << readText(err);
  std::this_thread::sleep_for(300ms);  // steps under way on the simulation's threads
  server.stop();
  return test::waitForExit(pid, 10s);
}

// It ends within a second, with Xlib's exit status and our message.
TEST(SculptWindowProcess, ALostDisplayEndsTheProgramAtOnceWithAMessage) {
  test::ScratchDirectory scratch("sculpt_display_loss");
  const fs::path err = scratch.path() / "err.txt";
  const std::optional<int> status = loseTheDisplayOfARunningProgram(scratch.path(), err);
  ASSERT_TRUE(status.has_value()) << "still running 10 s after the display went away";
  ASSERT_TRUE(WIFEXITED(*status)) << "ended by signal " << WTERMSIG(*status);
  EXPECT_EQ(WEXITSTATUS(*status), kDisplayLostExitStatus);
  EXPECT_NE(readText(err).find("sculpt: the connection to the display was lost"),
            std::string::npos)
      << readText(err);
  EXPECT_FALSE(fs::exists(scratch.path() / "sculpt" / "untitled.sculpt.recovery"))
      << "nothing unsaved, nothing to recover";
}

// A message to a standard error nobody reads (SIGPIPE) does not end it before the work is kept.
TEST(SculptWindowProcess, ALostDisplayEndsTheProgramWhenNobodyReadsItsMessages) {
  test::ScratchDirectory scratch("sculpt_display_loss_pipe");
  const std::optional<int> status = loseTheDisplayOfARunningProgram(scratch.path(), {});
  ASSERT_TRUE(status.has_value()) << "still running 10 s after the display went away";
  ASSERT_TRUE(WIFEXITED(*status)) << "ended by signal " << WTERMSIG(*status);
  EXPECT_EQ(WEXITSTATUS(*status), kDisplayLostExitStatus);
}

// The handler the app installs, called as Xlib calls it, in a child of this process (it ends the
// process): the paint stroke not yet saved is in the recovery file.
TEST_F(SculptSession, ALostDisplayKeepsTheUnsavedWorkInTheRecoveryFile) {
  open(std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json", false);
  ASSERT_TRUE(framesUntilPhysics());
  paintStrokeAcrossTheMiddle();
  ASSERT_TRUE(framesUntil([this] { return app_->document().canUndo(); }));
  ASSERT_TRUE(app_->document().dirty());
  const MaterialSamples painted = app_->document().project().materials;
  const fs::path recovery = app_->document().recoveryPath();
  ASSERT_FALSE(fs::exists(recovery));

  ASSERT_TRUE(testing::xlibIoHandlerInstalled());
  const fs::path err = folder_ / "child_err.txt";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // the handler never returns; if it did, 99 says so
    if (!std::freopen(err.c_str(), "w", stderr)) ::_exit(98);
    testing::callXlibIoHandler();
    ::_exit(99);
  }
  const std::optional<int> status = test::waitForExit(child, 30s);
  ASSERT_TRUE(status.has_value()) << "the child did not end";
  ASSERT_TRUE(WIFEXITED(*status)) << "ended by signal " << WTERMSIG(*status);
  EXPECT_EQ(WEXITSTATUS(*status), kDisplayLostExitStatus) << readText(err);
  ASSERT_TRUE(fs::exists(recovery)) << readText(err);
  EXPECT_TRUE(sameMaterialSamples(loadProject(recovery).materials, painted));
  EXPECT_NE(readText(err).find("display lost: the unsaved work is kept in " + recovery.string()),
            std::string::npos)
      << readText(err);
}

}  // namespace
}  // namespace sculpt::app
