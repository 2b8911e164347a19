// sculpt-cli info FILE [--levels K]: what a control mesh holds and whether it is valid; with
// K >= 1 also the finite elements of the simulation at level K.

#include <array>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "fem/fem_model.h"
#include "io/control_mesh_json.h"
#include "mesh/cell_shape.h"
#include "mesh/topology.h"
#include "mesh/validation.h"
#include "subdiv/mj_refiner.h"
#include "subdiv/refinement_cost.h"
#include "subdiv/regularity.h"

namespace sculpt::cli {

const char* const kInfoUsage =
    "  info FILE [--levels K]\n"
    "      Counts of vertices, edges, faces and cells by shape, boundary size, tags, bounding\n"
    "      box and the validation report. With --levels K (0-6) also the level-K counts and the\n"
    "      regular / extraordinary / irregular cells, and for K >= 1 the simulation elements\n"
    "      (as in the paper's Table 1; at most 200000 level-K cells):\n"
    "        fem: elements=<n> BE=<%> LE=<%> PE=<%> tricubic=<n> trilinear=<n> pyramid=<n>\n"
    "      BE, LE and PE being the shares of tricubic B-spline, trilinear and pyramid elements.\n"
    "      Exit 2 when the mesh is not valid.\n";

namespace {

constexpr OptionSpec kOptions[] = {{"levels", true}, {"help", false}};
// The element data take about 17 kB per element (1.1 GB for block10 at level 2): above this many
// level-K cells info does not build them.
constexpr uint64_t kMaxFemCells = 200'000;

std::string shapeCounts(const Topology& topology) {
  std::array<uint64_t, kNumCellShapes> counts{};
  for (uint32_t c = 0; c < topology.numCells(); ++c) {
    ++counts[static_cast<size_t>(classifyCellShape(topology, c))];
  }
  std::string text;
  for (int s = 0; s < kNumCellShapes; ++s) {
    if (counts[static_cast<size_t>(s)] == 0) continue;
    if (!text.empty()) text += ' ';
    text += std::string(cellShapeName(static_cast<CellShape>(s))) + "=" +
            std::to_string(counts[static_cast<size_t>(s)]);
  }
  return text.empty() ? "none" : text;
}

uint64_t countFlags(const std::vector<uint8_t>& flags) {
  uint64_t n = 0;
  for (uint8_t flag : flags) n += flag != 0 ? 1 : 0;
  return n;
}

std::string formatPoint(double x, double y, double z) {
  char text[96];
  std::snprintf(text, sizeof text, "%.9g %.9g %.9g", x, y, z);
  return text;
}

void printTopology(const Topology& topology, const char* indent) {
  std::cout << indent << "edges: " << topology.numEdges() << '\n'
            << indent << "faces: " << topology.numFaces() << '\n'
            << indent << "cells_by_shape: " << shapeCounts(topology) << '\n'
            << indent << "boundary_faces: " << countFlags(topology.faceIsBoundary) << '\n'
            << indent << "boundary_edges: " << countFlags(topology.edgeIsBoundary) << '\n'
            << indent << "boundary_vertices: " << countFlags(topology.vertexIsBoundary) << '\n';
}

void printBoundingBox(const CellComplex& mesh) {
  if (mesh.numVertices() == 0) {
    std::cout << "bounding_box: empty\n";
    return;
  }
  const Eigen::RowVector3d lo = mesh.positions.colwise().minCoeff();
  const Eigen::RowVector3d hi = mesh.positions.colwise().maxCoeff();
  std::cout << "bounding_box_min: " << formatPoint(lo.x(), lo.y(), lo.z()) << '\n'
            << "bounding_box_max: " << formatPoint(hi.x(), hi.y(), hi.z()) << '\n';
}

void printValidation(const std::vector<ValidationIssue>& issues) {
  const size_t errors = countErrors(issues);
  const size_t warnings = issues.size() - errors;
  if (issues.empty()) {
    std::cout << "validation: valid\n";
    return;
  }
  std::cout << "validation: " << (errors == 0 ? "valid" : "invalid") << " (" << errors
            << (errors == 1 ? " error, " : " errors, ") << warnings
            << (warnings == 1 ? " warning)\n" : " warnings)\n");
  for (const ValidationIssue& issue : issues) {
    std::cout << "  " << (issue.severity == ValidationIssue::Severity::Error ? "error" : "warning")
              << ": " << issue.message << '\n';
  }
}

// Refines and prints the level-K section; returns false (after an error line) when refused.
bool printLevel(const std::string& file, const CellComplex& mesh, const Topology& topology,
                int levels) {
  if (const std::string refusal = refinementRefusal(topology, levels, file); !refusal.empty()) {
    printError(refusal);
    return false;
  }
  ProgressReporter progress = stderrProgress();
  const std::optional<Subdivision> result = subdivide(mesh, levels, &progress);
  if (!result) {
    printError(file + ": refinement was cancelled");
    return false;
  }
  const CellComplex& finest = result->finest();
  const Topology& finestTopology = result->finestTopology();
  std::array<uint64_t, 3> regularity{};
  for (CellRegularity r : classifyCells(finestTopology)) ++regularity[static_cast<size_t>(r)];
  std::cout << "level " << levels << ":\n"
            << "  vertices: " << finest.numVertices() << '\n'
            << "  cells: " << finest.numCells() << '\n';
  printTopology(finestTopology, "  ");
  std::cout << "  regular: " << regularity[0] << '\n'
            << "  extraordinary: " << regularity[1] << '\n'
            << "  irregular: " << regularity[2] << '\n';
  return true;
}

std::string percent(uint32_t part, uint32_t whole) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%", whole == 0 ? 0.0 : 100.0 * part / whole);
  return text;
}

// The element line of level `levels` (>= 1), with the default material. A model that cannot be
// built is reported on the line: the mesh itself is valid, so this is no error of info.
void printElements(const std::string& file, const CellComplex& mesh, const Topology& topology,
                   int levels) {
  const uint64_t cells = estimateRefinementCost(topology, levels).cells;
  if (cells > kMaxFemCells) {
    std::cout << "  fem: not built (about " << cells << " cells; info builds elements for at "
              << "most " << kMaxFemCells << ")\n";
    return;
  }
  if (const std::string refusal = refinementRefusal(topology, levels, file, kFiniteElements);
      !refusal.empty()) {
    std::cout << "  fem: not built (" << refusal << ")\n";
    return;
  }
  FemSetup setup;
  setup.level = levels;
  std::string error;
  ProgressReporter progress = stderrProgress();
  const std::optional<FemModel> model = FemModel::create(mesh, setup, &error, &progress);
  if (!model) {
    std::cout << "  fem: not built (" << (error.empty() ? "cancelled" : error) << ")\n";
    return;
  }
  const ElementCounts counts = model->mesh().counts();
  const uint32_t total = counts.total();
  std::cout << "  fem: elements=" << total << " BE=" << percent(counts.tricubic, total)
            << " LE=" << percent(counts.trilinear, total)
            << " PE=" << percent(counts.pyramid, total) << " tricubic=" << counts.tricubic
            << " trilinear=" << counts.trilinear << " pyramid=" << counts.pyramid << '\n';
}

int info(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kInfoUsage;
    return kExitSuccess;
  }
  if (args.positional().size() != 1) throw UsageError("info needs exactly one FILE (see --help)");
  file = args.positional()[0];
  const bool withLevels = args.has("levels");
  const int levels = args.intValue("levels", 0, 0, kMaxLevels);

