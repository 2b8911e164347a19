#pragma once
// Everything a sculpting session saves: the control mesh with its crease/corner tags, the
// painted material samples, the pinned control points, the embedded surface (a reference to a
// file or the OBJ text itself), the camera, and the tool and simulation settings. The window
// keeps one Project as the master copy of the user's work; project_file.h writes and reads it,
// undo_history.h records edits to it.

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "fem/material.h"
#include "mesh/cell_complex.h"

namespace sculpt {

struct FemMesh;

/// Material samples painted through the volume: one per Gauss point of the simulation level K
/// (FemMesh::gaussMaterial order), each with the rest position it was taken at.
///
/// Resampling: when the topology or the level changes, the new Gauss points take the material of
/// the nearest old sample by rest position (resampleMaterials below; ties go to the lower old
/// index, so the result is deterministic). Empty samples mean "uniform default material".
struct MaterialSamples {
  int level = 0;                               ///< the level K the samples belong to
  std::vector<Eigen::Vector3d> restPositions;  ///< #S rest positions (m)
  std::vector<Material> materials;             ///< #S materials (E, nu, density, damping)

  size_t size() const { return materials.size(); }
};

/// The embedded (rendered) surface: either a reference to a file with the hash of its contents
/// at save time (to notice that it changed), or the OBJ text itself when `embedded` is set.
struct SurfaceSource {
  std::string path;         ///< as the user chose it (absolute or relative to the project)
  std::string contentHash;  ///< contentHash() of the file's bytes, empty when unknown
  bool embedded = false;    ///< objText holds the surface; path is informational only
  std::string objText;      ///< OBJ text when embedded
  bool operator==(const SurfaceSource&) const = default;
};

struct CameraState {
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();  ///< orbit centre (m)
  double yawRad = 0.0;
  double pitchRad = 0.0;
  double distance = 5.0;  ///< pivot to eye (m)
  bool orthographic = false;
  bool operator==(const CameraState&) const = default;
};

struct ProjectSimulation {
  std::string integrator = "implicit-euler";
  double timeStepS = 1.0 / 60.0;
  Eigen::Vector3d gravity{0.0, 0.0, -9.81};  ///< m/s^2
  int level = 2;                             ///< simulation level K
  bool operator==(const ProjectSimulation&) const = default;
};

/// A tool setting: a switch, a number or a word (brush radius, falloff preset, mirror axis...).
using ToolValue = std::variant<bool, double, std::string>;
/// Sorted by key, so files list them in a fixed order.
using ToolSettings = std::map<std::string, ToolValue>;

struct Project {
  CellComplex controlMesh;     ///< positions, cells, crease and corner tags
  MaterialSamples materials;   ///< painted samples (empty: uniform default)
  std::vector<uint32_t> pins;  ///< pinned control points, ascending, no repeats
  SurfaceSource surface;
  CameraState camera;
  ToolSettings tools;
  ProjectSimulation simulation;
};

/// True when the two control meshes have the same positions, cells and tags (bit for bit).
bool sameControlMesh(const CellComplex& a, const CellComplex& b);
/// True when level, positions and materials agree bit for bit.
bool sameMaterialSamples(const MaterialSamples& a, const MaterialSamples& b);
/// Bitwise equality of doubles (tells -0.0 from 0.0 and compares NaNs by payload), the notion
/// that matters for byte-identical files.
bool sameBits(double a, double b);
bool sameBits(const Material& a, const Material& b);

/// The materials at every Gauss point of `mesh`, tagged with `level`.
MaterialSamples captureMaterials(const FemMesh& mesh, int level);

/// For each of `positions`, the material of the nearest sample of `from` (ties: lowest index);
/// `fallback` for all of them when `from` is empty. O((S + P) log S) with a k-d tree.
std::vector<Material> resampleMaterials(const MaterialSamples& from,
                                        std::span<const Eigen::Vector3d> positions,
                                        const Material& fallback = {});

/// "fnv1a64:<16 hex digits>" of the bytes: detects that a referenced surface file changed.
std::string contentHash(std::string_view bytes);

/// Sorts and removes repeats (the order pins are kept and saved in).
void normalisePins(std::vector<uint32_t>& pins);

}  // namespace sculpt
