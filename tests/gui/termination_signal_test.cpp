// SIGTERM and SIGINT end the window without losing work (sculpt/termination_signals.h): the
// handler only notes the signal, the frame loop writes the recovery file of unsaved edits (a
// stroke still held included) and closes without the unsaved-changes prompt, and the next start
// offers that file. A second signal takes the default action.

#include "render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <thread>

#include "gui/sculpt_session.h"
#include "project/autosave.h"
#include "project/project_file.h"
#include "sculpt/termination_signals.h"
#include "support/child_exit.h"

extern char** environ;

namespace sculpt::app {
namespace {

namespace fs = std::filesystem;

const std::string kBlock3 = std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json";

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(TerminationSignals, TheFirstSignalIsNotedAndASecondTakesTheDefaultAction) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // only async-signal-safe calls from here on
    ::signal(SIGINT, SIG_DFL);  // as a foreground program starts (a background job ignores it)
    installTerminationHandlers();
    ::raise(SIGINT);
    if (terminationSignal() != SIGINT) ::_exit(3);
    ::raise(SIGTERM);  // the default action ends the process here
    ::_exit(4);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status))
      << "exited with " << WEXITSTATUS(status) << " (3: the first signal was not noted)";
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
}

// A background job's SIGINT (or `nohup sculpt`'s SIGHUP): a signal ignored at the start stays
// ignored, and the others are still handled.
TEST(TerminationSignals, ASignalIgnoredAtTheStartStaysIgnored) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // only async-signal-safe calls from here on
    ::signal(SIGINT, SIG_IGN);
    ::signal(SIGHUP, SIG_DFL);
    installTerminationHandlers();
    ::raise(SIGINT);
    if (terminationSignal() != 0) ::_exit(3);
    ::raise(SIGHUP);
    if (terminationSignal() != SIGHUP) ::_exit(4);
    restoreDefaultTermination();
    ::raise(SIGINT);  // still ignored
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "3: SIGINT was noted; 4: SIGHUP was not";
}

// The interactive window (worker threads) drawn offscreen, with the real handler installed and
// the signal raised in this process.
TEST_F(SculptSession, SigtermKeepsTheUnsavedStrokesInTheRecoveryFileOfferedAtTheNextStart) {
  installTerminationHandlers();
  struct DefaultTermination {
    ~DefaultTermination() { restoreDefaultTermination(); }
  } defaultTermination;
  open(kBlock3, false);
  ASSERT_TRUE(framesUntilPhysics());
  const ViewRect view = app_->viewRect();
  const ImVec2 middle(0.5f * (view.min.x + view.max.x), 0.5f * (view.min.y + view.max.y));
  ToolState& tools = app_->model().tools;
  paintStrokeAcrossTheMiddle();
  ASSERT_TRUE(framesUntil([this] { return app_->document().canUndo(); }));
  ASSERT_EQ(app_->document().undoLabel(), "Paint Young's modulus");
  const MaterialSamples painted = app_->document().project().materials;
  ASSERT_GT(painted.size(), 0u);

  // A pin stroke still held when SIGTERM comes: it is ended and kept too.
  tools.tool = ToolKind::Pin;
  tools.brush().radiusPixels = 120.0f;
  const size_t pinsBefore = app_->document().project().pins.size();
  drag(ImVec2(middle.x - 40, middle.y + 40), 80.0f, 0.0f, 6);
  ASSERT_EQ(::raise(SIGTERM), 0);
  EXPECT_EQ(terminationSignal(), SIGTERM);
  ASSERT_TRUE(framesUntil([this] { return glfwWindowShouldClose(window_) != 0; }))
      << "the window closes after SIGTERM";
  EXPECT_FALSE(app_->model().document.closePrompt) << "no prompt: nobody may be there";
  EXPECT_EQ(app_->document().undoLabel(), "Pin") << "the held stroke became an edit";
  const fs::path recovery = folder_ / "untitled.sculpt.recovery";
  ASSERT_EQ(app_->document().recoveryPath(), recovery);
  ASSERT_TRUE(fs::exists(recovery)) << "SIGTERM writes the recovery file first";
  const Project kept = loadProject(recovery);
  EXPECT_TRUE(sameMaterialSamples(kept.materials, painted)) << "the paint stroke is kept";
  EXPECT_GT(kept.pins.size(), pinsBefore) << "the held pin stroke is kept";
  EXPECT_EQ(kept.pins, app_->document().project().pins);

  // The next start offers it, and recovering it brings the strokes back.
  restoreDefaultTermination();
  glfwSetWindowShouldClose(window_, 0);
  open(kBlock3, false);
  ASSERT_TRUE(framesUntil([this] { return !app_->model().document.recoveryOffer.empty(); }));
  EXPECT_EQ(app_->model().document.recoveryOffer, recovery.string());
  app_->model().requests.recover = true;
  frames(1);
  EXPECT_TRUE(app_->document().dirty()) << "recovered work is not saved yet";
  EXPECT_TRUE(sameMaterialSamples(app_->document().project().materials, painted));
  EXPECT_EQ(app_->document().project().pins, kept.pins);
}

// The real program: a signal to an idle window closes it through the frame loop (preferences
// saved on the way out) with the exit status a shell gives a signal's end, 128 + the signal.
void closesTheWindowThroughItsLoop(int signal) {
  test::ScratchDirectory scratch("sculpt_signal");
  const fs::path out = scratch.path() / "out.txt", err = scratch.path() / "err.txt";
  const std::string command = "XDG_CONFIG_HOME=" + scratch.path().string() + " exec " +
                              SCULPT_BINARY_DIR "/bin/sculpt --scene " + kBlock3 + " > " +
                              out.string() + " 2> " + err.string();
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  // Started as from a terminal, whatever this test inherited (nohup, a background job).
  posix_spawnattr_t attributes;
  ASSERT_EQ(posix_spawnattr_init(&attributes), 0);
  sigset_t defaults;
  sigemptyset(&defaults);
  for (const int s : {SIGTERM, SIGINT, SIGHUP}) sigaddset(&defaults, s);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, "/bin/sh", nullptr, &attributes,
                                  const_cast<char**>(argv), environ);
  posix_spawnattr_destroy(&attributes);
  ASSERT_EQ(spawned, 0);
  const auto started = std::chrono::steady_clock::now();
  while (readText(out).find("first frame") == std::string::npos &&
         std::chrono::steady_clock::now() - started < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_NE(readText(out).find("first frame"), std::string::npos) << readText(err);
  ASSERT_EQ(::kill(pid, signal), 0);
  const std::optional<int> status = test::waitForExit(pid, std::chrono::seconds(10));
  ASSERT_TRUE(status.has_value()) << "still running 10 s after " << terminationSignalName(signal);
  ASSERT_TRUE(WIFEXITED(*status)) << "ended by the signal itself, not through the loop";
  EXPECT_EQ(WEXITSTATUS(*status), 128 + signal) << readText(err);
  EXPECT_TRUE(fs::exists(scratch.path() / "sculpt" / "preferences.json"));
  EXPECT_FALSE(fs::exists(scratch.path() / "sculpt" / "untitled.sculpt.recovery"))
      << "nothing unsaved, nothing to recover";
}

TEST(SculptWindowProcess, SigtermClosesTheWindowThroughItsLoop) {
  closesTheWindowThroughItsLoop(SIGTERM);
}

// The terminal that started the program was closed.
TEST(SculptWindowProcess, SighupClosesTheWindowThroughItsLoop) {
  closesTheWindowThroughItsLoop(SIGHUP);
}

}  // namespace
}  // namespace sculpt::app
