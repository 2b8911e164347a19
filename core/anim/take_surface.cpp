#include "anim/take_surface.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sculpt {

TakeSurface::TakeSurface(std::shared_ptr<const Take> take, FrameRange range, uint32_t every,
                         InterpolationMethod method)
    : take_(std::move(take)), range_(range), every_(every), method_(method) {
  const uint32_t frames = take_ ? take_->frameCount() : 0;
  if (frames == 0) throw std::invalid_argument("the take has no frames");
  if (every_ == 0) throw std::invalid_argument("every 0th frame is no frame rate");
  if (range_.count == 0 && range_.first < frames) range_.count = frames - range_.first;
  if (range_.first >= frames || range_.count > frames - range_.first)
    throw std::invalid_argument("frames " + std::to_string(range_.first + 1) + " to " +
                                std::to_string(range_.first + range_.count) +
                                " are not in the take of " + std::to_string(frames) + " frames");
  const auto shownFrom = [this](uint32_t takeFrame) {  // the first shown frame at or after it
    return framesEvery(takeFrame - range_.first, every_);
  };
  frames_ = framesEvery(range_.count, every_);
  const uint32_t end = range_.first + range_.count;
  for (const TakeSegment& s : take_->segments()) {
    const uint32_t first = shownFrom(std::max(s.frames.first, range_.first));
    const uint32_t last =
        shownFrom(std::max(std::min(s.frames.first + s.frames.count, end), range_.first));
    if (first >= last) continue;
    Segment segment;
    segment.surface = s.surface;
    segment.frames = {first, last - first};
    const SceneGeometry& g = s.surface->geometry();
    if (!g.surface) throw std::logic_error("the recorded scene has no surface");
    segment.restNormals.resize(3 * static_cast<size_t>(g.restNormals.rows()));
    for (Eigen::Index v = 0; v < g.restNormals.rows(); ++v)
      for (int d = 0; d < 3; ++d)
        segment.restNormals[3 * v + d] = static_cast<float>(g.restNormals(v, d));
    if (g.surface->normals.rows() > 0) segment.normalAnchors = normalAnchors(*g.surface);
    segment.vertexAnchors.resize(g.restPositions.rows());
    for (uint32_t v = 0; v < segment.vertexAnchors.size(); ++v) segment.vertexAnchors[v] = v;
    segments_.push_back(std::move(segment));
  }
}

TakeSurface::~TakeSurface() = default;

const SurfaceMesh& TakeSurface::restSurface(uint32_t s) const {
  return *segments_[s].surface->geometry().surface;
}
const std::vector<float>& TakeSurface::restVertexNormals(uint32_t s) const {
  return segments_[s].restNormals;
}
const std::vector<uint32_t>& TakeSurface::triangles(uint32_t s) const {
  return segments_[s].surface->geometry().triangles;
}
const VolumeMesh& TakeSurface::restSolid(uint32_t s) const {
  return segments_[s].surface->geometry().cellMesh;
}

uint32_t TakeSurface::maxVertices() const {
  uint32_t most = 0;
  for (const Segment& s : segments_)
    most = std::max(most, static_cast<uint32_t>(s.surface->geometry().restPositions.rows()));
  return most;
}

const TakeSurface::Segment& TakeSurface::segmentFor(uint32_t frame) const {
  if (frame >= frames_)
    throw std::out_of_range("frame " + std::to_string(frame) + " is not in the take");
  return segments_[segmentOf(frame)];
}

EmbeddedDeformer& TakeSurface::deformer(const Segment& segment) const {
  if (!segment.deformer) {
    const SceneGeometry& g = segment.surface->geometry();
    DeformerSettings settings;
    settings.buildAttributeWeights = false;
    segment.deformer = std::make_unique<EmbeddedDeformer>(g.cellMesh, g.restPositions,
                                                          g.embedding, settings);
  }
  return *segment.deformer;
}

namespace {
void toFloats(const Points& values, std::vector<float>& out) {
  out.resize(3 * static_cast<size_t>(values.rows()));
  for (Eigen::Index i = 0; i < values.rows(); ++i)
    for (int d = 0; d < 3; ++d) out[3 * i + d] = static_cast<float>(values(i, d));
}
}  // namespace

void TakeSurface::evaluateSurface(uint32_t frame, SurfaceFrameData& out) const {
  const Segment& segment = segmentFor(frame);
  take_->controlPoints(takeFrame(frame), control_);
  segment.surface->cellNodes(control_, nodes_);
  EmbeddedDeformer& d = deformer(segment);
  d.setFrame(nodes_, method_);
  toFloats(d.positions(), out.positions);
  if (!out.withNormals) {
    out.normals.clear();
    out.sourceNormals.clear();
    return;
  }
  const SceneGeometry& g = segment.surface->geometry();
  toFloats(d.deformNormals(g.restNormals, segment.vertexAnchors), out.normals);
  if (segment.normalAnchors.empty())
    out.sourceNormals.clear();
  else
    toFloats(d.deformNormals(g.surface->normals, segment.normalAnchors), out.sourceNormals);
}

void TakeSurface::evaluateSolid(uint32_t frame, SolidFrameData& out) const {
  const Segment& segment = segmentFor(frame);
  take_->controlPoints(takeFrame(frame), control_);
  segment.surface->cellNodes(control_, out.nodes);
  out.displacement = out.nodes - segment.surface->geometry().cellMesh.positions;
  if (const CellFields* fields = take_->fieldsAt(takeFrame(frame)))
    out.fields = *fields;
  else
    out.fields = CellFields{};
}

}  // namespace sculpt
