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
    "      phong and attribute interpolation under a bend + twist, interior, surface and corner\n"
    "      cells, tets and hexes, node gradients by average and by fit; Kelvinlet grab/twist/\n"
    "      pinch at h/eps = 0.5, 0.25, 0.125) and writes DIR/phong-study.md and\n"
    "      DIR/phong-convergence-<case>.png. Last line: the slopes, phong_tet=<s>\n"
    "      phong_fit_tet=<s> linear_tet=<s> ... phong_hex_surface=<s> ...\n"
    "      phong_fit_hex_corner=<s>\n";

namespace {

constexpr OptionSpec kOptions[] = {{"out", true}, {"help", false}};
const double kSpacings[] = {0.1, 0.05, 0.025, 0.0125, 0.00625};
const char* const kMethodColumn[] = {"linear", "vertex", "phong", "attribute"};
const std::array<uint8_t, 3> kMethodColour[] = {{214, 39, 40}, {148, 103, 189}, {31, 119, 180},
                                                {255, 127, 14}};
const std::array<uint8_t, 3> kFitColour = {44, 160, 44};
constexpr size_t kLinear = 0, kVertex = 1, kPhong = 2, kAttribute = 3;

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

const char* cellsName(StudyCells cells) {
  return cells == StudyCells::Tetrahedra ? "tetrahedra" : "hexahedra";
}

const char* placementName(StudyPlacement placement) {
  switch (placement) {
    case StudyPlacement::Interior: return "interior";
    case StudyPlacement::Surface: return "surface";
    case StudyPlacement::Corner: return "corner";
  }
  return "?";
}

/// One test case with both node-gradient schemes (the linear and attribute columns do not
/// depend on the scheme).
struct SchemePair {
  ConvergenceSeries average, fit;
};

void appendConvergenceTable(std::string& md, const SchemePair& pair) {
  const ConvergenceSeries& average = pair.average;
  md += "\n### " + std::string(cellsName(average.cells)) + ", " +
        placementName(average.placement) +
        " test cell\n\n| h | mean edge | linear | attribute | vertex (average) | phong (average) | "
        "vertex (fit) | phong (fit) | linear / phong (fit) | average / fit |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (size_t r = 0; r < average.rows.size(); ++r) {
    const MethodErrors& a = average.rows[r].errors;
    const MethodErrors& f = pair.fit.rows[r].errors;
    md += "| " + format("%.5f", average.rows[r].spacing) + " | " +
          format("%.5f", average.rows[r].meanEdge);
    for (double e : {a.max[kLinear], a.max[kAttribute], a.max[kVertex], a.max[kPhong],
                     f.max[kVertex], f.max[kPhong]})
      md += " | " + format("%.3e", e);
    md += " | " + format("%.1f", a.max[kLinear] / f.max[kPhong]) + " | " +
          format("%.1f", a.max[kPhong] / f.max[kPhong]) + " |\n";
  }
  md += "| **slope** | |";
  for (double slope : {average.slopes[kLinear], average.slopes[kAttribute],
                       average.slopes[kVertex], average.slopes[kPhong], pair.fit.slopes[kVertex],
                       pair.fit.slopes[kPhong]})
    md += " **" + format("%.2f", slope) + "** |";
  md += " | |\n";
}

