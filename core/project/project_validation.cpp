#include "project/project_validation.h"

#include <cmath>
#include <string_view>
#include <string>
#include <variant>
#include <vector>

namespace sculpt {
namespace {

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

std::string offsetsProblem(const std::vector<uint32_t>& offsets, size_t total, const char* what) {
  if (offsets.empty() || offsets.front() != 0) return std::string(what) + " must start at 0";
  for (size_t i = 1; i < offsets.size(); ++i) {
    if (offsets[i] < offsets[i - 1]) {
      return std::string(what) + " decrease at entry " + std::to_string(i);
    }
  }
  if (offsets.back() != total) {
    return std::string(what) + " end at " + std::to_string(offsets.back()) + " but there are " +
           std::to_string(total) + " entries";
  }
  return {};
}

}  // namespace

// User text made safe for a one-line message: printable ASCII, bounded length.
std::string printable(std::string_view text) {
  std::string out;
  for (const char ch : text.substr(0, kMaxQuoted)) {
    const auto u = static_cast<unsigned char>(ch);
    out.push_back(u >= 0x20 && u < 0x7f ? ch : '?');
  }
  if (text.size() > kMaxQuoted) out += "...";
  return out;
}

std::string projectProblem(const Project& project) {
  const CellComplex& mesh = project.controlMesh;
  const size_t numVertices = static_cast<size_t>(mesh.positions.rows());
  if (!mesh.positions.allFinite()) return "a control point position is not a finite number";
  if (std::string p = offsetsProblem(mesh.loopBegin, mesh.loopVertices.size(), "face loop offsets");
      !p.empty()) {
    return p;
  }
  if (std::string p =
          offsetsProblem(mesh.cellFaceBegin, mesh.loopBegin.size() - 1, "cell face offsets");
      !p.empty()) {
    return p;
  }
  auto badVertex = [&](uint32_t v) { return v >= numVertices; };
  for (size_t i = 0; i < mesh.loopVertices.size(); ++i) {
    if (badVertex(mesh.loopVertices[i])) {
      return "face loop vertex " + std::to_string(i) + " is " +
             std::to_string(mesh.loopVertices[i]) + ", but there are " +
             std::to_string(numVertices) + " control points";
    }
  }
  for (size_t i = 0; i < mesh.creases.size(); ++i) {
    if (badVertex(mesh.creases[i][0]) || badVertex(mesh.creases[i][1])) {
      return "crease " + std::to_string(i) + " names a control point that does not exist";
    }
  }
  for (const uint32_t v : mesh.corners) {
    if (badVertex(v)) return "corner " + std::to_string(v) + " is not a control point";
  }
  for (size_t i = 0; i < project.pins.size(); ++i) {
    if (badVertex(project.pins[i])) {
      return "pin " + std::to_string(project.pins[i]) + " is not a control point";
    }
    if (i > 0 && project.pins[i] <= project.pins[i - 1]) {
      return "pins must be ascending without repeats (see normalisePins)";
    }
  }
  const MaterialSamples& samples = project.materials;
  if (samples.restPositions.size() != samples.materials.size()) {
    return "there are " + std::to_string(samples.materials.size()) + " material samples but " +
           std::to_string(samples.restPositions.size()) + " sample positions";
  }
  if (samples.level < 0 || samples.level > kMaxProjectLevel) {
    return "the material sample level is not from 0 to " + std::to_string(kMaxProjectLevel);
  }
  for (size_t i = 0; i < samples.size(); ++i) {
    if (!finite(samples.restPositions[i])) {
      return "material sample " + std::to_string(i) + " has a non-finite position";
    }
    if (std::string p = materialProblem(samples.materials[i]); !p.empty()) {
      return "material sample " + std::to_string(i) + ": " + p;
    }
  }
  const CameraState& camera = project.camera;
  if (!finite(camera.pivot) || !std::isfinite(camera.yawRad) || !std::isfinite(camera.pitchRad) ||
      !std::isfinite(camera.distance)) {
    return "a camera setting is not a finite number";
  }
  const ProjectSimulation& sim = project.simulation;
  if (!std::isfinite(sim.timeStepS) || !finite(sim.gravity)) {
    return "a simulation setting is not a finite number";
  }
  if (sim.level < 0 || sim.level > kMaxProjectLevel) {
    return "the simulation level is not from 0 to " + std::to_string(kMaxProjectLevel);
  }
  for (const auto& [key, value] : project.tools) {
    if (const double* number = std::get_if<double>(&value); number && !std::isfinite(*number)) {
      return "tool setting \"" + printable(key) + "\" is not a finite number";
    }
  }
  return {};
}

}  // namespace sculpt
