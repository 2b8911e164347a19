#include "fem/fem_model.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "mesh/topology.h"

namespace sculpt {

std::optional<FemModel> FemModel::create(const CellComplex& control, const FemSetup& setup,
                                         std::string* error, ProgressReporter* progress) {
  auto fail = [&](std::string message) -> std::optional<FemModel> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  if (!setup.trilinear && (setup.level < 1 || setup.level > 6))
    return fail("simulation level " + std::to_string(setup.level) +
                " is out of range (1..6; every cell must be subdivided at least once)");
  FemModel model;
  model.setup_ = setup;
  if (setup.trilinear) {
    Subdivision s;
    s.levels.push_back(control);
    s.topologies.push_back(buildTopology(control));
    s.stencils = StencilTable::identity(control.numVertices());
    model.subdivision_ = std::make_unique<Subdivision>(std::move(s));
  } else {
    auto s = subdivide(control, setup.level, progress);
    if (!s) return std::nullopt;  // cancelled
    model.subdivision_ = std::make_unique<Subdivision>(std::move(*s));
  }
  FemMeshOptions options;
  options.allowTricubic = !setup.trilinear;
  options.material = setup.material;
  std::string problem;
  auto mesh = buildFemMesh(model.subdivision_->finest(), model.subdivision_->finestTopology(),
                           model.subdivision_->stencils, options, &problem);
  if (!mesh) return fail(problem);
  model.mesh_ = std::make_unique<FemMesh>(std::move(*mesh));
  model.elastic_ = std::make_unique<ElasticKernel>(*model.mesh_);
  model.A_ = sculpt::stencilMatrix(model.mesh_->nodeStencils);
  if (progress && !progress->report(1.0, "elements")) return std::nullopt;
  return model;
}

// Both products go level by level (S_K ... S_1, then the virtual centres from the level-K
// vertices) rather than through the composed A: with few control points every node depends on
// many of them, and the per-level tables hold fewer entries (block3 at K = 3: 235,000 against
// 417,000).
void FemModel::nodesFromControl(const Points& control, Points& nodes) const {
  const FemMesh& mesh = *mesh_;
  if (mesh.centreStencils.numRows() == 0) {
    subdivision_->chain.apply(control, nodes);
    return;
  }
  thread_local Points lattice, centres;
  subdivision_->chain.apply(control, lattice);
  mesh.centreStencils.apply(lattice, centres);
  nodes.resize(mesh.numNodes(), 3);
  nodes.topRows(mesh.numLatticeNodes) = lattice;
  nodes.bottomRows(centres.rows()) = centres;
}

void FemModel::addToControl(const Points& nodeVectors, Points& control) const {
  const FemMesh& mesh = *mesh_;
  thread_local Points lattice, projected;
  if (mesh.centreStencils.numRows() == 0) {
    subdivision_->chain.applyTranspose(nodeVectors, projected);
  } else {
    mesh.centreStencils.applyTranspose(nodeVectors.bottomRows(mesh.centreStencils.numRows()),
                                       lattice);
    lattice += nodeVectors.topRows(mesh.numLatticeNodes);
    subdivision_->chain.applyTranspose(lattice, projected);
  }
  control += projected;
}

void FemModel::refreshMatrices() const {
  if (!matricesStale_) return;
  std::vector<double> density = fieldWeights(*mesh_, MassField::Density);
  std::vector<double> damping = fieldWeights(*mesh_, MassField::Damping);
  // The matrices are linear in the weights: after a paint dab, the change of weights on the
  // painted elements gives the change of the matrices (a dab on the bunny touches a few percent
  // of the elements; a whole rebuild made every step of a density stroke several times longer).
  std::vector<uint8_t> changed(mesh_->numElements(), 0);
  uint32_t changedCount = 0;
  const bool haveLast = assembledDensity_.size() == density.size();
  if (haveLast)
    for (uint32_t e = 0; e < mesh_->numElements(); ++e)
      for (uint32_t q = mesh_->gaussBegin(e); q < mesh_->gaussBegin(e) + mesh_->gaussCount(e); ++q)
        if (density[q] != assembledDensity_[q] || damping[q] != assembledDamping_[q]) {
          changed[e] = 1;
          ++changedCount;
          break;
        }
  SparseMatrix mass, dampingMatrix;  // made first, kept only when both are made
  if (haveLast && 4 * changedCount <= mesh_->numElements()) {
    std::vector<double> delta(density.size(), 0.0);
    const auto updated = [&](const SparseMatrix& matrix, const std::vector<double>& now,
                             const std::vector<double>& before) {
      bool any = false;
      for (size_t q = 0; q < now.size(); ++q) {
        delta[q] = now[q] - before[q];
        any = any || delta[q] != 0.0;
      }
      if (!any) return matrix;
      SparseMatrix sum = matrix + reducedWeightedMatrix(*mesh_, A_, delta, changed);
      sum.prune(0.0);  // a field painted back to zero leaves no entries, as a rebuild
      return sum;
    };
    mass = updated(reducedMass_, density, assembledDensity_);
    dampingMatrix = updated(reducedDamping_, damping, assembledDamping_);
  } else {
    mass = reducedWeightedMatrix(*mesh_, A_, density);
    // Damping proportional to density everywhere (any uniform material) gives D~ = ratio M~ (to
    // rounding): no second assembly and reduction, a third of the first step's set-up.
    const std::vector<Material>& samples = mesh_->gaussMaterial;
    const double ratio = samples.empty() || !(samples.front().density > 0.0)
                             ? -1.0
                             : samples.front().damping / samples.front().density;
    const bool proportional =
        ratio >= 0.0 && std::all_of(samples.begin(), samples.end(), [&](const Material& m) {
          return std::abs(m.damping - ratio * m.density) <= 1e-12 * std::abs(m.damping);
        });
    if (proportional) {
      dampingMatrix = ratio * mass;
      dampingMatrix.prune(0.0);  // zero damping: an empty matrix, as the assembly gives
    } else {
      dampingMatrix = reducedWeightedMatrix(*mesh_, A_, damping);
    }
  }
  reducedMass_ = std::move(mass);
  reducedDamping_ = std::move(dampingMatrix);
  assembledDensity_ = std::move(density);
  assembledDamping_ = std::move(damping);
  matricesStale_ = false;
}

const SparseMatrix& FemModel::reducedMass() const {
  refreshMatrices();
  return reducedMass_;
}

const SparseMatrix& FemModel::reducedDamping() const {
  refreshMatrices();
  return reducedDamping_;
}

double FemModel::totalMass() const {
  const std::vector<double> masses = fieldWeights(*mesh_, MassField::Density);
  return std::accumulate(masses.begin(), masses.end(), 0.0);
}

long FemModel::paintMaterial(const Eigen::Vector3d& centre, double radius,
                             const Material& material, std::string* error) {
  const double r2 = std::isinf(radius) ? radius : radius * radius;
  return paintMaterial(
      [&](const Eigen::Vector3d& rest) { return (rest - centre).squaredNorm() > r2 ? 0.0 : 1.0; },
      material, MaterialFields{}, error);
}

bool FemModel::setMaterials(std::span<const Material> materials, std::string* error) {
  const auto fail = [&](const std::string& why) {
    if (error) *error = why;
    return false;
  };
  if (materials.size() != mesh_->numGaussPoints())
    return fail(std::to_string(materials.size()) + " materials for " +
                std::to_string(mesh_->numGaussPoints()) + " Gauss points");
  for (size_t q = 0; q < materials.size(); ++q)
    if (const std::string problem = materialProblem(materials[q]); !problem.empty())
      return fail("material " + std::to_string(q) + ": " + problem);
  bool massChanged = false, stiffnessChanged = false;
  for (size_t q = 0; q < materials.size(); ++q) {
    Material& sample = mesh_->gaussMaterial[q];
    const Material& m = materials[q];
    massChanged |= sample.density != m.density || sample.damping != m.damping;
    stiffnessChanged |= sample.youngs != m.youngs || sample.poisson != m.poisson;
    sample = m;
    mesh_->gaussLame[q] = lameParameters(m);
  }
  refreshAfterMaterialChange(massChanged, stiffnessChanged);
  return true;
}

void FemModel::refreshAfterMaterialChange(bool massChanged, bool stiffnessChanged) {
  // Only what depends on the changed fields is refreshed: the elastic kernel's packed moduli
  // for E and nu (the stiffness is matrix-free), the mass and damping matrices for density and
  // damping (lazily, on next use).
  if (stiffnessChanged) elastic_->refreshMaterial();
  if (massChanged) {
    matricesStale_ = true;
    ++massVersion_;
  }
  if (massChanged || stiffnessChanged) ++materialVersion_;
}

long FemModel::paintMaterial(const std::function<double(const Eigen::Vector3d&)>& weight,
                             const Material& target, const MaterialFields& fields,
                             std::string* error) {
  if (const std::string problem = materialProblem(target); !problem.empty()) {
    if (error) *error = "invalid material: " + problem;
    return -1;
  }
  const auto blend = [](double& value, double goal, double w) {
    value = w >= 1.0 ? goal : value + w * (goal - value);
  };
  long touched = 0;
  bool massChanged = false, stiffnessChanged = false;
  for (uint32_t q = 0; q < mesh_->numGaussPoints(); ++q) {
    const double w = weight(mesh_->gaussRestPosition[q]);
    if (!(w > 0.0)) continue;
    Material& sample = mesh_->gaussMaterial[q];
    const Material before = sample;
    if (fields.density) blend(sample.density, target.density, w);
    if (fields.damping) blend(sample.damping, target.damping, w);
    if (fields.youngs) blend(sample.youngs, target.youngs, w);
    if (fields.poisson) blend(sample.poisson, target.poisson, w);
    massChanged |= sample.density != before.density || sample.damping != before.damping;
    const bool stiffer = sample.youngs != before.youngs || sample.poisson != before.poisson;
    if (stiffer) mesh_->gaussLame[q] = lameParameters(sample);
    stiffnessChanged |= stiffer;
    ++touched;
  }
  refreshAfterMaterialChange(massChanged, stiffnessChanged);
  return touched;
}

}  // namespace sculpt
