// sculpt-cli study phong --out DIR
//
// Reruns the Phong Deformation accuracy experiments (the convergence study of James 2020 Fig. 10
// and the Kelvinlet comparison) with this program's deformer, and writes what docs/ shows:
// DIR/phong-study.md (tables) and DIR/phong-convergence-*.png (log-log plots).

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "cli/cli_args.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/loglog_chart.h"
#include "embed/interpolation_study.h"
#include "io/atomic_file.h"

namespace sculpt::cli {

const char* const kStudyUsage =
    "  study phong --out DIR\n"
    "      Reruns the Phong Deformation accuracy experiments (convergence of linear, vertex,\n"
    "      phong and attribute interpolation under a bend + twist, interior and surface cells,\n"
    "      tets and hexes; Kelvinlet grab/twist/pinch at h/eps = 0.5, 0.25, 0.125) and writes\n"
    "      DIR/phong-study.md and DIR/phong-convergence-<case>.png. Last line: the interior\n"
    "      slopes, phong_tet=<s> linear_tet=<s> attribute_tet=<s> phong_hex=<s> ...\n";

namespace {

constexpr OptionSpec kOptions[] = {{"out", true}, {"help", false}};
const double kSpacings[] = {0.1, 0.05, 0.025, 0.0125, 0.00625};
const char* const kMethodColumn[] = {"linear", "vertex", "phong", "attribute"};
const std::array<uint8_t, 3> kMethodColour[] = {{214, 39, 40}, {148, 103, 189}, {31, 119, 180},
                                                {255, 127, 14}};

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

const char* cellsName(StudyCells cells) {
  return cells == StudyCells::Tetrahedra ? "tetrahedra" : "hexahedra";
}

const char* placementName(StudyPlacement placement) {
  return placement == StudyPlacement::Interior ? "interior" : "surface";
}

void appendConvergenceTable(std::string& md, const ConvergenceSeries& series) {
  md += "\n### " + std::string(cellsName(series.cells)) + ", " + placementName(series.placement) +
        " test cell\n\n| h | mean edge | linear | vertex | phong | attribute | linear / phong |\n"
        "|---|---|---|---|---|---|---|\n";
  for (const ConvergenceRow& row : series.rows) {
    md += "| " + format("%.5f", row.spacing) + " | " + format("%.5f", row.meanEdge);
    for (double e : row.errors.max) md += " | " + format("%.3e", e);
    md += " | " + format("%.1f", row.errors.max[0] / row.errors.max[2]) + " |\n";
  }
  md += "| **slope** | |";
  for (double slope : series.slopes) md += " **" + format("%.2f", slope) + "** |";
  md += " |\n";
}

std::filesystem::path writeChart(const std::filesystem::path& dir, const ConvergenceSeries& series) {
  LogLogChart chart;
  chart.title = std::string("Bend + twist, ") + cellsName(series.cells) + ", " +
                placementName(series.placement) + " cell";
  chart.xLabel = "mean edge length h";
  chart.yLabel = "max |f(X) - phi(X)|";
  for (size_t m = 0; m < kAllMethods.size(); ++m) {
    ChartSeries line;
    line.name = std::string(kMethodColumn[m]) + " (slope " + format("%.2f", series.slopes[m]) + ")";
    line.rgb = kMethodColour[m];
    line.dashed = kAllMethods[m] == InterpolationMethod::Vertex;
    for (const ConvergenceRow& row : series.rows) {
      line.x.push_back(row.meanEdge);
      line.y.push_back(row.errors.max[m]);
    }
    chart.series.push_back(std::move(line));
  }
  const std::filesystem::path path = dir / (std::string("phong-convergence-") +
                                            (series.cells == StudyCells::Tetrahedra ? "tet" : "hex") +
                                            "-" + placementName(series.placement) + ".png");
  writeLogLogChartPng(path, chart);
  return path;
}

int study(const CliArgs& args) {
  if (args.has("help")) {
    std::cout << "usage:\n" << kStudyUsage;
    return kExitSuccess;
  }
  if (args.positional().size() != 1 || args.positional()[0] != "phong")
    throw UsageError("study needs the experiment name: phong");
  const std::filesystem::path dir = args.requiredValue("out");
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw UsageError("cannot create " + dir.string() + ": " + error.message());

  std::string md =
      "<!-- written by `sculpt-cli study phong --out " + dir.string() + "`; do not edit -->\n"
      "## Convergence (bend + twist, 25 test points at fixed local positions)\n\n"
      "Largest error over the test points. Slopes are least-squares fits of log(error) against\n"
      "log(mean edge length) over all rows.\n";
  std::string last;
  for (StudyPlacement placement : {StudyPlacement::Interior, StudyPlacement::Surface})
    for (StudyCells cells : {StudyCells::Tetrahedra, StudyCells::Hexahedra}) {
      std::cerr << "study: " << cellsName(cells) << ", " << placementName(placement) << '\n';
      const ConvergenceSeries series = runConvergenceStudy(cells, placement, kSpacings);
      appendConvergenceTable(md, series);
      const std::filesystem::path chart = writeChart(dir, series);
      md += "\n![" + chart.filename().string() + "](" + chart.filename().string() + ")\n";
      const std::string tag = std::string(cells == StudyCells::Tetrahedra ? "tet" : "hex") +
                              (placement == StudyPlacement::Interior ? "" : "_surface");
      last += "phong_" + tag + "=" + format("%.2f", series.slopes[2]) + " linear_" + tag + "=" +
              format("%.2f", series.slopes[0]) + " attribute_" + tag + "=" +
              format("%.2f", series.slopes[3]) + " ";
    }

  md += "\n## Regularized Kelvinlets (eps = 1, nu = 0.45, largest displacement eps/4)\n\n"
        "2000 test points in the ball of radius 1.5 eps; tet lattice of [-2, 2]^3 with cube edge h.\n\n"
        "| lattice | brush | h/eps | rms linear | rms phong | rms ratio | max ratio |\n"
        "|---|---|---|---|---|---|---|\n";
  const double ratios[] = {0.5, 0.25, 0.125};
  for (bool jittered : {false, true}) {
    std::cerr << "study: Kelvinlets, " << (jittered ? "jittered" : "regular") << " lattice\n";
    for (const KelvinletRow& row : runKelvinletStudy(ratios, jittered))
      md += std::string("| ") + (jittered ? "jittered 15%" : "regular") + " | " +
            brushName(row.brush) + " | " + format("%.3f", row.spacingOverEps) + " | " +
            format("%.3e", row.errors.rms[0]) + " | " + format("%.3e", row.errors.rms[2]) +
            " | " + format("%.2f", row.rmsRatio) + " | " + format("%.2f", row.maxRatio) + " |\n";
  }
  writeFileAtomically(dir / "phong-study.md", md);
  std::cerr << "study: wrote " << (dir / "phong-study.md").string() << " and 4 charts\n";
  std::cout << last << '\n';
  return kExitSuccess;
}

}  // namespace

int runStudyCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] { return study(CliArgs::parse(args, kOptions)); });
}

}  // namespace sculpt::cli
