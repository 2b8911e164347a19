// sculpt-cli's FEM commands end to end (static, simulate, bench fem, info --levels): they run the
// built binary on the assets and check exit codes, the key=value last lines, the VTK output and
// that bad input is one "error:" line with exit code 2.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/cli_fixture.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

const std::string kAssets = SCULPT_SOURCE_DIR "/assets/";

// Boxes on the assets. beam.json is [0,10]x[0,1]x[0,1]; block3.json is [0,3]^3.
const std::string kBeamRoot = "--fix -1,-1,-1,0.01,2,2";
const std::string kBeamTip = "9.99,-1,-1,11,2,2";
const std::string kBlockBottom = "--fix -1,-1,-1,4,0.01,4";  // the 16 control points at y = 0
const std::string kBlockTop = "-1,2.99,-1,4,4,4";

using test::CliResult;
using test::isMilliseconds;
using test::KeyValues;
using test::keyValues;
using test::quote;
using test::readText;

std::vector<std::string> keys(const KeyValues& pairs) {
  std::vector<std::string> names;
  for (const auto& [key, value] : pairs) names.push_back(key);
  return names;
}

// The whole text as a number (strtod accepts "nan" and "inf", which the callers reject).
double number(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  EXPECT_TRUE(!text.empty() && end == text.c_str() + text.size()) << "'" << text << "'";
  return value;
}

std::map<std::string, double> numbers(const KeyValues& pairs) {
  std::map<std::string, double> values;
  for (const auto& [key, value] : pairs)
    if (key != "model") values[key] = number(value);  // the one word among them
  return values;
}

// The POINT_DATA vector `name` of a legacy VTK file: one row per point; empty when absent.
std::vector<std::array<double, 3>> pointVectors(const std::string& vtk, const std::string& name) {
  std::vector<std::array<double, 3>> rows;
  const size_t data = vtk.find("\nPOINT_DATA ");
  if (data == std::string::npos) return rows;
  std::istringstream in(vtk.substr(data + 1));
  std::string word, field, type;
  size_t count = 0;
  in >> word >> count;
  for (;;) {
    if (!(in >> word)) return {};
    if (word == "VECTORS") {
      in >> field >> type;
      if (field == name) break;
      for (size_t i = 0; i < 3 * count; ++i) in >> word;  // another field
    }
  }
  for (size_t i = 0; i < count; ++i) {
    std::array<double, 3> row{};
    for (double& v : row) {
      if (!(in >> word)) return {};
      v = std::strtod(word.c_str(), nullptr);
      if (!std::isfinite(v)) ADD_FAILURE() << name << " row " << i << ": " << word;
    }
    rows.push_back(row);
  }
  return rows;
}

bool hasNonFiniteText(const std::string& text) {
  for (const char* bad : {"nan", "NaN", "NAN", "inf", "Inf", "INF"})
    if (text.find(bad) != std::string::npos) return true;
  return false;
}

class FemCliTest : public test::CliFixture {
 protected:
  FemCliTest() : CliFixture("sculpt_fem_cli_test_") {}

  // Runs static on the beam (trilinear, root fixed) with the tip force (0, fy, 0); returns
  // max_displacement.
  double staticBeam(double fy, const std::string& extra, const std::string& out) const {
    std::ostringstream args;
    args << "static " << quote(kAssets + "beam.json") << " --trilinear " << kBeamRoot << " --force "
         << kBeamTip << " 0," << fy << ",0 " << extra << " --out " << quote(out);
    SCOPED_TRACE(args.str());
    const CliResult result = run(args.str());
    EXPECT_EQ(result.exitCode, 0) << result.err;
    const KeyValues pairs = keyValues(result.lastLine());
    EXPECT_EQ(keys(pairs), (std::vector<std::string>{"max_displacement", "iterations", "residual"}))
        << result.lastLine();
    if (pairs.empty()) return 0;
    return number(pairs[0].second);
  }
};

const std::vector<std::string> kSimulateKeys = {
    "steps",          "time",     "max_displacement", "kinetic_energy",
    "elastic_energy", "substeps", "cg_iterations",    "model",
    "min_jacobian",   "inverted_elements"};

