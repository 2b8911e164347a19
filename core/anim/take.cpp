#include "anim/take.h"

#include <stdexcept>
#include <utility>

namespace sculpt {

uint32_t Take::segmentOf(uint32_t frame) const {
  for (uint32_t s = 0; s < segments_.size(); ++s)
    if (frame < segments_[s].frames.first + segments_[s].frames.count) return s;
  throw std::out_of_range("frame " + std::to_string(frame) + " is not in the take");
}

const CellFields* Take::fieldsAt(uint32_t frame) const {
  const CellFields* found = nullptr;
  for (const TakeFields& f : fields_)
    if (f.firstFrame <= frame) found = f.fields.get();
  return found;
}

void Take::controlPoints(uint32_t frame, Points& control) const {
  if (frame >= frameCount())
    throw std::out_of_range("frame " + std::to_string(frame) + " is not in the take");
  const uint64_t begin = frameOffset_[frame];
  const uint64_t end = frame + 1 < frameCount() ? frameOffset_[frame + 1] : control_.size();
  const Eigen::Index rows = static_cast<Eigen::Index>((end - begin) / 3);
  control.resize(rows, 3);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (int d = 0; d < 3; ++d) control(i, d) = control_[begin + 3 * i + d];
}

void Take::append(const std::shared_ptr<const SceneSurfaceMap>& surface, const Points& control) {
  if (frameCount() >= kMaxTakeFrames)
    throw std::length_error("a take holds at most " + std::to_string(kMaxTakeFrames) + " frames");
  if (control.rows() != surface->numControlPoints())
    throw std::invalid_argument("the control points do not belong to the scene");
  if (segments_.empty() || segments_.back().surface != surface)
    segments_.push_back({surface, {frameCount(), 0}});
  ++segments_.back().frames.count;
  frameOffset_.push_back(control_.size());
  for (Eigen::Index i = 0; i < control.rows(); ++i)
    for (int d = 0; d < 3; ++d) control_.push_back(static_cast<float>(control(i, d)));
}

void Take::setFields(std::shared_ptr<const CellFields> fields) {
  if (!fields_.empty() && fields_.back().firstFrame == frameCount()) {
    fields_.back().fields = std::move(fields);
    return;
  }
  fields_.push_back({frameCount(), std::move(fields)});
}

size_t Take::memoryBytes() const {
  size_t bytes = control_.capacity() * sizeof(float) + frameOffset_.capacity() * sizeof(uint64_t);
  for (const TakeFields& f : fields_)
    bytes += (f.fields->youngs.size() + f.fields->density.size() + f.fields->damping.size()) *
             sizeof(float);
  return bytes;
}

}  // namespace sculpt
