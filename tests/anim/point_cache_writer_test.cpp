// The PC2 and MDD writers, read back by hand from their byte layouts (Blender's Mesh Cache
// modifier reads the same headers) and checked against the take frame by frame.

#include "anim/point_cache_writer.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <string>

#include "anim/export_test_files.h"
#include "anim/fake_animated_surface.h"
#include "io/file_error.h"
#include "support/scratch_directory.h"

namespace sculpt {
namespace {

using test::FakeAnimatedSurface;

std::string scratchName(const char* name) { return std::string("sculpt_point_cache_") + name; }

TEST(Pc2Writer, WritesEveryFrameBitForBit) {
  test::ScratchDirectory dir(scratchName("pc2"));
  const FakeAnimatedSurface take(6, 24.0);
  const auto path = dir.path() / "wave.pc2";
  const ExportResult result = writePc2(take, path);

  const std::string bytes = test::fileBytes(path);
  const uint32_t vertices = take.restSurface(0).numVertices();
  ASSERT_EQ(bytes.size(), 32u + 6u * vertices * 12u);
  EXPECT_EQ(std::memcmp(bytes.data(), "POINTCACHE2\0", 12), 0);
  EXPECT_EQ(test::littleEndian32(bytes, 12), 1u);  // file version
  EXPECT_EQ(test::littleEndian32(bytes, 16), vertices);
  EXPECT_EQ(std::bit_cast<float>(test::littleEndian32(bytes, 20)), 1.0f);  // start frame
  EXPECT_EQ(std::bit_cast<float>(test::littleEndian32(bytes, 24)), 1.0f);  // sampling
  EXPECT_EQ(test::littleEndian32(bytes, 28), 6u);
  SurfaceFrameData frame;
  for (uint32_t f = 0; f < 6; ++f) {
    take.evaluateSurface(f, frame);
    for (size_t i = 0; i < frame.positions.size(); ++i) {
      const size_t at = 32 + (f * size_t{vertices} * 3 + i) * 4;
      ASSERT_EQ(test::littleEndian32(bytes, at), std::bit_cast<uint32_t>(frame.positions[i]))
          << "frame " << f << " value " << i;
    }
  }
  EXPECT_EQ(result.files, std::vector<std::filesystem::path>{path});
  EXPECT_EQ(result.bytes, bytes.size());
  EXPECT_EQ(result.frames, 6u);
  EXPECT_FALSE(result.cancelled);
  EXPECT_EQ(test::fileNames(dir.path()), std::set<std::string>{"wave.pc2"});
}

TEST(MddWriter, WritesTimesAndEveryFrameBigEndian) {
  test::ScratchDirectory dir(scratchName("mdd"));
  const FakeAnimatedSurface take(5, 30.0);
  const auto path = dir.path() / "wave.mdd";
  const ExportResult result = writeMdd(take, path);

  const std::string bytes = test::fileBytes(path);
  const uint32_t vertices = take.restSurface(0).numVertices();
  ASSERT_EQ(bytes.size(), 8u + 5u * 4u + 5u * vertices * 12u);
  EXPECT_EQ(test::bigEndian32(bytes, 0), 5u);
  EXPECT_EQ(test::bigEndian32(bytes, 4), vertices);
  for (uint32_t f = 0; f < 5; ++f) {
    EXPECT_EQ(test::bigEndianFloat(bytes, 8 + 4 * f), static_cast<float>(f / 30.0));
  }
  SurfaceFrameData frame;
  const size_t data = 8 + 5 * 4;
  for (uint32_t f = 0; f < 5; ++f) {
    take.evaluateSurface(f, frame);
    for (size_t i = 0; i < frame.positions.size(); ++i) {
      const size_t at = data + (f * size_t{vertices} * 3 + i) * 4;
      ASSERT_EQ(test::bigEndian32(bytes, at), std::bit_cast<uint32_t>(frame.positions[i]))
          << "frame " << f << " value " << i;
    }
  }
  EXPECT_EQ(result.bytes, bytes.size());
  EXPECT_EQ(result.frames, 5u);
}

TEST(Pc2Writer, RefusesATakeThatChangesItsVertexCount) {
  test::ScratchDirectory dir(scratchName("pc2_topology"));
  const FakeAnimatedSurface take(6, 24.0, 2);  // segment 2 starts at frame 4, one column wider
  for (const auto write : {&writePc2, &writeMdd}) {
    const auto path = dir.path() / "wave.cache";
    try {
      write(take, path, nullptr);
      FAIL() << "a 2-segment take was written";
    } catch (const FileError& error) {
      EXPECT_EQ(std::string(error.what()),
                path.string() +
                    ": a point cache needs one vertex count; the take changes topology at frame "
                    "4 (use .glb or a sequence)");
    }
    EXPECT_TRUE(test::fileNames(dir.path()).empty());
  }
}

TEST(Pc2Writer, CancelLeavesTheExistingFileUnchanged) {
  test::ScratchDirectory dir(scratchName("pc2_cancel"));
  const FakeAnimatedSurface take(6, 24.0);
  for (const auto write : {&writePc2, &writeMdd}) {
    const auto path = dir.path() / "wave.cache";
    { std::ofstream(path) << "the previous export"; }
    ProgressReporter progress = test::cancelAfter(2);
    const ExportResult result = write(take, path, &progress);
    EXPECT_TRUE(result.cancelled);
    EXPECT_TRUE(result.files.empty());
    EXPECT_EQ(result.frames, 0u);
    EXPECT_EQ(test::fileBytes(path), "the previous export");
    EXPECT_EQ(test::fileNames(dir.path()), std::set<std::string>{"wave.cache"});
  }
}

TEST(Pc2Writer, ReportsEveryFrame) {
  test::ScratchDirectory dir(scratchName("pc2_progress"));
  const FakeAnimatedSurface take(4, 24.0);
  std::vector<double> fractions;
  ProgressReporter progress([&](double fraction, std::string_view) {
    fractions.push_back(fraction);
    return true;
  });
  writeMdd(take, dir.path() / "wave.mdd", &progress);
  EXPECT_EQ(fractions, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
}

TEST(Pc2Writer, UnwritablePathThrowsAndLeavesNothing) {
  test::ScratchDirectory dir(scratchName("pc2_unwritable"));
  const FakeAnimatedSurface take(3, 24.0);
  const auto path = dir.path() / "missing" / "wave.pc2";
  try {
    writePc2(take, path);
    FAIL() << "wrote into a directory that does not exist";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
  }
  EXPECT_TRUE(test::fileNames(dir.path()).empty());
  EXPECT_THROW(writeMdd(take, "/proc/nonexistent/x.mdd"), FileError);
}

// A write that fails part way (the file size limit stands in for a full disk) names the file
// and removes the partial file. Run in a child process: the limit is per process.
TEST(Pc2Writer, FailedWriteThrowsAndRemovesThePartialFile) {
  test::ScratchDirectory dir(scratchName("pc2_full"));
  const auto path = dir.path() / "wave.pc2";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{200, 200};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    int code = 1;
    try {
      writePc2(FakeAnimatedSurface(6, 24.0), path);
    } catch (const FileError& error) {
      const std::string what = error.what();
      if (what.find(path.string() + ": cannot write") == 0 && test::fileNames(dir.path()).empty())
        code = 0;
    }
    ::_exit(code);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_TRUE(test::fileNames(dir.path()).empty());
}

TEST(Pc2Writer, TwoRunsWriteIdenticalBytes) {
  test::ScratchDirectory dir(scratchName("pc2_repeat"));
  const FakeAnimatedSurface take(5, 24.0);
  for (const auto write : {&writePc2, &writeMdd}) {
    write(take, dir.path() / "a", nullptr);
    write(take, dir.path() / "b", nullptr);
    EXPECT_EQ(test::fileBytes(dir.path() / "a"), test::fileBytes(dir.path() / "b"));
  }
}

}  // namespace
}  // namespace sculpt
