#include "project/undo_history.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace sculpt {
namespace {

// Changed control-point rows (same vertex count and cells before and after).
struct PositionDelta {
  std::vector<uint32_t> vertices;
  std::vector<double> before, after;  // 3 per vertex
};
struct TagSwap {
  std::vector<std::array<uint32_t, 2>> creasesBefore, creasesAfter;
  std::vector<uint32_t> cornersBefore, cornersAfter;
};
// Changed samples of an unchanged sample set.
struct SampleDelta {
  std::vector<uint32_t> indices;
  std::vector<Material> before, after;
};
struct PinDelta {
  std::vector<uint32_t> added, removed;  // ascending
};
template <typename T>
struct Swap {
  T before, after;
};

bool sameCells(const CellComplex& a, const CellComplex& b) {
  return a.positions.rows() == b.positions.rows() && a.cellFaceBegin == b.cellFaceBegin &&
         a.loopBegin == b.loopBegin && a.loopVertices == b.loopVertices;
}

bool sameRow(const Points& a, const Points& b, Eigen::Index row) {
  return sameBits(a(row, 0), b(row, 0)) && sameBits(a(row, 1), b(row, 1)) &&
         sameBits(a(row, 2), b(row, 2));
}

bool samePoints(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (!sameBits(a[i][k], b[i][k])) return false;
    }
  }
  return true;
}

template <typename T>
size_t vectorBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}
size_t meshBytes(const CellComplex& m) {
  return static_cast<size_t>(m.positions.size()) * sizeof(double) + vectorBytes(m.cellFaceBegin) +
         vectorBytes(m.loopBegin) + vectorBytes(m.loopVertices) + vectorBytes(m.creases) +
         vectorBytes(m.corners);
}
size_t samplesBytes(const MaterialSamples& s) {
  return vectorBytes(s.restPositions) + vectorBytes(s.materials);
}

bool contains(const std::vector<uint32_t>& sorted, uint32_t value) {
  return std::binary_search(sorted.begin(), sorted.end(), value);
}

[[noreturn]] void mismatch(const char* what) {
  throw std::logic_error(std::string("cannot undo or redo: the project's ") + what +
                         " changed without being recorded in the history");
}

}  // namespace

struct UndoHistory::Entry {
  std::string label;
  std::optional<PositionDelta> positions;
  std::optional<TagSwap> tags;
  std::optional<Swap<CellComplex>> mesh;
  std::optional<SampleDelta> samples;
  std::optional<Swap<MaterialSamples>> sampleSet;
  std::optional<PinDelta> pins;
  std::optional<Swap<SurfaceSource>> surface;
  size_t bytes = 0;

  bool empty() const {
    return !positions && !tags && !mesh && !samples && !sampleSet && !pins && !surface;
  }
  size_t estimateBytes() const {
    size_t total = sizeof(Entry) + label.capacity();
    if (positions) {
      total += vectorBytes(positions->vertices) + vectorBytes(positions->before) +
               vectorBytes(positions->after);
    }
    if (tags) {
      total += vectorBytes(tags->creasesBefore) + vectorBytes(tags->creasesAfter) +
               vectorBytes(tags->cornersBefore) + vectorBytes(tags->cornersAfter);
    }
    if (mesh) total += meshBytes(mesh->before) + meshBytes(mesh->after);
    if (samples) {
      total += vectorBytes(samples->indices) + vectorBytes(samples->before) +
               vectorBytes(samples->after);
    }
    if (sampleSet) total += samplesBytes(sampleSet->before) + samplesBytes(sampleSet->after);
    if (pins) total += vectorBytes(pins->added) + vectorBytes(pins->removed);
    if (surface) {
      for (const SurfaceSource* s : {&surface->before, &surface->after}) {
        total += s->path.capacity() + s->contentHash.capacity() + s->objText.capacity();
      }
    }
    return total;
  }
};

UndoHistory::UndoHistory(Limits limits) : limits_(limits) {}
UndoHistory::UndoHistory() : UndoHistory(Limits{}) {}
UndoHistory::~UndoHistory() = default;
UndoHistory::UndoHistory(UndoHistory&&) noexcept = default;
UndoHistory& UndoHistory::operator=(UndoHistory&&) noexcept = default;

