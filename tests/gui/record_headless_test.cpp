// sculpt --headless --record-seconds: a small control-mesh scene recorded 1 s at 10 fps into a
// PNG sequence (frames from 1, the window's size) and an H.264 video checked with ffprobe; and
// the one sentence when ffmpeg is missing.

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/scratch_directory.h"

namespace {

namespace fs = std::filesystem;
const std::string kSculpt = SCULPT_BINARY_DIR "/bin/sculpt";
const std::string kScene = SCULPT_SOURCE_DIR "/assets/block3.json";

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Outcome {
  int status = -1;
  std::string out, err;
};

Outcome run(const fs::path& dir, const std::string& args, const std::string& env = {}) {
  // Preferences go to the test's folder, never to the user's configuration.
  const std::string command = "XDG_CONFIG_HOME=" + dir.string() + " " + env + " " + kSculpt + " " +
                              args + " > " + (dir / "out.txt").string() + " 2> " +
                              (dir / "err.txt").string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "out.txt"),
          slurp(dir / "err.txt")};
}

std::string lastLine(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

TEST(RecordHeadless, WritesAPngSequenceAndAnH264VideoOfTheTake) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "no X display: run under xvfb-run";
  ASSERT_EQ(std::system("command -v ffprobe > /dev/null 2>&1"), 0)
      << "ffprobe (ffmpeg) is missing: scripts/install-deps.sh installs ffmpeg";
  sculpt::test::ScratchDirectory scratch("record_headless");
  const fs::path dir = scratch.path();
  const Outcome r =
      run(dir, "--headless --scene " + kScene + " --size 320x240 --record-seconds 1 --fps 10" +
                   " --record-out " + (dir / "frame_####.png").string() + " --record-out " +
                   (dir / "take.mp4").string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::printf("[ output ] %s\n", lastLine(r.out).c_str());
  EXPECT_EQ(lastLine(r.out).rfind("frames=11 seconds=1 vertices=", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(" keys=0 bytes="), std::string::npos) << r.out;
  for (int k = 1; k <= 11; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", k);
    int width = 0, height = 0, channels = 0;
    ASSERT_TRUE(stbi_info((dir / name).c_str(), &width, &height, &channels)) << name;
    EXPECT_EQ(width, 320) << name;
    EXPECT_EQ(height, 240) << name;
  }
  EXPECT_FALSE(fs::exists(dir / "frame_0000.png"));
  EXPECT_FALSE(fs::exists(dir / "frame_0012.png"));
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find("partial"), std::string::npos) << entry.path();

  const std::string probe =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,pix_fmt,nb_read_frames,width,height -of csv=p=0 " +
      (dir / "take.mp4").string() + " > " + (dir / "probe.txt").string();
  ASSERT_EQ(std::system(probe.c_str()), 0);
  const std::string fields = lastLine(slurp(dir / "probe.txt"));
  std::printf("[ ffprobe ] %s\n", fields.c_str());
  // ffprobe prints the fields in its own order: codec, size, pixel format, frames read.
  EXPECT_EQ(fields, "h264,320,240,yuv420p,11");
}

TEST(RecordHeadless, Mp4WithoutFfmpegIsOneSentenceAndExitStatus2) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "no X display: run under xvfb-run";
  sculpt::test::ScratchDirectory scratch("record_headless_no_ffmpeg");
  const fs::path dir = scratch.path();
  const fs::path video = dir / "take.mp4";
  const Outcome r = run(dir, "--headless --scene " + kScene + " --size 320x240 --record-seconds 1" +
                             " --record-out " + video.string(), "PATH=" + (dir / "empty").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "error: " + video.string() +
                ": writing .mp4 needs the ffmpeg program (scripts/install-deps.sh installs it)\n");
  EXPECT_FALSE(fs::exists(video));
}

}  // namespace