TEST_F(FemCliTest, HelpListsTheFemCommands) {
  const CliResult help = run("--help");
  EXPECT_EQ(help.exitCode, 0);
  for (const char* text : {"static CONTROL.json", "simulate CONTROL.json", "bench fem CONTROL.json",
                           "fem: elements=<n> BE=<%> LE=<%> PE=<%>", "y axis points up"})
    EXPECT_NE(help.out.find(text), std::string::npos) << text;
  EXPECT_EQ(run("simulate --help").exitCode, 0);
  EXPECT_EQ(run("bench --help").exitCode, 0);
}

TEST_F(FemCliTest, StaticBeamTipForceWritesDisplacementsAndIsLinear) {
  const std::string out = path("beam.vtk");
  const double corotated = staticBeam(-10, "", out);
  EXPECT_GT(corotated, 0);
  EXPECT_TRUE(std::isfinite(corotated));
  // The VTK file: the deformed control mesh with one displacement row per control point (44),
  // the tip moved down and the fixed root not at all.
  const std::string vtk = readText(out);
  EXPECT_NE(vtk.find("\nPOINTS 44 "), std::string::npos);
  EXPECT_NE(vtk.find("\nPOINT_DATA 44\n"), std::string::npos);
  const auto displacement = pointVectors(vtk, "displacement");
  ASSERT_EQ(displacement.size(), 44u);
  EXPECT_EQ(displacement[0], (std::array<double, 3>{0, 0, 0}));  // vertex (0,0,0), fixed
  EXPECT_LT(displacement[10][1], 0);                             // vertex (10,0,0), the tip

  // Small-strain elasticity is linear in the load: twice the force, twice the displacement.
  const double once = staticBeam(-10, "--linear", path("once.vtk"));
  const double twice = staticBeam(-20, "--linear", path("twice.vtk"));
  ASSERT_GT(once, 0);
  EXPECT_NEAR(twice / once, 2.0, 2e-6);
  // A small load hardly rotates anything, so co-rotated and linear nearly agree.
  EXPECT_NEAR(corotated / once, 1.0, 0.01);
}

TEST_F(FemCliTest, StaticConvergesAtEveryLoadFromANanoNewtonToAKiloNewton) {
  // E = 2e5 Pa: the tip deflection goes from 1e-11 m (the elastic forces' rounding is then a
  // third of the load) to three quarters of the beam's length (large rotations).
  const std::string stiffness = "--E 2e5";
  std::map<double, double> tip;
  for (double load : {1e-9, 1e-6, 1e-3, 1.0, 1e3}) {
    tip[load] = staticBeam(-load, stiffness, path("load.vtk"));
    std::printf("[ measured ] tip load %g N: max displacement %.9g m\n", load, tip[load]);
  }
  // Small loads: linear in the load to 1e-5, down to the smallest.
  for (double load : {1e-9, 1e-6})
    EXPECT_NEAR(tip[load] / load, tip[1e-3] / 1e-3, 1e-5 * tip[1e-3] / 1e-3) << load;
  // 1 kN: far beyond the linear range, the beam bends and stiffens (an elastica shortens its
  // lever arm), so it moves less than linear scaling says (13 m), but still most of its length.
  EXPECT_LT(tip[1e3], 0.7 * 1e6 * tip[1e-3]);
  EXPECT_GT(tip[1e3], 5.0);
  const CliResult big = run("static " + quote(kAssets + "beam.json") + " --trilinear " + kBeamRoot +
                            " --force " + kBeamTip + " 0,-1e3,0 " + stiffness + " --out " +
                            quote(path("big.vtk")));
  // Load steps to 1e-9 of the load, or (depending on the factorisation's last bits) the rounding
  // floor of the elastic forces, which sits at about that level here (docs/fem.md).
  EXPECT_TRUE(big.err.find("load steps") != std::string::npos ||
              big.err.find("rounding of the elastic forces") != std::string::npos)
      << big.err;
  EXPECT_LE(number(keyValues(big.lastLine()).at(2).second), 2e-9) << big.lastLine();
}