bool UndoHistory::record(std::string label, const Project& before, const Project& after) {
  auto entry = std::make_unique<Entry>();
  entry->label = std::move(label);

  // Control mesh: a delta of moved points and the tags, or the whole mesh for a topology edit.
  const CellComplex& m0 = before.controlMesh;
  const CellComplex& m1 = after.controlMesh;
  if (sameCells(m0, m1)) {
    PositionDelta delta;
    for (Eigen::Index v = 0; v < m0.positions.rows(); ++v) {
      if (sameRow(m0.positions, m1.positions, v)) continue;
      delta.vertices.push_back(static_cast<uint32_t>(v));
      for (int k = 0; k < 3; ++k) {
        delta.before.push_back(m0.positions(v, k));
        delta.after.push_back(m1.positions(v, k));
      }
    }
    if (!delta.vertices.empty()) entry->positions = std::move(delta);
    if (m0.creases != m1.creases || m0.corners != m1.corners) {
      entry->tags = TagSwap{m0.creases, m1.creases, m0.corners, m1.corners};
    }
  } else {
    entry->mesh = Swap<CellComplex>{m0, m1};
  }

  // Materials: changed samples, or the whole set when it was resampled to other points.
  const MaterialSamples& s0 = before.materials;
  const MaterialSamples& s1 = after.materials;
  if (s0.level == s1.level && s0.materials.size() == s1.materials.size() &&
      samePoints(s0.restPositions, s1.restPositions)) {
    SampleDelta delta;
    for (size_t i = 0; i < s0.materials.size(); ++i) {
      if (sameBits(s0.materials[i], s1.materials[i])) continue;
      delta.indices.push_back(static_cast<uint32_t>(i));
      delta.before.push_back(s0.materials[i]);
      delta.after.push_back(s1.materials[i]);
    }
    if (!delta.indices.empty()) entry->samples = std::move(delta);
  } else {
    entry->sampleSet = Swap<MaterialSamples>{s0, s1};
  }

  // Pins: what was added and what was removed.
  std::vector<uint32_t> p0 = before.pins, p1 = after.pins;
  normalisePins(p0);
  normalisePins(p1);
  PinDelta pins;
  std::set_difference(p1.begin(), p1.end(), p0.begin(), p0.end(), std::back_inserter(pins.added));
  std::set_difference(p0.begin(), p0.end(), p1.begin(), p1.end(), std::back_inserter(pins.removed));
  if (!pins.added.empty() || !pins.removed.empty()) entry->pins = std::move(pins);

  if (!(before.surface == after.surface)) {
    entry->surface = Swap<SurfaceSource>{before.surface, after.surface};
  }

  if (entry->empty()) return false;
  if (entry->positions) {
    entry->positions->vertices.shrink_to_fit();
    entry->positions->before.shrink_to_fit();
    entry->positions->after.shrink_to_fit();
  }
  if (entry->samples) {
    entry->samples->indices.shrink_to_fit();
    entry->samples->before.shrink_to_fit();
    entry->samples->after.shrink_to_fit();
  }
  entry->bytes = entry->estimateBytes();

  // A new edit ends the redo tail; then the oldest entries go until the limits hold.
  while (entries_.size() > done_) {
    bytes_ -= entries_.back()->bytes;
    entries_.pop_back();
  }
  bytes_ += entry->bytes;
  entries_.push_back(std::move(entry));
  done_ = entries_.size();
  while (!entries_.empty() && (entries_.size() > limits_.maxSteps ||
                               (entries_.size() > 1 && bytes_ > limits_.maxBytes))) {
    bytes_ -= entries_.front()->bytes;
    entries_.pop_front();
    --done_;
  }
  return true;
}

std::string UndoHistory::undoLabel() const {
  return canUndo() ? entries_[done_ - 1]->label : std::string();
}

std::string UndoHistory::redoLabel() const {
  return canRedo() ? entries_[done_]->label : std::string();
}

