// sculpt-cli subdivide CONTROL.json --levels K --out OUT(.json|.vtk) [--boundary SURFACE.obj]:
// MacCracken–Joy refinement of a control mesh, written for ParaView or as a new control mesh.

#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "io/control_mesh_json.h"
#include "io/obj_writer.h"
#include "io/vtk_writer.h"
#include "mesh/topology.h"
#include "subdiv/mj_refiner.h"
#include "subdiv/refinement_cost.h"

namespace sculpt::cli {

const char* const kSubdivideUsage =
    "  subdivide CONTROL.json --levels K --out OUT.json|OUT.vtk [--boundary SURFACE.obj]\n"
    "      Refines K times (0-6; 0 writes the control mesh itself). .json writes the level-K\n"
    "      complex as a control mesh, .vtk a legacy unstructured grid for ParaView; --boundary\n"
    "      writes the outward boundary surface as OBJ.\n";

namespace {

constexpr OptionSpec kOptions[] = {
    {"levels", true}, {"out", true}, {"boundary", true}, {"help", false}};

int subdivideCommand(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kSubdivideUsage;
    return kExitSuccess;
  }
  if (args.positional().size() != 1) {
    throw UsageError("subdivide needs exactly one CONTROL file (see --help)");
  }
  // Check every argument before any work is done.
  const std::string control = args.positional()[0];
  const int levels = args.intValue("levels", -1, 0, kMaxLevels);
  if (levels < 0) throw UsageError("--levels is required");
  const std::string out = args.requiredValue("out");
  const std::string outExt = lowerExtension(out);
  if (outExt != ".json" && outExt != ".vtk") {
    throw UsageError("--out " + out + ": unknown extension (expected .json or .vtk)");
  }
  const std::optional<std::string> boundary = args.value("boundary");
  if (boundary && lowerExtension(*boundary) != ".obj") {
    throw UsageError("--boundary " + *boundary + ": unknown extension (expected .obj)");
  }

  file = control;
  const std::optional<LoadedMesh> loaded = loadValidControlMesh(control);
  if (!loaded) return kExitBadInput;
  const Topology controlTopology = buildTopology(loaded->mesh);
  if (const std::string refusal = refinementRefusal(controlTopology, levels, control);
      !refusal.empty())
    return printError(refusal);

  // Level 0 is the control mesh itself; otherwise refine.
  std::optional<Subdivision> result;
  if (levels > 0) {
    ProgressReporter progress = stderrProgress();
    result = subdivide(loaded->mesh, levels, &progress);
    if (!result) return printError(control + ": refinement was cancelled");
  }
  const CellComplex& finest = result ? result->finest() : loaded->mesh;
  const Topology& topology = result ? result->finestTopology() : controlTopology;

  file = out;
  if (outExt == ".json") {
    saveControlMeshJson(finest, out);
  } else {
    writeVtk(finest, topology, out);
  }
  std::cout << "wrote " << out << " (cells=" << finest.numCells()
            << ", vertices=" << finest.numVertices() << ")\n";
  if (boundary) {
    file = *boundary;
    const BoundarySurfaceCounts counts = writeBoundaryObj(finest, topology, *boundary);
    std::cout << "wrote " << *boundary << " (faces=" << counts.faces
              << ", vertices=" << counts.vertices << ")\n";
  }
  return kExitSuccess;
}

}  // namespace

int runSubdivideCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] { return subdivideCommand(CliArgs::parse(args, kOptions), file); });
}

}  // namespace sculpt::cli
