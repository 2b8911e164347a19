// The window's command line: a file named on its own opens as --scene does, and two scenes are
// refused with a message that names both.

#include <gtest/gtest.h>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "sculpt/options.h"

namespace sculpt::app {
namespace {

Options parse(std::initializer_list<std::string> args) {
  std::vector<std::string> words{"sculpt"};
  words.insert(words.end(), args);
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  return parseOptions(static_cast<int>(argv.size()), argv.data(), nullptr);
}

std::string refusal(std::initializer_list<std::string> args) {
  try {
    parse(args);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "accepted";
}

TEST(WindowOptions, AFileNamedOnItsOwnIsTheScene) {
  EXPECT_EQ(parse({}).scene, "");
  EXPECT_EQ(parse({"work.sculpt"}).scene, "work.sculpt");
  EXPECT_EQ(parse({"--scene", "assets/block3.json"}).scene, "assets/block3.json");
  // Anywhere among the options, and not taken for an option's value.
  const Options options = parse({"--level", "2", "assets/bunny.obj", "--wireframe"});
  EXPECT_EQ(options.scene, "assets/bunny.obj");
  EXPECT_EQ(options.level, 2);
  EXPECT_TRUE(options.display.wireframe);
  EXPECT_EQ(parse({"--script", "s.json", "a.json"}).script, "s.json");
}

TEST(WindowOptions, TwoScenesAreRefusedByName) {
  EXPECT_EQ(refusal({"a.json", "b.obj"}),
            "two scenes given ('a.json' and 'b.obj'): the window opens one");
  EXPECT_EQ(refusal({"--scene", "a.json", "b.obj"}),
            "two scenes given ('a.json' and 'b.obj'): the window opens one");
  EXPECT_EQ(refusal({"a.json", "--surface", "b.obj"}),
            "two scenes given ('a.json' and 'b.obj'): the window opens one");
  EXPECT_EQ(refusal({"--frobnicate"}), "unknown option '--frobnicate'");
  EXPECT_EQ(refusal({"--scene"}), "--scene needs a value");
}

}  // namespace
}  // namespace sculpt::app
