// Sequence file name patterns: one run of '#' becomes the 1-based, zero-padded frame number.

#include "anim/frame_pattern.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace sculpt {
namespace {

TEST(FramePattern, ReplacesTheRunWithThePaddedFrameNumber) {
  const FramePattern pattern = framePatternOrThrow("out/name_####.obj");
  EXPECT_EQ(framePath(pattern, 1), std::filesystem::path("out/name_0001.obj"));
  EXPECT_EQ(framePath(pattern, 42), std::filesystem::path("out/name_0042.obj"));
  EXPECT_EQ(framePath(pattern, 12345), std::filesystem::path("out/name_12345.obj"));
  EXPECT_EQ(framePath(framePatternOrThrow("f#.vtk"), 7), std::filesystem::path("f7.vtk"));
  EXPECT_EQ(framePath(framePatternOrThrow("f#.vtk"), 10), std::filesystem::path("f10.vtk"));
}

TEST(FramePattern, OnlyTheFileNameCounts) {
  EXPECT_TRUE(isFramePattern("take#1/name_##.obj"));
  EXPECT_EQ(framePath(framePatternOrThrow("take#1/name_##.obj"), 3),
            std::filesystem::path("take#1/name_03.obj"));
  EXPECT_FALSE(isFramePattern("take#1/name.obj"));
}

TEST(FramePattern, RefusesNoRunOrTwoRuns) {
  EXPECT_FALSE(isFramePattern("name.obj"));
  EXPECT_FALSE(isFramePattern("a_##_##.obj"));
  EXPECT_FALSE(parseFramePattern("a_##_##.obj").has_value());
  try {
    framePatternOrThrow("name.obj");
    FAIL() << "accepted a name without #";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "'name.obj' is not a sequence pattern: put #### where the frame number goes, "
                 "e.g. name_####.obj");
  }
  try {
    framePatternOrThrow("a_##_##.obj");
    FAIL() << "accepted two runs";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "'a_##_##.obj' is not a sequence pattern: put #### where the frame number goes, "
                 "e.g. a_####.obj");
  }
}

TEST(FramePattern, CollectionDropsTheRunAndItsSeparator) {
  EXPECT_EQ(collectionPath(framePatternOrThrow("out/name_####.vtk"), ".pvd"),
            std::filesystem::path("out/name.pvd"));
  EXPECT_EQ(collectionPath(framePatternOrThrow("out/name_####.vtk"), ".vtk.series"),
            std::filesystem::path("out/name.vtk.series"));
  EXPECT_EQ(collectionPath(framePatternOrThrow("name-##.vtu"), ".pvd"),
            std::filesystem::path("name.pvd"));
  EXPECT_EQ(collectionPath(framePatternOrThrow("name.###.vtu"), ".pvd"),
            std::filesystem::path("name.pvd"));
  EXPECT_EQ(collectionPath(framePatternOrThrow("name##.vtu"), ".pvd"),
            std::filesystem::path("name.pvd"));
  EXPECT_EQ(collectionPath(framePatternOrThrow("####.vtk"), ".pvd"),
            std::filesystem::path("frames.pvd"));
}

}  // namespace
}  // namespace sculpt
