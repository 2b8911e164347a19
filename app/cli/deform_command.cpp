// sculpt-cli deform --rest REST --deformed DEF --surface IN [--method M] [--eps E] [--radius R]
// [--normals analytic|recompute|keep] --out OUT: moves a detailed surface embedded in a volume
// mesh (tetrahedra or hexahedra) with the deformed states of that mesh, one frame or a numbered
// sequence of frames ('#' runs in DEF and OUT). The embedding is computed once.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/fem_options.h"
#include "embed/embedded_deformer.h"
#include "embed/interpolation_method.h"
#include "embed/recomputed_normals.h"
#include "io/file_error.h"
#include "io/surface_file.h"
#include "io/volume_mesh_file.h"
#include "mesh/surface_mesh.h"

namespace sculpt::cli {

const char* const kDeformUsage =
    "  deform --rest REST --deformed DEF --surface IN [--method phong|linear|vertex|attribute]\n"
    "         [--gradients fit|average] [--eps E] [--radius R]\n"
    "         [--normals analytic|recompute|keep] --out OUT\n"
    "      Moves the surface IN (.obj, .gltf, .glb), embedded in the volume mesh REST (.vtk,\n"
    "      .msh, .node/.ele; tetrahedra or hexahedra), with DEF, the same mesh deformed (same\n"
    "      nodes and cells). OUT (.obj, .glb, .gltf) keeps IN's vertex count and order, faces\n"
    "      and texture coordinates. Method default phong. Node gradients: fit (default; a\n"
    "      quadratic least-squares fit around each node, third order in surface cells too) or\n"
    "      average (the paper's eq. 12); E regularises the average (default 1); R is the\n"
    "      attribute radius (default 1.5 x mean edge length). Normals: analytic (default;\n"
    "      cofactor of the gradient, recomputed for attribute), recompute (area-weighted from\n"
    "      the deformed faces) or keep. A run of '#' in DEF's file name is a\n"
    "      frame number (sim_####.vtk): every frame from the lowest to the highest number found\n"
    "      is deformed, to OUT with its own '#' run replaced. Points outside REST are\n"
    "      extrapolated (with a warning). Last line: deformed=<frames> vertices=<n>\n"
    "      outside=<points outside REST> method=<M> gradients=<fit|average>.\n";

namespace {

namespace fs = std::filesystem;

enum class NormalMode { Analytic, Recompute, Keep };

/// Most surface-point/node pairs the attribute method may weigh (16 bytes each).
constexpr double kMaxAttributeWeights = 2.5e8;
/// Frame numbers have at most this many digits.
constexpr size_t kMaxFrameDigits = 9;

/// A file name with an optional run of '#' standing for a zero-padded frame number.
struct NumberedPath {
  fs::path directory;
  std::string prefix;  ///< file name before the run (the whole name when there is none)
  std::string suffix;  ///< file name after the run
  size_t width = 0;    ///< length of the run; 0 when the name has none

  bool numbered() const { return width > 0; }

  /// The path of frame `number` (the name itself when not numbered).
  fs::path frame(uint64_t number) const {
    if (!numbered()) return directory / prefix;
    std::string digits = std::to_string(number);
    if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
    return directory / (prefix + digits + suffix);
  }