TEST_F(FemCliTest, StaticSaysWhenTheLoadCannotMoveTheSolid) {
  // E = 1e308 Pa: the displacement is below what the positions can represent. Not an answer.
  const CliResult result = run("static " + quote(kAssets + "beam.json") + " --trilinear " +
                               kBeamRoot + " --force " + kBeamTip + " 0,-1,0 --E 1e308 --out " +
                               quote(path("stiff.vtk")));
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_NE(result.err.find("too small for this stiffness"), std::string::npos) << result.err;
}

TEST_F(FemCliTest, SimulateRefusesLoadsBeyondDoublePrecision) {
  // 1e200 N: the work of the load overflows. The step is refused with a sentence (exit 1), not
  // reported as a motionless success.
  const CliResult result =
      run("simulate " + quote(kAssets + "block3.json") + " --levels 1 --force 0,0,0,4,4,4 " +
          "1e200,0,0 --dt 0.01 --steps 3 --out " + quote(path("huge.vtk")));
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_NE(result.err.find("the loads are too large"), std::string::npos) << result.err;
  // A large but representable load still runs. (1e30 N, which moves the block 1e23 m, now
  // ends with a sentence: at such positions rounding alone turns elements inside out, which the
  // inversion barrier prices at 1e199 J, more than the loads supplied.)
  const CliResult large =
      run("simulate " + quote(kAssets + "block3.json") + " --levels 1 --force 0,0,0,4,4,4 " +
          "1e12,0,0 --dt 0.01 --steps 3 --out " + quote(path("large.vtk")));
  EXPECT_EQ(large.exitCode, 0) << large.err;
  EXPECT_GT(numbers(keyValues(large.lastLine())).at("max_displacement"), 1e4);
}

// The top of block3 (E = 1e5 Pa) grabbed with a stiff spring and pushed 6 m down through its
// fixed bottom in half a second, held, and let go at 1 s; the run ends 1 s later.
TEST_F(FemCliTest, TheInversionBarrierTurnsASolidPushedThroughItselfBack) {
  const std::string script = path("squash.json");
  test::writeText(script, R"({"format": "sculpt-session", "version": 1, "events": [
    {"t": 0, "type": "grab", "point": [1.5, 3, 1.5], "stiffness": 1e7,
     "path": [[0, 1.5, 3, 1.5], [0.5, 1.5, -3, 1.5]], "release": 1.0}]})");
  std::map<std::string, std::map<std::string, double>> last;
  for (const char* model : {"barrier", "corotated"}) {
    const CliResult result =
        run("simulate " + quote(kAssets + "block3.json") + " --levels 1 " + kBlockBottom +
            " --model " + model + " --dt 0.01 --steps 200 --script " + quote(script) + " --out " +
            quote(path(std::string(model) + ".vtk")));
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const KeyValues pairs = keyValues(result.lastLine());
    ASSERT_EQ(keys(pairs), kSimulateKeys) << result.lastLine();
    EXPECT_EQ(pairs[7].second, model);
    last[model] = numbers(pairs);
    std::printf("%s: %s\n", model, result.lastLine().c_str());
  }
  // Measured: barrier min_jacobian 0.61, no element inverted; corotated -0.037 with 20 inverted.
  EXPECT_EQ(last["barrier"].at("inverted_elements"), 0);
  EXPECT_GT(last["barrier"].at("min_jacobian"), 0.3);
  EXPECT_GT(last["corotated"].at("inverted_elements"), 0);
  EXPECT_LT(last["corotated"].at("min_jacobian"), 0.0);
  expectBadInput("simulate " + quote(kAssets + "block3.json") +
                     " --model neo --dt 0.01 --steps 1 " + "--out " + quote(path("x.vtk")),
                 "--model must be barrier or corotated, got 'neo'");
}

