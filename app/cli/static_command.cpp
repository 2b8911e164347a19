// sculpt-cli static CONTROL [--levels K | --trilinear] --E PA --nu V [--fix BOX]...
// [--force BOX FX,FY,FZ]... [--linear] --out RESULT.vtk: static equilibrium under box loads.

#include <cstdio>
#include <iostream>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/fem_options.h"

namespace sculpt::cli {

const char* const kStaticUsage =
    "  static CONTROL.json [FEM options] [--linear] --out RESULT.vtk\n"
    "      Static equilibrium (co-rotated elasticity, Newton + preconditioned CG; --linear:\n"
    "      small-strain linear elasticity). RESULT.vtk is the deformed control mesh with the\n"
    "      POINT_DATA vector 'displacement' in control-point order. Last line:\n"
    "      max_displacement=<m> iterations=<n> residual=<r> (largest displacement of the\n"
    "      simulation nodes, CG iterations, relative force residual).\n";

namespace {

int staticCommand(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kStaticUsage << kFemOptionsUsage;
    return kExitSuccess;
  }
  if (args.positional().size() != 1)
    throw UsageError("static needs exactly one CONTROL file (see --help)");
  const FemCommandOptions options = parseFemOptions(args);
  const std::string out = args.requiredValue("out");
  if (lowerExtension(out) != ".vtk")
    throw UsageError("--out " + out + ": unknown extension (expected .vtk)");
  if (options.fixed.empty())
    throw UsageError("static needs at least one --fix box (an unsupported solid has no "
                     "equilibrium)");

  file = args.positional()[0];
  const std::optional<LoadedMesh> loaded = loadValidControlMesh(file);
  if (!loaded) return kExitBadInput;
  std::optional<FemModel> model = buildFemModel(loaded->mesh, options.setup, file);
  if (!model) return kExitBadInput;

  SimulationSettings settings;
  settings.corotated = !args.has("linear");
  Simulator simulator(*model, settings);
  applyConstraintsAndForces(simulator, options);
  const StaticReport report = simulator.solveStatic();
  if (!report.message.empty()) std::cerr << "static: " << report.message << '\n';

  writeDeformedControlVtk(*model, simulator.positions(), out);
  std::printf("max_displacement=%.9g iterations=%d residual=%.3g\n",
              maxNodeDisplacement(*model, simulator.positions()), report.cgIterations,
              report.residual);
  return report.converged ? kExitSuccess : 1;
}

}  // namespace

int runStaticCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] {
    std::vector<OptionSpec> specs = kFemOptions;
    specs.insert(specs.end(), {{"out", true}, {"linear", false}, {"help", false}});
    return staticCommand(CliArgs::parse(args, specs), file);
  });
}

}  // namespace sculpt::cli
