#include "sculpt/video_encoder.h"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <sstream>
#include <utility>

#include "io/file_error.h"
#include "util/shell_command.h"

namespace sculpt::app {

VideoEncoder::VideoEncoder(std::filesystem::path path, int width, int height, double fps)
    : path_(std::move(path)), width_(width), height_(height) {
  if (width_ <= 0 || height_ <= 0 || width_ % 2 != 0 || height_ % 2 != 0)
    throw FileError(path_.string() + ": H.264 in yuv420p needs an even width and height (got " +
                    std::to_string(width_) + "x" + std::to_string(height_) + ")");
  // ffmpeg picks the container from the name: the temporary one keeps the .mp4 ending.
  temporary_ =
      path_.parent_path() / ("." + path_.stem().string() + ".partial" + path_.extension().string());
  std::ostringstream command;
  command << "ffmpeg -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgba -s " << width_ << "x"
          << height_ << " -r " << fps << " -i - -c:v libx264 -pix_fmt yuv420p -movflags +faststart "
          << shellQuote(temporary_.string());
  // A dead ffmpeg must fail the write, not kill this process.
  std::signal(SIGPIPE, SIG_IGN);
  pipe_ = ::popen(command.str().c_str(), "w");
  if (!pipe_) throw FileError(path_.string() + ": cannot start ffmpeg");
}

VideoEncoder::~VideoEncoder() { abandon(); }

void VideoEncoder::abandon() {
  if (pipe_) ::pclose(pipe_);
  pipe_ = nullptr;
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void VideoEncoder::write(std::span<const uint8_t> rgba) {
  const size_t bytes = static_cast<size_t>(width_) * static_cast<size_t>(height_) * 4;
  if (!pipe_ || rgba.size() != bytes || std::fwrite(rgba.data(), 1, bytes, pipe_) != bytes) {
    abandon();
    throw FileError(path_.string() + ": ffmpeg stopped taking frames");
  }
}

uint64_t VideoEncoder::finish() {
  if (!pipe_) throw FileError(path_.string() + ": the video was abandoned");
  const int status = ::pclose(std::exchange(pipe_, nullptr));
  std::error_code error;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove(temporary_, error);
    throw FileError(path_.string() + ": ffmpeg failed (exit status " +
                    std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  }
  std::filesystem::rename(temporary_, path_, error);
  if (error) {
    const std::string reason = error.message();
    std::filesystem::remove(temporary_, error);
    throw FileError(path_.string() + ": cannot move the video into place: " + reason);
  }
  return std::filesystem::file_size(path_);
}

}  // namespace sculpt::app