// Three times E on the top faces: the linearised step has no minimum. It was taken unsolved
// (CG stopped at its first direction: cg_iterations=0, nothing moved, exit 0); now it is retried
// with sub-steps, which add inertia until the system is definite, and says so.
TEST_F(FemCliTest, APressureBeyondTheLimitPointIsNotAnUnsolvedStep) {
  const std::string script = path("inflate.json");
  test::writeText(script, R"({"format": "sculpt-session", "version": 1, "events": [
    {"t": 0, "type": "inflate", "centre": [1.5, 3, 1.5], "radius": 1.6, "pressure": 3e5,
     "duration": 1}]})");
  const CliResult result =
      run("simulate " + quote(kAssets + "block3.json") + " --levels 1 " + kBlockBottom +
          " --dt 0.05 --steps 2 --script " + quote(script) + " --out " + quote(path("i.vtk")));
  EXPECT_NE(result.err.find("the step's system is not positive definite"), std::string::npos)
      << result.err;
  EXPECT_FALSE(hasNonFiniteText(result.lastLine())) << result.lastLine();
  if (result.exitCode == 0) {
    EXPECT_GT(numbers(keyValues(result.lastLine())).at("cg_iterations"), 0);
  }
}

TEST_F(FemCliTest, StaticBadInputIsOneErrorLine) {
  const std::string beam = quote(kAssets + "beam.json");
  const std::string out = " --out " + quote(path("x.vtk"));
  const std::string load = " --force " + kBeamTip + " 0,-1,0";
  expectBadInput("static " + beam + " --fix 0,0,0,1,1" + out, "--fix: '0,0,0,1,1' must be");
  expectBadInput("static " + beam + " --fix 0,0,0,x,1,1" + out, "not a finite number");
  expectBadInput("static " + beam + " --fix 1,0,0,0,1,1" + out, "minimum above its maximum");
  expectBadInput("static " + beam + " --fix 20,0,0,21,1,1" + load + out,
                 "--fix 20,0,0,21,1,1 contains no control point");
  expectBadInput("static " + beam + " --levels 0 " + kBeamRoot + out, "--levels must be");
  expectBadInput("static " + beam + " " + kBeamRoot + load, "--out is required");
  expectBadInput("static " + beam + " " + kBeamRoot + " --bogus" + out, "unknown option '--bogus'");
  expectBadInput("static " + beam + " --E -5 " + kBeamRoot + out, "Young's modulus");
  expectBadInput("static " + beam + " --nu 0.5 " + kBeamRoot + out, "Poisson ratio");
  EXPECT_FALSE(fs::exists(path("x.vtk")));
}

TEST_F(FemCliTest, SimulateBlockUnderGravityImplicit) {
  const std::string out = path("block.vtk");
  const CliResult result =
      run("simulate " + quote(kAssets + "block3.json") + " --levels 1 " + kBlockBottom +
          " --gravity --integrator implicit --dt 0.01 --steps 20 --out " + quote(out));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const KeyValues pairs = keyValues(result.lastLine());
  ASSERT_EQ(keys(pairs), kSimulateKeys) << result.lastLine();
  EXPECT_FALSE(hasNonFiniteText(result.lastLine())) << result.lastLine();
  const auto v = numbers(pairs);
  EXPECT_EQ(v.at("steps"), 20);
  EXPECT_NEAR(v.at("time"), 0.2, 1e-12);
  EXPECT_GT(v.at("max_displacement"), 0);
  EXPECT_TRUE(std::isfinite(v.at("kinetic_energy")));
  EXPECT_GE(v.at("kinetic_energy"), 0);
  EXPECT_TRUE(std::isfinite(v.at("elastic_energy")));
  EXPECT_GT(v.at("elastic_energy"), 0);
  EXPECT_GE(v.at("substeps"), 20);
  EXPECT_GT(v.at("cg_iterations"), 0);
  // Gravity pulls down (-y): the top of the block sinks, the fixed bottom stays.
  const auto displacement = pointVectors(readText(out), "displacement");
  ASSERT_EQ(displacement.size(), 64u);
  EXPECT_EQ(displacement[0], (std::array<double, 3>{0, 0, 0}));  // (0,0,0), fixed
  EXPECT_LT(displacement[63][1], 0);                             // (3,3,3)
}