std::filesystem::path writeChart(const std::filesystem::path& dir, const SchemePair& pair) {
  const ConvergenceSeries& average = pair.average;
  LogLogChart chart;
  chart.title = std::string("Bend + twist, ") + cellsName(average.cells) + ", " +
                placementName(average.placement) + " cell";
  chart.xLabel = "mean edge length h";
  chart.yLabel = "max |f(X) - phi(X)|";
  auto addLine = [&](const ConvergenceSeries& series, size_t m, const std::string& name,
                     std::array<uint8_t, 3> rgb, bool dashed) {
    ChartSeries line;
    line.name = name + " (slope " + format("%.2f", series.slopes[m]) + ")";
    line.rgb = rgb;
    line.dashed = dashed;
    for (const ConvergenceRow& row : series.rows) {
      line.x.push_back(row.meanEdge);
      line.y.push_back(row.errors.max[m]);
    }
    chart.series.push_back(std::move(line));
  };
  addLine(average, kLinear, kMethodColumn[kLinear], kMethodColour[kLinear], false);
  addLine(average, kAttribute, kMethodColumn[kAttribute], kMethodColour[kAttribute], false);
  addLine(average, kVertex, "vertex, average", kMethodColour[kVertex], true);
  addLine(average, kPhong, "phong, average", kMethodColour[kPhong], false);
  addLine(pair.fit, kPhong, "phong, fit", kFitColour, false);
  const std::filesystem::path path =
      dir / (std::string("phong-convergence-") +
             (average.cells == StudyCells::Tetrahedra ? "tet" : "hex") + "-" +
             placementName(average.placement) + ".png");
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
      "log(mean edge length) over all rows. Node gradients: `average` is the paper's weighted\n"
      "average of cell gradients (eq. 12), `fit` the quadratic least-squares fit (docs/phong.md).\n"
      "The surface cell has no cells above it; the corner cell none above, in +x or in +y.\n";
  std::string summary =
      "\n### Slopes of phong\n\n| cells | test cell | linear | phong (average) | phong (fit) | "
      "finest-h error, average / fit |\n|---|---|---|---|---|---|\n";
  std::string sections, last;
  for (StudyPlacement placement :
       {StudyPlacement::Interior, StudyPlacement::Surface, StudyPlacement::Corner})
    for (StudyCells cells : {StudyCells::Tetrahedra, StudyCells::Hexahedra}) {
      std::cerr << "study: " << cellsName(cells) << ", " << placementName(placement) << '\n';
      const SchemePair pair{
          runConvergenceStudy(cells, placement, kSpacings, GradientScheme::Average),
          runConvergenceStudy(cells, placement, kSpacings, GradientScheme::Fit)};
      appendConvergenceTable(sections, pair);
      const std::filesystem::path chart = writeChart(dir, pair);
      sections += "\n![" + chart.filename().string() + "](" + chart.filename().string() + ")\n";
      summary += std::string("| ") + cellsName(cells) + " | " + placementName(placement) + " | " +
                 format("%.2f", pair.average.slopes[kLinear]) + " | " +
                 format("%.2f", pair.average.slopes[kPhong]) + " | " +
                 format("%.2f", pair.fit.slopes[kPhong]) + " | " +
                 format("%.1f", pair.average.rows.back().errors.max[kPhong] /
                                    pair.fit.rows.back().errors.max[kPhong]) +
                 " |\n";
      const std::string tag = std::string(cells == StudyCells::Tetrahedra ? "tet" : "hex") +
                              (placement == StudyPlacement::Interior
                                   ? ""
                                   : std::string("_") + placementName(placement));
      last += "phong_" + tag + "=" + format("%.2f", pair.average.slopes[kPhong]) + " phong_fit_" +
              tag + "=" + format("%.2f", pair.fit.slopes[kPhong]) + " linear_" + tag + "=" +
              format("%.2f", pair.average.slopes[kLinear]) + " attribute_" + tag + "=" +
              format("%.2f", pair.average.slopes[kAttribute]) + " ";
    }
  md += summary + sections;

  md +=
      "\n## Regularized Kelvinlets (eps = 1, nu = 0.45, largest displacement eps/4)\n\n"
      "2000 test points in the ball of radius 1.5 eps; tet lattice of [-2, 2]^3 with cube edge h;\n"
      "phong with the paper's averaged node gradients (all test points are interior).\n\n"
      "| lattice | brush | h/eps | rms linear | rms phong | rms ratio | max ratio |\n"
      "|---|---|---|---|---|---|---|\n";
  const double ratios[] = {0.5, 0.25, 0.125};
  for (bool jittered : {false, true}) {
    std::cerr << "study: Kelvinlets, " << (jittered ? "jittered" : "regular") << " lattice\n";
    for (const KelvinletRow& row : runKelvinletStudy(ratios, jittered, GradientScheme::Average))
      md += std::string("| ") + (jittered ? "jittered 15%" : "regular") + " | " +
            brushName(row.brush) + " | " + format("%.3f", row.spacingOverEps) + " | " +
            format("%.3e", row.errors.rms[0]) + " | " + format("%.3e", row.errors.rms[2]) +
            " | " + format("%.2f", row.rmsRatio) + " | " + format("%.2f", row.maxRatio) + " |\n";
  }
  writeFileAtomically(dir / "phong-study.md", md);
  std::cerr << "study: wrote " << (dir / "phong-study.md").string() << " and 6 charts\n";
  std::cout << last << '\n';
  return kExitSuccess;
}

}  // namespace

int runStudyCommand(const std::vector<std::string>& args) {
  std::string file;
  return runGuarded(file, [&] { return study(CliArgs::parse(args, kOptions)); });
}

}  // namespace sculpt::cli