  /// The frame number of file name `name`, if it matches (digits padded exactly to the width,
  /// or more digits without a leading zero).
  std::optional<uint64_t> match(const std::string& name) const {
    if (name.size() < prefix.size() + width + suffix.size()) return std::nullopt;
    if (name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    if (name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) return std::nullopt;
    const std::string digits =
        name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (digits.size() > kMaxFrameDigits) return std::nullopt;
    if (digits.size() > width && digits[0] == '0') return std::nullopt;
    uint64_t number = 0;
    for (char ch : digits) {
      if (ch < '0' || ch > '9') return std::nullopt;
      number = number * 10 + static_cast<uint64_t>(ch - '0');
    }
    return number;
  }
};

/// Splits `text` at the run of '#' in its file name. Throws UsageError for two runs.
NumberedPath parseNumberedPath(const std::string& text, const std::string& option) {
  const fs::path path(text);
  NumberedPath numbered;
  numbered.directory = path.parent_path();
  const std::string name = path.filename().string();
  const size_t begin = name.find('#');
  if (begin == std::string::npos) {
    numbered.prefix = name;
    return numbered;
  }
  const size_t end = name.find_first_not_of('#', begin);
  const size_t stop = end == std::string::npos ? name.size() : end;
  if (name.find('#', stop) != std::string::npos)
    throw UsageError("--" + option + " " + text + ": more than one run of '#' in the file name");
  if (stop - begin > kMaxFrameDigits)
    throw UsageError("--" + option + " " + text + ": a run of more than " +
                     std::to_string(kMaxFrameDigits) + " '#'");
  numbered.prefix = name.substr(0, begin);
  numbered.suffix = name.substr(stop);
  numbered.width = stop - begin;
  return numbered;
}

/// The frame numbers of the existing files that match `pattern`, ascending. Throws FileError
/// when the directory cannot be listed or nothing matches.
std::vector<uint64_t> findFrames(const NumberedPath& pattern, const std::string& text) {
  const fs::path directory = pattern.directory.empty() ? fs::path(".") : pattern.directory;
  std::vector<uint64_t> numbers;
  std::error_code error;
  fs::directory_iterator it(directory, error);
  if (error)
    throw FileError(text + ": cannot list the directory " + directory.string() + " (" +
                    error.message() + ")");
  for (; it != fs::directory_iterator(); it.increment(error)) {
    if (error) break;
    std::error_code typeError;
    if (!it->is_regular_file(typeError)) continue;
    if (const auto number = pattern.match(it->path().filename().string()))
      numbers.push_back(*number);
  }
  if (error)
    throw FileError(text + ": cannot list the directory " + directory.string() + " (" +
                    error.message() + ")");
  if (numbers.empty())
    throw FileError(text + ": no frame file in " + directory.string() + " (looked for " +
                    pattern.frame(0).filename().string() + " and other numbers)");
  std::sort(numbers.begin(), numbers.end());
  numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
  return numbers;
}

/// Throws FileError unless `deformed` has the nodes and cells of `rest`.
/// `rest` as its file has it (before any re-orientation): a frame lists the same cells.
void checkSameMesh(const VolumeMesh& rest, const VolumeMesh& deformed, const std::string& restPath,
                   const std::string& deformedPath) {
  if (deformed.numNodes() != rest.numNodes())
    throw FileError(deformedPath + ": " + std::to_string(deformed.numNodes()) +
                    " nodes but the rest mesh " + restPath + " has " +
                    std::to_string(rest.numNodes()));
  const uint32_t cells = std::min(rest.numCells(), deformed.numCells());
  for (uint32_t c = 0; c < cells; ++c) {
    const auto a = rest.cells.row(c);
    const auto b = deformed.cells.row(c);
    if (!std::equal(a.begin(), a.end(), b.begin(), b.end()))
      throw FileError(deformedPath + ": cell " + std::to_string(c) +
                      " differs from the rest mesh " + restPath);
  }
  if (deformed.numCells() != rest.numCells())
    throw FileError(deformedPath + ": " + std::to_string(deformed.numCells()) +
                    " cells but the rest mesh " + restPath + " has " +
                    std::to_string(rest.numCells()));
}

/// Throws UsageError when the attribute method at `radius` (0: default) would weigh more
/// point-node pairs than memory allows, estimated from the density of nodes in their box.
void checkAttributeCost(const VolumeMesh& rest, uint32_t points, double radius) {
  const double mean = meanEdgeLength(rest);
  const double r = radius > 0.0 ? radius : defaultAttributeRadius(mean);
  const Eigen::Vector3d extent =
      (rest.positions.colwise().maxCoeff() - rest.positions.colwise().minCoeff()).transpose();
  double boxVolume = 1.0;
  for (int d = 0; d < 3; ++d) boxVolume *= std::max(extent[d], mean);
  const double nodes = rest.numNodes();
  const double sphere = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double perPoint = std::clamp(nodes * sphere / boxVolume, 1.0, nodes);
  if (!(perPoint * points <= kMaxAttributeWeights)) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "--radius %.6g: about %.3g surface point-node weights, more than the %.3g "
                  "allowed; use a smaller radius",
                  r, perPoint * points, kMaxAttributeWeights);
    throw UsageError(text);
  }
}

struct DeformOptions {
  std::string restPath, deformedPath, surfacePath, outPath;
  InterpolationMethod method = InterpolationMethod::Phong;
  DeformerSettings settings;
  NormalMode normals = NormalMode::Analytic;
};

DeformOptions parseOptions(const CliArgs& args) {
  if (!args.positional().empty())
    throw UsageError("deform takes no positional argument ('" + args.positional()[0] +
                     "'; see --help)");
  DeformOptions options;
  options.restPath = args.requiredValue("rest");
  options.deformedPath = args.requiredValue("deformed");
  options.surfacePath = args.requiredValue("surface");
  options.outPath = args.requiredValue("out");

  const std::string method = args.value("method").value_or("phong");
  const auto parsed = parseInterpolationMethod(method);
  if (!parsed)
    throw UsageError("--method: unknown method '" + method +
                     "' (expected phong, linear, vertex or attribute)");
  options.method = *parsed;

  if (const auto eps = args.value("eps")) {
    options.settings.eps = parseNumber(*eps, "eps");
    if (options.settings.eps < 0.0) throw UsageError("--eps: '" + *eps + "' must be >= 0");
  }
  if (const auto radius = args.value("radius")) {
    options.settings.attributeRadius = parseNumber(*radius, "radius");
    if (options.settings.attributeRadius <= 0.0)
      throw UsageError("--radius: '" + *radius + "' must be > 0 (leave it out for the default)");
  }
  options.settings.gradients = gradientSchemeOption(args);
  options.settings.buildAttributeWeights = options.method == InterpolationMethod::Attribute;

  const std::string normals = args.value("normals").value_or("analytic");
  if (normals == "analytic") {
    options.normals = NormalMode::Analytic;
  } else if (normals == "recompute") {
    options.normals = NormalMode::Recompute;
  } else if (normals == "keep") {
    options.normals = NormalMode::Keep;
  } else {
    throw UsageError("--normals: unknown mode '" + normals +
                     "' (expected analytic, recompute or keep)");
  }

  const std::string extension = lowerExtension(options.outPath);
  if (extension != ".obj" && extension != ".glb" && extension != ".gltf")
    throw UsageError("--out " + options.outPath +
                     ": unknown extension (expected .obj, .glb or .gltf)");
  return options;
}

int deformCommand(const CliArgs& args, std::string& file) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kDeformUsage;
    return kExitSuccess;
  }
  const DeformOptions options = parseOptions(args);
  const NumberedPath deformedPattern = parseNumberedPath(options.deformedPath, "deformed");
  const NumberedPath outPattern = parseNumberedPath(options.outPath, "out");
  if (deformedPattern.numbered() && !outPattern.numbered())
    throw UsageError("--out " + options.outPath +
                     ": needs a run of '#' for the frame number, as --deformed has one");

  // Inputs: the rest mesh, the surface, the frames (before any precompute, so that a bad
  // pattern is reported at once)
  file = options.restPath;
  // Mirrored cells (node orders of the other orientation convention) are re-oriented: the
  // interpolation is the same map either way. Degenerate and folded cells are still refused.
  const VolumeMesh restAsRead = readVolumeMesh(options.restPath, CellShapeCheck::OrientationFree);
  VolumeMesh rest = restAsRead;
  const uint32_t mirrored = orientCellsPositively(rest);
  if (mirrored > 0) {
    // Mirrored cells are a convention; cells inverted by a fold overlap their neighbours.
    if (const std::string fold = findFoldedFace(rest); !fold.empty())
      throw FileError(options.restPath + ": " + fold);
  }
  if (mirrored > 0)
    std::cerr << "note: " << options.restPath << ": " << mirrored << " of " << rest.numCells()
              << " cells are negatively oriented; they are used with their node order "
                 "reversed\n";
  file = options.surfacePath;
  const LoadedSurface loaded = readSurfaceFile(options.surfacePath);
  const SurfaceMesh& surface = loaded.surface();
  if (surface.numVertices() == 0) throw FileError(options.surfacePath + ": no vertices");
  file = options.deformedPath;
  const std::vector<uint64_t> frames = deformedPattern.numbered()
                                           ? findFrames(deformedPattern, options.deformedPath)
                                           : std::vector<uint64_t>{0};

  // Precompute once
  if (options.settings.attributeRadius > 0.0 && options.method != InterpolationMethod::Attribute)
    std::cerr << "warning: --radius is used by --method attribute only\n";
  if (options.method == InterpolationMethod::Attribute)
    checkAttributeCost(rest, surface.numVertices(), options.settings.attributeRadius);
  file = options.surfacePath;
  // Progress lines for large surfaces (embedding a million points takes about a second).
  ProgressReporter progress =
      surface.positions.rows() > 200'000 ? stderrProgress() : ProgressReporter{};
  EmbeddedDeformer deformer(std::move(rest), surface.positions, options.settings, &progress);
  const Embedding& embedding = deformer.embedding();
  if (embedding.outsideCount > 0) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "warning: %u of %u surface points lie outside the rest mesh (up to %.6g away); "
                  "they are extrapolated from the nearest cell\n",
                  embedding.outsideCount, embedding.numPoints(), embedding.maxOutsideDistance);
    std::cerr << line;
  }
  const bool hasNormals = surface.normals.rows() > 0;
  const bool recompute =
      options.normals == NormalMode::Recompute ||
      (options.normals == NormalMode::Analytic && options.method == InterpolationMethod::Attribute);
  const std::vector<uint32_t> anchors =
      hasNormals ? normalAnchors(surface) : std::vector<uint32_t>{};

  // Each frame: read, check against the rest mesh, deform, write
  SurfaceMesh result = surface;
  const uint64_t first = frames.front(), last = frames.back();
  uint64_t previous = first;
  int written = 0;
  for (const uint64_t number : frames) {
    if (number > previous + 1) {
      const std::string from = deformedPattern.frame(previous + 1).string();
      if (number == previous + 2) {
        std::cerr << "warning: frame " << previous + 1 << " is missing (no " << from
                  << "); continuing\n";
      } else {
        std::cerr << "warning: frames " << previous + 1 << " to " << number - 1
                  << " are missing (no " << from << " ... "
                  << deformedPattern.frame(number - 1).string() << "); continuing\n";
      }
    }
    previous = number;
    const std::string deformedPath =
        deformedPattern.numbered() ? deformedPattern.frame(number).string() : options.deformedPath;
    const std::string outPath =
        deformedPattern.numbered() ? outPattern.frame(number).string() : options.outPath;
    if (deformedPattern.numbered())
      std::cerr << "frame " << number - first + 1 << '/' << last - first + 1 << ": " << deformedPath
                << " -> " << outPath << '\n';

    file = deformedPath;
    // A simulation frame may contain inverted cells; the deformer copes, so only its structure
    // is checked (and below, that it has the rest mesh's nodes and cells).
    const VolumeMesh deformed = readVolumeMesh(deformedPath, CellShapeCheck::Skipped);
    checkSameMesh(restAsRead, deformed, options.restPath, deformedPath);
    deformer.setFrame(deformed.positions, options.method);
    result.positions = deformer.positions();
    if (hasNormals) {
      if (options.normals == NormalMode::Keep) {
        result.normals = surface.normals;
      } else if (recompute) {
        result.normals = recomputedNormals(surface, result.positions, anchors);
      } else {
        result.normals = deformer.deformNormals(surface.normals, anchors);
      }
    }
    file = outPath;
    writeSurfaceFile(outPath, loaded, result);
    ++written;
  }

  std::cout << "deformed=" << written << " vertices=" << surface.numVertices()
            << " outside=" << embedding.outsideCount << " method=" << methodName(options.method)
            << " gradients=" << gradientSchemeName(options.settings.gradients) << '\n';
  return kExitSuccess;
}

}  // namespace

int runDeformCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] {
    const OptionSpec specs[] = {{"rest", true},    {"deformed", true}, {"surface", true},
                                {"method", true},  {"eps", true},      {"radius", true},
                                {"normals", true}, {"out", true},      {"gradients", true},
                                {"help", false}};
    return deformCommand(CliArgs::parse(args, specs), file);
  });
}

}  // namespace sculpt::cli