TEST_F(FemCliTest, SimulatePaperIntegratorAtATinyStep) {
  const CliResult result =
      run("simulate " + quote(kAssets + "block3.json") + " --levels 1 " + kBlockBottom +
          " --gravity --integrator paper --dt 1e-4 --steps 20 --out " + quote(path("p.vtk")));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const KeyValues pairs = keyValues(result.lastLine());
  ASSERT_EQ(keys(pairs), kSimulateKeys) << result.lastLine();
  const auto v = numbers(pairs);
  EXPECT_EQ(v.at("steps"), 20);
  EXPECT_EQ(v.at("substeps"), 20);  // stable without halving
  EXPECT_GT(v.at("max_displacement"), 0);
  EXPECT_TRUE(std::isfinite(v.at("kinetic_energy")) && std::isfinite(v.at("elastic_energy")));
  EXPECT_TRUE(result.errLines().empty()) << result.err;  // no step messages
}

TEST_F(FemCliTest, SimulateAbsurdInputsNeverPrintNonFiniteValues) {
  // Stiff (E = 1e12), a 10 s step and 1e9 N on the top: the paper scheme cannot do this. The
  // command must say what happened and keep everything finite.
  for (const char* mode : {"--trilinear", "--levels 1"}) {
    for (const std::string integrator : {"paper", "implicit"}) {
      const std::string out = path("absurd.vtk");
      const std::string args = "simulate " + quote(kAssets + "block3.json") + " " + mode +
                               " --integrator " + integrator + " --E 1e12 " + kBlockBottom +
                               " --force " + kBlockTop + " 0,1e9,0 --dt 10 --steps 3 --out " +
                               quote(out);
      SCOPED_TRACE(args);
      const CliResult result = run(args);
      EXPECT_FALSE(result.signaled);
      EXPECT_TRUE(result.exitCode == 0 || result.exitCode == 1) << result.exitCode << result.err;
      const KeyValues pairs = keyValues(result.lastLine());
      ASSERT_EQ(keys(pairs), kSimulateKeys) << result.lastLine();
      EXPECT_FALSE(hasNonFiniteText(result.lastLine())) << result.lastLine();
      for (const auto& [key, value] : numbers(pairs)) EXPECT_TRUE(std::isfinite(value)) << key;
      const std::string vtk = readText(out);
      EXPECT_FALSE(hasNonFiniteText(vtk));
      EXPECT_EQ(pointVectors(vtk, "displacement").size(), 64u);
      if (result.exitCode == 1) {
        // A failed step: stderr says so, and that the state before it was kept.
        EXPECT_NE(result.err.find("even with"), std::string::npos) << result.err;
        EXPECT_NE(result.err.find("simulate: stopped at step"), std::string::npos) << result.err;
        EXPECT_LT(numbers(pairs).at("steps"), 3);
      } else if (numbers(pairs).at("substeps") > 3) {
        EXPECT_NE(result.err.find("sub-steps of"), std::string::npos) << result.err;
      }
      if (integrator == "paper") {
        EXPECT_FALSE(result.errLines().empty()) << "the paper scheme needs sub-steps here";
      }
    }
  }
}

TEST_F(FemCliTest, SimulateReportsEachKindOfStepMessageOnce) {
  // The paper scheme at 0.01 s is unstable for E = 1e7 on the trilinear block: nearly every step
  // is redone with sub-steps. The message comes once, then a count.
  const CliResult result = run("simulate " + quote(kAssets + "block3.json") +
                               " --trilinear --integrator paper " + "--E 1e7 " + kBlockBottom +
                               " --gravity --dt 0.01 --steps 40 --out " + quote(path("m.vtk")));
  ASSERT_TRUE(result.exitCode == 0 || result.exitCode == 1) << result.err;
  const auto lines = result.errLines();
  int firsts = 0, counts = 0;
  for (const std::string& line : lines) {
    if (line.rfind("simulate: step ", 0) == 0) ++firsts;
    if (line.find(" steps reported a message like step ") != std::string::npos) ++counts;
  }
  const auto v = numbers(keyValues(result.lastLine()));
  ASSERT_GT(v.at("substeps"), v.at("steps")) << result.err;  // sub-steps were taken
  EXPECT_GE(firsts, 1);
  EXPECT_LE(firsts, 3) << result.err;
  EXPECT_GE(counts, 1) << result.err;  // the sub-step message, 38 or so times
  EXPECT_LE(counts, firsts) << result.err;
  EXPECT_LE(lines.size(), 8u) << result.err;
}