bool UndoHistory::undo(Project& project) {
  if (!canUndo()) return false;
  apply(*entries_[done_ - 1], project, false);
  --done_;
  return true;
}

bool UndoHistory::redo(Project& project) {
  if (!canRedo()) return false;
  apply(*entries_[done_], project, true);
  ++done_;
  return true;
}

void UndoHistory::clear() {
  entries_.clear();
  done_ = 0;
  bytes_ = 0;
}

void UndoHistory::apply(const Entry& e, Project& project, bool forward) const {
  // Check every part first so that a mismatch leaves the project untouched. The parts apply in
  // the order mesh, samples, pins: pins name vertices of the mesh they are applied to.
  CellComplex& mesh = project.controlMesh;
  const CellComplex* meshFrom = e.mesh ? (forward ? &e.mesh->before : &e.mesh->after) : nullptr;
  const CellComplex* meshTo = e.mesh ? (forward ? &e.mesh->after : &e.mesh->before) : nullptr;
  if (meshFrom && (!sameCells(mesh, *meshFrom) || mesh.creases != meshFrom->creases ||
                   mesh.corners != meshFrom->corners)) {
    mismatch("control mesh");
  }
  if (e.positions) {
    if (!e.positions->vertices.empty() && e.positions->vertices.back() >= mesh.numVertices()) {
      mismatch("control mesh");
    }
  }
  if (e.tags) {
    const auto& creases = forward ? e.tags->creasesBefore : e.tags->creasesAfter;
    const auto& corners = forward ? e.tags->cornersBefore : e.tags->cornersAfter;
    if (mesh.creases != creases || mesh.corners != corners) mismatch("crease or corner tags");
  }
  MaterialSamples& samples = project.materials;
  if (e.samples) {
    if (!e.samples->indices.empty() && e.samples->indices.back() >= samples.materials.size()) {
      mismatch("material samples");
    }
  }
  if (e.sampleSet) {
    const MaterialSamples& from = forward ? e.sampleSet->before : e.sampleSet->after;
    if (from.level != samples.level || from.materials.size() != samples.materials.size()) {
      mismatch("material samples");
    }
  }
  if (e.pins) {
    const auto& mustHave = forward ? e.pins->removed : e.pins->added;
    const auto& mustLack = forward ? e.pins->added : e.pins->removed;
    std::vector<uint32_t> pins = project.pins;
    normalisePins(pins);
    for (const uint32_t p : mustHave) {
      if (!contains(pins, p)) mismatch("pins");
    }
    for (const uint32_t p : mustLack) {
      if (contains(pins, p)) mismatch("pins");
    }
  }

  // Apply.
  if (meshTo) mesh = *meshTo;
  if (e.positions) {
    const auto& values = forward ? e.positions->after : e.positions->before;
    for (size_t i = 0; i < e.positions->vertices.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        mesh.positions(e.positions->vertices[i], k) = values[3 * i + static_cast<size_t>(k)];
      }
    }
  }
  if (e.tags) {
    mesh.creases = forward ? e.tags->creasesAfter : e.tags->creasesBefore;
    mesh.corners = forward ? e.tags->cornersAfter : e.tags->cornersBefore;
  }
  if (e.sampleSet) samples = forward ? e.sampleSet->after : e.sampleSet->before;
  if (e.samples) {
    const auto& values = forward ? e.samples->after : e.samples->before;
    for (size_t i = 0; i < e.samples->indices.size(); ++i) {
      samples.materials[e.samples->indices[i]] = values[i];
    }
  }
  if (e.pins) {
    const auto& remove = forward ? e.pins->removed : e.pins->added;
    const auto& add = forward ? e.pins->added : e.pins->removed;
    std::vector<uint32_t>& pins = project.pins;
    pins.erase(
        std::remove_if(pins.begin(), pins.end(), [&](uint32_t p) { return contains(remove, p); }),
        pins.end());
    pins.insert(pins.end(), add.begin(), add.end());
    normalisePins(pins);
  }
  if (e.surface) project.surface = forward ? e.surface->after : e.surface->before;
}

}  // namespace sculpt
