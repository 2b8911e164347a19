#include "cli/fem_options.h"

#include "scene/control_export.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "cli/cli_common.h"
#include "io/vtk_writer.h"
#include "mesh/topology.h"
#include "sim/standard_forms.h"
#include "subdiv/refinement_cost.h"

namespace sculpt::cli {

const std::vector<OptionSpec> kFemOptions = {
    {"levels", true}, {"trilinear", false}, {"E", true},   {"nu", true},
    {"density", true}, {"damping", true},   {"fix", true}, {"force", true, 1}};

const char* const kFemOptionsUsage =
    "      --levels K (simulation level, default 2) or --trilinear (trilinear elements on the\n"
    "      control cells, A = identity); --E PA (default 1e5), --nu V (0.3), --density RHO\n"
    "      (1000 kg/m^3), --damping GAMMA (0 kg/(m^3 s)); --fix BOX fixes the control points\n"
    "      in BOX; --force BOX FX,FY,FZ spreads a total force (N) over the control points in\n"
    "      BOX. BOX is xmin,ymin,zmin,xmax,ymax,zmax; --fix=BOX also works.\n";

double parseNumber(const std::string& text, const std::string& option) {
  double value = 0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || ptr != end || !std::isfinite(value))
    throw UsageError("--" + option + ": '" + text + "' is not a finite number");
  return value;
}

namespace {

std::vector<double> parseList(const std::string& text, const std::string& option, size_t count,
                              const char* shape) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) values.push_back(parseNumber(item, option));
  if (values.size() != count)
    throw UsageError("--" + option + ": '" + text + "' must be " + shape);
  return values;
}

}  // namespace

Eigen::AlignedBox3d parseBox(const std::string& text, const std::string& option) {
  const std::vector<double> v = parseList(text, option, 6, "xmin,ymin,zmin,xmax,ymax,zmax");
  const Eigen::Vector3d lo(v[0], v[1], v[2]), hi(v[3], v[4], v[5]);
  if ((lo.array() > hi.array()).any())
    throw UsageError("--" + option + ": '" + text + "' has a minimum above its maximum");
  return {lo, hi};
}

Eigen::Vector3d parseVector3(const std::string& text, const std::string& option) {
  const std::vector<double> v = parseList(text, option, 3, "x,y,z");
  return {v[0], v[1], v[2]};
}

FemCommandOptions parseFemOptions(const CliArgs& args) {
  FemCommandOptions options;
  options.setup.trilinear = args.has("trilinear");
  if (options.setup.trilinear && args.has("levels"))
    throw UsageError("--levels and --trilinear exclude each other");
  options.setup.level = args.intValue("levels", 2, 1, kMaxLevels);
  Material& m = options.setup.material;
  if (auto v = args.value("E")) m.youngs = parseNumber(*v, "E");
  if (auto v = args.value("nu")) m.poisson = parseNumber(*v, "nu");
  if (auto v = args.value("density")) m.density = parseNumber(*v, "density");
  if (auto v = args.value("damping")) m.damping = parseNumber(*v, "damping");
  if (const std::string problem = materialProblem(m); !problem.empty())
    throw UsageError("invalid material: " + problem);
  for (const std::string& box : args.values("fix")) options.fixed.push_back(parseBox(box, "fix"));
  for (const std::string& value : args.values("force")) {
    const size_t space = value.find(' ');
    if (space == std::string::npos) throw UsageError("--force needs BOX and FX,FY,FZ");
    options.forces.push_back({parseBox(value.substr(0, space), "force"),
                              parseVector3(value.substr(space + 1), "force")});
  }
  return options;
}

void applyConstraintsAndForces(Simulator& simulator, const FemCommandOptions& options) {
  auto describe = [](const Eigen::AlignedBox3d& box) {
    std::ostringstream s;
    s << box.min().x() << ',' << box.min().y() << ',' << box.min().z() << ',' << box.max().x()
      << ',' << box.max().y() << ',' << box.max().z();
    return s.str();
  };
  for (const Eigen::AlignedBox3d& box : options.fixed) {
    if (simulator.fixInBox(box) == 0)
      throw UsageError("--fix " + describe(box) + " contains no control point");
  }
  if (options.forces.empty()) return;
  const Points& rest = simulator.model().restControl();
  Points forces = Points::Zero(rest.rows(), 3);
  for (const BoxForce& force : options.forces) {
    std::vector<Eigen::Index> inside;
    for (Eigen::Index i = 0; i < rest.rows(); ++i)
      if (force.box.contains(rest.row(i).transpose())) inside.push_back(i);
    if (inside.empty())
      throw UsageError("--force " + describe(force.box) + " contains no control point");
    for (Eigen::Index i : inside)
      forces.row(i) += force.total.transpose() / static_cast<double>(inside.size());
  }
  simulator.addLoad(std::make_unique<ControlForceForm>(std::move(forces)));
}

std::optional<FemModel> buildFemModel(const CellComplex& control, const FemSetup& setup,
                                      const std::string& file) {
  if (const std::string refusal = refinementRefusal(
          buildTopology(control), setup.trilinear ? 0 : setup.level, file, kSimulation);
      !refusal.empty()) {
    printError(refusal);
    return std::nullopt;
  }
  std::string error;
  ProgressReporter progress = stderrProgress();
  auto model = FemModel::create(control, setup, &error, &progress);
  if (!model) printError(file + ": " + (error.empty() ? "cancelled" : error));
  return model;
}

SimulationSettings parseIntegratorAndStep(const CliArgs& args, bool dtRequired) {
  SimulationSettings settings;
  if (auto name = args.value("integrator")) {
    const auto integrator = parseIntegrator(*name);
    if (!integrator)
      throw UsageError("--integrator must be paper or implicit, got '" + *name + "'");
    settings.integrator = *integrator;
  }
  if (auto name = args.value("model")) {
    const auto model = parseElasticModel(*name);
    if (!model) throw UsageError("--model must be barrier or corotated, got '" + *name + "'");
    settings.elasticModel = *model;
  }
  const std::optional<std::string> dt =
      dtRequired ? std::optional<std::string>(args.requiredValue("dt")) : args.value("dt");
  if (dt) {
    settings.timeStep = parseNumber(*dt, "dt");
    if (!(settings.timeStep > 0) || settings.timeStep > 10.0)
      throw UsageError("--dt must be above 0 and at most 10 s, got '" + *dt + "'");
  }
  return settings;
}

void writeDeformedControlVtk(const FemModel& model, const Points& positions,
                             const std::string& path) {
  sculpt::writeDeformedControlVtk(model.control(), positions, path);
}

double maxNodeDisplacement(const FemModel& model, const Points& control) {
  Points nodes;
  model.nodesFromControl(control - model.restControl(), nodes);
  return nodes.rowwise().norm().maxCoeff();
}

}  // namespace sculpt::cli