TEST_F(FemCliTest, SimulateBadInputIsOneErrorLine) {
  const std::string block = quote(kAssets + "block3.json") + " --levels 1 " + kBlockBottom;
  const std::string out = " --out " + quote(path("x.vtk"));
  expectBadInput("simulate " + block + " --dt 0 --steps 1" + out, "--dt must be above 0");
  expectBadInput("simulate " + block + " --dt -1 --steps 1" + out, "--dt must be above 0");
  expectBadInput("simulate " + block + " --dt 11 --steps 1" + out, "at most 10");
  expectBadInput("simulate " + block + " --dt nan --steps 1" + out, "not a finite number");
  expectBadInput("simulate " + block + " --dt inf --steps 1" + out, "not a finite number");
  expectBadInput("simulate " + block + " --dt 0.01 --steps 0" + out, "--steps must be");
  expectBadInput("simulate " + block + " --dt 0.01 --steps 10000001" + out, "1 to 10000000");
  expectBadInput("simulate " + block + " --steps 1" + out, "--dt is required");
  expectBadInput("simulate " + block + " --dt 0.01" + out, "--steps is required");
  expectBadInput("simulate " + block + " --dt 0.01 --steps 1", "--out is required");
  expectBadInput("simulate " + block + " --dt 0.01 --steps 1 --integrator euler" + out,
                 "paper or implicit");
  expectBadInput("simulate " + block + " --dt 0.01 --steps 1 --gravity=yes" + out,
                 "takes no value");
  expectBadInput("simulate " + block + " --dt 0.01 --steps 1 --out " + quote(path("x.obj")),
                 "unknown extension");
  expectBadInput("simulate " + quote(path("none.json")) + " --dt 0.01 --steps 1" + out,
                 "none.json");
  EXPECT_FALSE(fs::exists(path("x.vtk")));
}

TEST_F(FemCliTest, BenchFemPrintsKeyValueLastLine) {
  const CliResult result =
      run("bench fem " + quote(kAssets + "block3.json") + " --levels 1 --steps 3");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const KeyValues pairs = keyValues(result.lastLine());
  ASSERT_EQ(keys(pairs), (std::vector<std::string>{"fem_step_ms", "elements", "tricubic",
                                                   "trilinear", "pyramid", "cg_iterations",
                                                   "elastic_pass_ms", "step_passes",
                                                   "first_step_ms", "step_p99_ms",
                                                   "step_max_ms"}))
      << result.lastLine();
  EXPECT_TRUE(isMilliseconds(pairs[0].second)) << result.lastLine();
  const auto v = numbers(pairs);
  EXPECT_EQ(v.at("elements"), v.at("tricubic") + v.at("trilinear") + v.at("pyramid"));
  EXPECT_EQ(v.at("elements"), 216);  // 27 cells, 8 children each
  EXPECT_EQ(v.at("pyramid"), 0);
  EXPECT_GT(v.at("cg_iterations"), 0);
  for (const char* text : {"setup_ms=", "threads=", "control_points=64", "nodes=", "fixed=16"})
    EXPECT_NE(result.out.find(text), std::string::npos) << text << " not in\n" << result.out;

  const std::string cube = quote(kAssets + "cube.json");
  expectBadInput("bench fem " + cube, "--levels is required");
  expectBadInput("bench fem " + cube + " --levels 1 --integrator rk4", "paper or implicit");
  expectBadInput("bench fem " + cube + " --levels 1 --repeat 2", "--repeat");
  expectBadInput("bench subdivide " + cube + " --levels 1 --E 5", "--E applies to bench fem");
  expectBadInput("bench fem " + cube + " --levels 1 --fix 5,5,5,6,6,6",
                 "contains no control point");
}

