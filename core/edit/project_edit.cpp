#include "edit/project_edit.h"

#include <stdexcept>
#include <utility>

#include "edit/edit_support.h"
#include "fem/fem_model.h"
#include "mesh/validation.h"

namespace sculpt {
namespace {

// The painted samples carried to the Gauss points of `mesh` at the samples' level.
MaterialSamples carriedMaterials(const MaterialSamples& old, const CellComplex& mesh) {
  FemSetup setup;
  setup.level = old.level;
  setup.trilinear = old.level <= 0;
  std::string error;
  const std::optional<FemModel> model = FemModel::create(mesh, setup, &error);
  if (!model) edit::reject("the painted materials cannot be carried over: " + error + ".");
  MaterialSamples samples = captureMaterials(model->mesh(), old.level);
  samples.materials = resampleMaterials(old, samples.restPositions);
  return samples;
}

}  // namespace

void applyTopologyEdit(Project& project, const TopologyEdit& edit) {
  // Everything is computed first and committed by moves that cannot throw (strong guarantee).
  const CellComplex& oldMesh = project.controlMesh;
  if (edit.newVertexOfOld.size() != oldMesh.numVertices())
    edit::reject("the edit maps " + std::to_string(edit.newVertexOfOld.size()) +
                 " vertices but the project's mesh has " + std::to_string(oldMesh.numVertices()) +
                 ".");
  for (const int64_t v : edit.newVertexOfOld)
    if (v < -1 || v >= static_cast<int64_t>(edit.mesh.numVertices()))
      edit::reject("the edit maps a vertex to " + std::to_string(v) + ", outside the new mesh (" +
                   std::to_string(edit.mesh.numVertices()) + " vertices).");
  if (const std::string error = edit::firstError(validate(edit.mesh)); !error.empty())
    edit::reject("the edited mesh is invalid: " + error + ".");

  std::vector<uint32_t> pins;
  for (const uint32_t v : project.pins)
    if (v < edit.newVertexOfOld.size() && edit.newVertexOfOld[v] >= 0)
      pins.push_back(static_cast<uint32_t>(edit.newVertexOfOld[v]));
  normalisePins(pins);
  MaterialSamples materials = project.materials.size() > 0
                                  ? carriedMaterials(project.materials, edit.mesh)
                                  : project.materials;
  CellComplex mesh = edit.mesh;

  project.controlMesh = std::move(mesh);
  project.pins = std::move(pins);
  project.materials = std::move(materials);
}

}  // namespace sculpt
