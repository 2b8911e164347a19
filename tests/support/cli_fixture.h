#pragma once
#include "support/shell_quote.h"
// sculpt-cli end to end: a GoogleTest fixture that runs the built binary in a fresh temporary
// folder per test and captures its exit status, stdout and stderr, plus the small text helpers the
// CLI tests share. A suite derives from CliFixture, naming its folder prefix:
//
//   class MyCliTest : public test::CliFixture {
//    protected:
//     MyCliTest() : CliFixture("sculpt_my_cli_test_") {}
//   };
//   TEST_F(MyCliTest, Bad) { expectBadInput("info " + quote(path("x.json")), "x.json"); }

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sculpt::test {

/// Short name for shellQuote in command lines of the CLI tests.
inline std::string quote(const std::string& text) { return shellQuote(text); }


/// The built sculpt-cli.
inline const std::string kCli = SCULPT_BINARY_DIR "/bin/sculpt-cli";

/// How one sculpt-cli run ended.
struct CliResult {
  bool signaled = false;  // killed by a signal (or exit code >= 128)
  int exitCode = -1;
  std::string out;
  std::string err;

  /// stderr without the progress lines ("[  0.01 s] ..."), which are not error reports.
  std::vector<std::string> errLines() const {
    std::vector<std::string> lines;
    std::istringstream in(err);
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && line[0] != '[') lines.push_back(line);
    return lines;
  }

  /// The last non-empty line of stdout.
  std::string lastLine() const {
    std::istringstream in(out);
    std::string last;
    for (std::string line; std::getline(in, line);)
      if (!line.empty()) last = line;
    return last;
  }
};


inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

using KeyValues = std::vector<std::pair<std::string, std::string>>;

/// "a=1 b=2" as (key, value) pairs; a word without '=' gives an empty key.
inline KeyValues keyValues(const std::string& line) {
  KeyValues pairs;
  std::istringstream in(line);
  for (std::string word; in >> word;) {
    const size_t eq = word.find('=');
    if (eq == std::string::npos) {
      pairs.emplace_back("", word);
    } else {
      pairs.emplace_back(word.substr(0, eq), word.substr(eq + 1));
    }
  }
  return pairs;
}

/// Digits, a point, exactly three digits.
inline bool isMilliseconds(const std::string& text) {
  const size_t dot = text.find('.');
  if (dot == 0 || dot == std::string::npos || text.size() - dot != 4) return false;
  for (size_t i = 0; i < text.size(); ++i)
    if (i != dot && (text[i] < '0' || text[i] > '9')) return false;
  return true;
}

/// A test with its own empty folder (removed afterwards) in which sculpt-cli runs.
class CliFixture : public ::testing::Test {
 protected:
  /// The folder is `<temp>/<prefix><pid>_<test name>`.
  explicit CliFixture(std::string prefix) : prefix_(std::move(prefix)) {}

  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (prefix_ + std::to_string(::getpid()) + "_" + info->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// Runs sculpt-cli with already-quoted arguments; stdout and stderr are captured apart.
  CliResult run(const std::string& args) const {
    const std::filesystem::path out = dir_ / "stdout.txt";
    const std::filesystem::path err = dir_ / "stderr.txt";
    // exec: the shell is replaced by the program, so a crash shows as a signal, not as 128+n.
    const std::string command =
        "exec " + quote(kCli) + " " + args + " >" + quote(out) + " 2>" + quote(err);
    const int status = std::system(command.c_str());
    CliResult result;
    result.signaled = WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) >= 128);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    result.out = readText(out);
    result.err = readText(err);
    return result;
  }

  /// Expects exit 2 with exactly one "error: " line on stderr that contains `mention`.
  void expectBadInput(const std::string& args, const std::string& mention) const {
    SCOPED_TRACE(args);
    const CliResult result = run(args);
    EXPECT_FALSE(result.signaled) << result.err;
    EXPECT_EQ(result.exitCode, 2) << result.err;
    const auto lines = result.errLines();
    ASSERT_EQ(lines.size(), 1u) << result.err;
    EXPECT_EQ(lines[0].rfind("error: ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(mention), std::string::npos) << lines[0];
  }

  /// `name` inside the test's folder.
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace sculpt::test