TEST_F(FemCliTest, InfoReportsElementCounts) {
  const CliResult block = run("info " + quote(kAssets + "block3.json") + " --levels 2");
  ASSERT_EQ(block.exitCode, 0) << block.err;
  EXPECT_NE(block.out.find("\n  fem: elements=1728 BE=57.9% LE=42.1% PE=0.0% tricubic=1000 "
                           "trilinear=728 pyramid=0\n"),
            std::string::npos)
      << block.out;

  const CliResult house = run("info " + quote(kAssets + "house.json") + " --levels 2");
  ASSERT_EQ(house.exitCode, 0) << house.err;
  const size_t at = house.out.find("  fem: ");
  ASSERT_NE(at, std::string::npos) << house.out;
  const std::string line = house.out.substr(at + 7, house.out.find('\n', at) - at - 7);
  const KeyValues pairs = keyValues(line);
  ASSERT_EQ(keys(pairs), (std::vector<std::string>{"elements", "BE", "LE", "PE", "tricubic",
                                                   "trilinear", "pyramid"}))
      << line;
  auto percent = [&](size_t i) {
    EXPECT_EQ(pairs[i].second.back(), '%') << line;
    return number(pairs[i].second.substr(0, pairs[i].second.size() - 1));
  };
  const double elements = number(pairs[0].second), pyramids = number(pairs[6].second);
  EXPECT_GT(percent(3), 0);
  EXPECT_GT(pyramids, 0);
  EXPECT_NEAR(percent(3), 100 * pyramids / elements, 0.05);
  EXPECT_NEAR(percent(1) + percent(2) + percent(3), 100, 0.2);
  EXPECT_EQ(elements, number(pairs[4].second) + number(pairs[5].second) + pyramids);

  // Level 0 has no simulation elements; info without --levels is as before.
  const CliResult level0 = run("info " + quote(kAssets + "block3.json") + " --levels 0");
  EXPECT_EQ(level0.exitCode, 0);
  EXPECT_EQ(level0.out.find("fem:"), std::string::npos) << level0.out;
  EXPECT_EQ(run("info " + quote(kAssets + "block3.json")).out.find("fem:"), std::string::npos);
}

}  // namespace
}  // namespace sculpt

namespace sculpt::test {
namespace {

// simulate --script: a session script (docs/file-formats.md) drives the tools while stepping. A
// grab that pulls the top of the pinned block up moves it; a malformed script is bad input that
// names the script.
class ScriptCliTest : public CliFixture {
 protected:
  ScriptCliTest() : CliFixture("sculpt_script_cli_test_") {}
};

TEST_F(ScriptCliTest, GrabScriptMovesTheBlockAndBadScriptsAreBadInput) {
  const std::string block = quote(std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json");
  const std::string script = path("pull.json");
  test::writeText(script, R"({"format": "sculpt-session", "version": 1, "events": [
    {"t": 0, "type": "pin", "box": [[-1, -1, -1], [4, 0.01, 4]]},
    {"t": 0, "type": "grab", "point": [1.5, 3, 1.5],
     "path": [[0, 1.5, 3, 1.5], [0.3, 1.5, 3.5, 1.5]], "stiffness": 5e5}]})");
  const CliResult pulled = run("simulate " + block + " --levels 1 --dt 0.02 --steps 20 --script " +
                               quote(script) + " --out " + quote(path("pulled.vtk")));
  ASSERT_EQ(pulled.exitCode, 0) << pulled.err;
  const auto v = numbers(keyValues(pulled.lastLine()));
  EXPECT_GT(v.at("max_displacement"), 0.1) << pulled.lastLine();  // pulled up by up to 0.5 m

  writeText(path("bad.json"), R"({"format": "sculpt-session", "version": 1, "events": [
    {"t": 0, "type": "inflate", "centre": [1, 1, 1], "radius": 1, "pressure": 10, "duration": -1}]})");
  expectBadInput("simulate " + block + " --levels 1 --dt 0.02 --steps 2 --script " +
                     quote(path("bad.json")) + " --out " + quote(path("x.vtk")),
                 "bad.json");
  writeText(path("cut.json"), R"({"format": "sculpt-session", "version": 1, "events": [{"t": 0,)");
  expectBadInput("simulate " + block + " --levels 1 --dt 0.02 --steps 2 --script " +
                     quote(path("cut.json")) + " --out " + quote(path("y.vtk")),
                 "cut.json");
}

}  // namespace
}  // namespace sculpt::test
