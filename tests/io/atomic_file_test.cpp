// Atomic writes leave either the old file or the new one, never a partial file or a stray
// temporary.

#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "io/file_error.h"

namespace sculpt {
namespace {

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("sculpt_atomic_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  size_t entries() const {
    return static_cast<size_t>(std::distance(std::filesystem::directory_iterator(dir_),
                                             std::filesystem::directory_iterator()));
  }
  std::filesystem::path dir_;
};

TEST_F(AtomicFileTest, WritesReplacesAndReadsBack) {
  const auto path = dir_ / "a.txt";
  writeFileAtomically(path, "first");
  EXPECT_EQ(readFile(path), "first");
  const std::string big(3'000'000, 'x');
  writeFileAtomically(path, big);
  EXPECT_EQ(readFile(path), big);
  writeFileAtomically(path, std::string("with\0nul", 8));
  EXPECT_EQ(readFile(path), std::string("with\0nul", 8));
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, FailureNamesTheFileAndLeavesNothingBehind) {
  try {
    writeFileAtomically(dir_ / "missing_dir" / "b.txt", "x");
    ADD_FAILURE() << "no error";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("b.txt"), std::string::npos) << error.what();
  }
  // Renaming onto a directory fails after the temporary file was written: it must be removed.
  std::filesystem::create_directories(dir_ / "c.txt");
  EXPECT_THROW(writeFileAtomically(dir_ / "c.txt", "x"), FileError);
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, ReadErrorsAreFileErrors) {
  try {
    readFile(dir_ / "nothing.json");
    ADD_FAILURE() << "no error";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("nothing.json: cannot open"), std::string::npos);
  }
  EXPECT_THROW(readFile(dir_), FileError);
  EXPECT_EQ(readFile("/dev/null"), "");
}

}  // namespace
}  // namespace sculpt