  const CellComplex mesh = loadControlMeshJson(file);
  const std::vector<ValidationIssue> issues = validate(mesh);
  const size_t errors = countErrors(issues);

  std::cout << "file: " << file << '\n'
            << "vertices: " << mesh.numVertices() << '\n'
            << "cells: " << mesh.numCells() << '\n';
  // Topology needs every vertex id in range; validation has already named the bad ones.
  std::optional<Topology> topology;
  if (vertexIdsInRange(mesh)) {
    topology = buildTopology(mesh);
    printTopology(*topology, "");
  } else {
    std::cout << "topology: not built (vertex indices out of range)\n";
  }
  std::cout << "creases: " << mesh.creases.size() << '\n'
            << "corners: " << mesh.corners.size() << '\n';
  printBoundingBox(mesh);
  printValidation(issues);

  if (errors > 0) {
    if (withLevels) std::cout << "level " << levels << ": not refined (the mesh is not valid)\n";
    std::cout.flush();
    return printError(validationFailure(file, issues, "listed above"));
  }
  if (withLevels && !printLevel(file, mesh, *topology, levels)) return kExitBadInput;
  if (withLevels && levels >= 1) printElements(file, mesh, *topology, levels);
  return kExitSuccess;
}

}  // namespace

int runInfoCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] { return info(CliArgs::parse(args, kOptions), file); });
}

}  // namespace sculpt::cli
