// sculpt-cli bench deform [--vertices N] [--method M] [--gradients fit|average] [--repeat R]
//
// The built-in scene: a 20x20x20-cube tetrahedral lattice of the unit cube (9261 nodes, 48000
// tetrahedra) and N points on a bumpy sphere inside it (a stand-in for a detailed surface, in a
// coherent order as mesh files have). A frame is what the application does per displayed frame:
// new node positions in, gradients, per-cell coefficients and every point's position out
// (single precision, cell-sorted structure of arrays, all worker threads). For the methods that
// use node gradients, frames with the other gradient scheme are interleaved in the same run.

#include "cli/bench_deform.h"
#include "cli/bench_timing.h"
#include "cli/cli_common.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "embed/embedded_deformer.h"
#include "embed/interpolation_study.h"
#include "mesh/lattice_mesh.h"
#include "util/parallel_for.h"

namespace sculpt::cli {

const OptionSpec kBenchDeformOptions[4] = {
    {"vertices", true}, {"method", true}, {"gradients", true}, {"repeat", true}};

namespace {

using Clock = BenchClock;

/// N points on a bumpy sphere (Fibonacci spiral order: neighbours in the list are neighbours in
/// space, as in a real mesh's vertex order).
Points bumpySphere(uint32_t n) {
  Points points(n, 3);
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (uint32_t i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n;
    const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * i;
    const Eigen::Vector3d direction(ring * std::cos(phi), ring * std::sin(phi), z);
    const double radius = 0.4 + 0.03 * std::sin(7 * phi) * std::sin(5 * std::acos(z));
    points.row(i) = (Eigen::Vector3d::Constant(0.5) + radius * direction).transpose();
  }
  return points;
}

}  // namespace

int benchDeform(const CliArgs& args) {
  const int vertices = args.intValue("vertices", 1'000'000, 1, 50'000'000);
  const int repeat = args.intValue("repeat", 31, 1, 10'000);
  const std::string methodName = args.value("method").value_or("phong");
  const auto method = parseInterpolationMethod(methodName);
  if (!method)
    throw UsageError("unknown method '" + methodName +
                     "' (expected phong, linear, vertex or attribute)");

  LatticeSpec spec;
  spec.cubes = {20, 20, 20};
  spec.spacing = 1.0 / 20;
  VolumeMesh mesh = tetLattice(spec);
  const Points surface = bumpySphere(static_cast<uint32_t>(vertices));

  const GradientScheme scheme = gradientSchemeOption(args);
  const GradientScheme otherScheme =
      scheme == GradientScheme::Fit ? GradientScheme::Average : GradientScheme::Fit;
  const bool usesGradients =
      *method == InterpolationMethod::Phong || *method == InterpolationMethod::Vertex;
  DeformerSettings settings;
  settings.buildAttributeWeights = *method == InterpolationMethod::Attribute;
  settings.gradients = scheme;
  const Clock::time_point embedStart = Clock::now();
  EmbeddedDeformer deformer(mesh, surface, settings);
  const double embedMs = millisecondsSince(embedStart);
  std::optional<EmbeddedDeformer> other;
  if (usesGradients) {
    settings.gradients = otherScheme;
    other.emplace(mesh, surface, settings);
  }

  // Frames alternate between two deformed states so that nothing is cached across frames.
  Points frames[2];
  for (int f = 0; f < 2; ++f) {
    frames[f].resize(mesh.positions.rows(), 3);
    for (Eigen::Index i = 0; i < mesh.positions.rows(); ++i) {
      const Eigen::Vector3d X = mesh.positions.row(i).transpose() - Eigen::Vector3d::Constant(0.5);
      frames[f].row(i) = ((1.0 - 0.1 * f) * bendAndTwist(X)).transpose();
    }
  }
  FloatPositions out;
  out.resize(deformer.numPoints());
  const auto timedFrame = [&](EmbeddedDeformer& d, const Points& frame, InterpolationMethod m) {
    const Clock::time_point start = Clock::now();
    d.setFrame(frame, m);
    d.evaluateSorted(out.x.data(), out.y.data(), out.z.data());
    return millisecondsSince(start);
  };
  // Each timed frame of the method is followed by a linear frame on the same data, and by one
  // with the other gradient scheme, so that the ratios come from one run (these machines are
  // shared and noisy).
  const bool compare = *method != InterpolationMethod::Linear;
  std::vector<double> samples, nodeStage, pointStage, linearSamples, ratios, otherSamples,
      schemeRatios;
  for (int r = -2; r < repeat; ++r) {  // two untimed warm-up frames
    const Points& frame = frames[(r + 2) % 2];
    const Clock::time_point start = Clock::now();
    deformer.setFrame(frame, *method);
    const Clock::time_point middle = Clock::now();
    deformer.evaluateSorted(out.x.data(), out.y.data(), out.z.data());
    const double total = millisecondsSince(start);
    const double linear = compare ? timedFrame(deformer, frame, InterpolationMethod::Linear) : 0.0;
    const double otherMs = other ? timedFrame(*other, frame, *method) : 0.0;
    if (r < 0) continue;
    samples.push_back(total);
    nodeStage.push_back(std::chrono::duration<double, std::milli>(middle - start).count());
    pointStage.push_back(total - nodeStage.back());
    if (compare) {
      linearSamples.push_back(linear);
      ratios.push_back(total / linear);
    }
    if (other) {
      otherSamples.push_back(otherMs);
      schemeRatios.push_back(total / otherMs);
    }
  }
  const double medianMs = median(samples);
  std::cerr << "bench deform: per frame, gradients and cell coefficients " << median(nodeStage)
            << " ms, points " << median(pointStage) << " ms (medians)\n";
  if (compare)
    std::cerr << "bench deform: linear frames interleaved in the same run " << median(linearSamples)
              << " ms; median ratio " << methodName << "/linear " << median(ratios) << '\n';
  const std::string schemeName(gradientSchemeName(scheme)),
      otherName(gradientSchemeName(otherScheme));
  if (other)
    std::cerr << "bench deform: " << otherName << " gradients interleaved in the same run "
              << median(otherSamples) << " ms; median ratio " << schemeName << "/" << otherName
              << " " << median(schemeRatios) << '\n';
  char line[320];
  std::snprintf(line, sizeof line,
                "deform_ms=%.3f embed_ms=%.1f vertices=%d method=%s gradients=%s threads=%u",
                medianMs, embedMs, vertices, methodName.c_str(), schemeName.c_str(), workerCount());
  std::string last = line;
  if (other) {
    std::snprintf(line, sizeof line, " %s_over_%s=%.3f", schemeName.c_str(), otherName.c_str(),
                  median(schemeRatios));
    last += line;
  }
  std::cerr << "bench deform: " << mesh.numNodes() << " nodes, " << mesh.numCells()
            << " tetrahedra, " << deformer.embedding().outsideCount << " points outside\n";
  std::cout << last << '\n';
  return 0;
}

}  // namespace sculpt::cli
