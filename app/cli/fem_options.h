#pragma once
// Options shared by the FEM subcommands (static, simulate, bench fem): the simulation level or
// trilinear mode, the material, fixed boxes and box forces.

#include <Eigen/Geometry>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "fem/fem_model.h"
#include "sim/simulator.h"

namespace sculpt::cli {

/// Options every FEM subcommand accepts (append the command's own).
extern const std::vector<OptionSpec> kFemOptions;
/// Their usage lines.
extern const char* const kFemOptionsUsage;

struct BoxForce {
  Eigen::AlignedBox3d box;
  Eigen::Vector3d total;  ///< spread equally over the control points in the box
};

struct FemCommandOptions {
  FemSetup setup;
  std::vector<Eigen::AlignedBox3d> fixed;
  std::vector<BoxForce> forces;
};

/// Parses and checks the shared options. Throws UsageError.
FemCommandOptions parseFemOptions(const CliArgs& args);

/// "xmin,ymin,zmin,xmax,ymax,zmax" (min <= max per axis). Throws UsageError naming `option`.
Eigen::AlignedBox3d parseBox(const std::string& text, const std::string& option);
/// "x,y,z". Throws UsageError naming `option`.
Eigen::Vector3d parseVector3(const std::string& text, const std::string& option);
/// A finite number. Throws UsageError naming `option`.
double parseNumber(const std::string& text, const std::string& option);

/// Fixes the control points in each --fix box and adds one ControlForceForm for the --force
/// boxes. Throws UsageError when a box contains no control point.
void applyConstraintsAndForces(Simulator& simulator, const FemCommandOptions& options);

/// Builds the model, printing one error line on failure or, before allocating, when the model
/// and its simulation would not fit in the memory available (subdiv/refinement_cost.h).
std::optional<FemModel> buildFemModel(const CellComplex& control, const FemSetup& setup,
                                      const std::string& file);

/// --integrator paper|implicit (default implicit) and --dt S (0 < S <= 10; `dtRequired` or
/// default 1/60 s) into settings. Throws UsageError.
SimulationSettings parseIntegratorAndStep(const CliArgs& args, bool dtRequired);

/// Writes the control mesh at `positions` with the POINT_DATA vector 'displacement' (from the
/// rest control points), as static and simulate do.
void writeDeformedControlVtk(const FemModel& model, const Points& positions,
                             const std::string& path);

/// Largest displacement of the simulation nodes (A (p - p_rest)), in metres.
double maxNodeDisplacement(const FemModel& model, const Points& control);

}  // namespace sculpt::cli
