#include "sculpt/rendered_frames.h"

#include <algorithm>
#include <system_error>
#include <utility>

#include "render/png_image.h"

namespace sculpt::app {

RenderedFrames::RenderedFrames(std::vector<std::filesystem::path> pngs,
                               std::vector<std::filesystem::path> videos, double fps)
    : videos_(std::move(videos)), fps_(fps) {
  for (const std::filesystem::path& pattern : pngs) pngs_.push_back(framePatternOrThrow(pattern));
}

RenderedFrames::~RenderedFrames() {
  if (finished_) return;
  encoders_.clear();  // each removes its temporary file
  std::error_code ignored;
  for (const std::filesystem::path& file : written_) std::filesystem::remove(file, ignored);
}

void RenderedFrames::write(uint32_t number, const std::vector<uint8_t>& pixels, int width,
                           int height) {
  for (const FramePattern& pattern : pngs_) {
    const std::filesystem::path file = framePath(pattern, number);
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    written_.push_back(file);  // before writing: a half-written frame goes on failure too
    render::writePng(file, width, height, pixels);
    bytes_ += std::filesystem::file_size(file);
  }
  if (encoders_.empty())
    for (const std::filesystem::path& video : videos_)  // yuv420p: even sizes
      encoders_.push_back(std::make_unique<VideoEncoder>(video, width & ~1, height & ~1, fps_));
  if (encoders_.empty()) return;
  const int ew = std::min(encoders_.front()->width(), width & ~1);
  const int eh = std::min(encoders_.front()->height(), height & ~1);
  std::vector<uint8_t> cropped(4 * static_cast<size_t>(encoders_.front()->width()) *
                                   static_cast<size_t>(encoders_.front()->height()),
                               0);
  for (int y = 0; y < eh; ++y)
    std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(4 * static_cast<size_t>(y) * width),
                4 * ew,
                cropped.begin() + static_cast<std::ptrdiff_t>(
                                      4 * static_cast<size_t>(y) * encoders_.front()->width()));
  for (const auto& encoder : encoders_) encoder->write(cropped);
}

uint64_t RenderedFrames::finish() {
  for (const auto& encoder : encoders_) bytes_ += encoder->finish();
  written_.insert(written_.end(), videos_.begin(), videos_.end());
  finished_ = true;
  return bytes_;
}

}  // namespace sculpt::app
