// The window's scene controller without GL: scene builds (default bunny, control meshes, bad
// files), the two-phase hand-over, stepping, live settings, rebuilds, cancellation and the
// per-cell fields, in the deterministic mode and on threads.

#include "scene/scene_controller.h"
#include "tools/session_script.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <thread>

#include "fem/fem_mesh.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

const std::string kAssets = std::string(SCULPT_SOURCE_DIR) + "/assets/";

SceneSource controlMesh(const std::string& name) {
  return {SceneKind::ControlMesh, kAssets + name};
}

void printStages(const char* title, const StageTimes& stages) {
  double total = 0.0;
  std::printf("[ measured ] %s:", title);
  for (const auto& [name, ms] : stages) {
    std::printf(" %s %.0f ms,", name.c_str(), ms);
    total += ms;
  }
  std::printf(" total %.0f ms\n", total);
}

/// Embedded surface points moved with the nodes by the cells' linear interpolant (trilinear in
/// a hexahedron in VTK order, barycentric in a tetrahedron): enough to see where the surface is.
Points linearSurface(const SceneGeometry& g, const Points& nodes) {
  const Embedding& e = g.embedding;
  Points out(e.numPoints(), 3);
  for (uint32_t p = 0; p < e.numPoints(); ++p) {
    const auto cell = g.cellMesh.cells.row(e.cells[p]);
    const double s = e.local(p, 0), t = e.local(p, 1), u = e.local(p, 2);
    Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
    if (cell.size() == 4) {
      const double w[4] = {1.0 - s - t - u, s, t, u};
      for (int a = 0; a < 4; ++a) x += w[a] * nodes.row(cell[a]);
    } else {
      const double corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
      for (int a = 0; a < 8; ++a) {
        const double w = (corner[a][0] ? s : 1 - s) * (corner[a][1] ? t : 1 - t) *
                         (corner[a][2] ? u : 1 - u);
        x += w * nodes.row(cell[a]);
      }
    }
    out.row(p) = x;
  }
  for (size_t k = 0; k < e.offsetPoints.size(); ++k)
    out.row(e.offsetPoints[k]) += e.offsetVectors[k].transpose();
  return out;
}

/// Cells per kind, and what the element counts say they must be (a pyramid element is split
/// into as many tetrahedra as its base has triangles: 2 for a quadrilateral, 1 for a triangle).
std::array<uint32_t, 3> cellsPerKind(const SceneGeometry& g) {
  std::array<uint32_t, 3> n{};
  for (uint8_t k : g.cellKind) ++n.at(k);
  return n;
}

/// Runs advance() until the frame is physics-ready (non-threaded: once is enough).
SceneFrame latest(SceneController& controller) {
  SceneFrame frame;
  EXPECT_TRUE(controller.fetchNewer(frame));
  return frame;
}

void expectFinite(const SceneFrame& frame) {
  EXPECT_TRUE(frame.nodes.allFinite());
  EXPECT_TRUE(frame.control.allFinite());
  for (const Eigen::Matrix3d& F : frame.gradients) ASSERT_TRUE(F.allFinite());
  for (float v : frame.cellStrainEnergy) ASSERT_TRUE(std::isfinite(v));
}

// ---------------------------------------------------------------------------------------------

TEST(SceneController, DefaultBunnyBuildsHangsAndKeepsItsPins) {
  SceneController controller(false);
  controller.load({}, SceneSettings{});
  EXPECT_TRUE(controller.buildStatus().running);
  EXPECT_EQ(controller.takeNewGeometry(), nullptr);  // nothing runs before advance()
  controller.advance();
  const BuildStatus status = controller.buildStatus();
  EXPECT_FALSE(status.running);
  EXPECT_EQ(status.error, "");
  const std::shared_ptr<const SceneGeometry> g = controller.takeNewGeometry();
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(controller.takeNewGeometry(), nullptr);  // once
  std::printf("[ measured ] %s: %zu triangles, %u cells, %u nodes, elements %u/%u/%u, "
              "%u of %u surface points outside the level-K solid (farthest %.2g)\n",
              g->description.c_str(), g->triangles.size() / 3, g->cellMesh.numCells(),
              g->cellMesh.numNodes(), g->elementCounts[0], g->elementCounts[1],
              g->elementCounts[2], g->embedding.outsideCount, g->embedding.numPoints(),
              g->embedding.maxOutsideDistance);
  printStages("default scene, phase 1", g->stageMs);
  printStages("default scene, both phases", status.stageMs);

  // Loop level 3 of the 3674-triangle bunny: 64 x 3674 triangles (the issue's "about 200k"), one
  // embedded point per vertex.
  EXPECT_EQ(g->triangles.size(), 3u * 64u * 3674u);
  EXPECT_EQ(g->restPositions.rows(), g->restNormals.rows());
  EXPECT_EQ(g->embedding.numPoints(), static_cast<uint32_t>(g->restPositions.rows()));
  // The cage's margin keeps the level-1 solid around the whole surface.
  EXPECT_EQ(g->embedding.outsideCount, 0u);
  // An all-hexahedral cage: no pyramids; one cell per element.
  EXPECT_EQ(cellsPerKind(*g), g->elementCounts);
  EXPECT_EQ(g->elementCounts[2], 0u);
  EXPECT_EQ(g->elementCounts[0] + g->elementCounts[1], g->cellMesh.numCells());
  // The stages of both phases were timed.
  for (const char* stage : {"read", "refine", "cage", "subdivide", "cells", "embed", "stencil"})
    EXPECT_TRUE(std::any_of(g->stageMs.begin(), g->stageMs.end(),
                            [&](const auto& s) { return s.first == stage && s.second >= 0; }))
        << stage;
  for (const char* stage : {"elements", "simulator", "first step"})
    EXPECT_TRUE(std::any_of(status.stageMs.begin(), status.stageMs.end(),
                            [&](const auto& s) { return s.first == stage; }))
        << stage;
  // The top layer is pinned (the ears), and only it.
  const double top = g->restControl.col(1).maxCoeff();
  int pinned = 0;
  for (size_t v = 0; v < g->pinned.size(); ++v) {
    pinned += g->pinned[v];
    if (g->pinned[v]) {
      EXPECT_GT(g->restControl(static_cast<Eigen::Index>(v), 1), top - 1.0);
    }
  }
  EXPECT_GT(pinned, 0);
  EXPECT_LT(pinned, static_cast<int>(g->pinned.size()) / 4);

  // The linear interpolant reproduces the rest surface (checks the embedding's coordinates).
  const Points rest = linearSurface(*g, g->cellMesh.positions);
  EXPECT_LT((rest - g->restPositions).cwiseAbs().maxCoeff(), 1e-9);

  SceneFrame frame = latest(controller);
  ASSERT_TRUE(frame.physicsReady);
  EXPECT_EQ(frame.sceneId, g->sceneId);
  for (int i = 0; i < 30; ++i) controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_NEAR(frame.simulatedTime, 32.0 / 60.0, 1e-12);  // first step in phase 2, 31 more
  expectFinite(frame);
  EXPECT_TRUE(frame.lastStep.ok) << frame.lastStep.message;
  // Hanging under gravity: the lowest surface point has moved down.
  const Points moved = linearSurface(*g, frame.nodes);
  const double height = rest.col(1).maxCoeff() - rest.col(1).minCoeff();
  std::printf(
      "[ measured ] lowest point after %.2f s: %.4f (rest %.4f, height %.2f), step %.1f ms\n",
      frame.simulatedTime, moved.col(1).minCoeff(), rest.col(1).minCoeff(), height, frame.stepMs);
  EXPECT_LT(moved.col(1).minCoeff(), rest.col(1).minCoeff() - 1e-3 * height);
  // Pinned control points have not moved at all; the others have.
  double freeMotion = 0.0;
  for (Eigen::Index v = 0; v < frame.control.rows(); ++v) {
    if (g->pinned[static_cast<size_t>(v)]) {
      EXPECT_EQ(frame.control.row(v), g->restControl.row(v)) << "control point " << v;
    } else {
      freeMotion = std::max(freeMotion, (frame.control.row(v) - g->restControl.row(v)).norm());
    }
  }
  EXPECT_GT(freeMotion, 1e-3 * height);
}

TEST(SceneController, DefaultBunnySwaysAndSettles) {
  // Hung by its ears, the bunny sags visibly, swings back past its lowest point, and then comes
  // to rest: the motion per step dies out.
  SceneController controller(false);
  controller.load({}, SceneSettings{});
  controller.advance();
  const std::shared_ptr<const SceneGeometry> g = controller.takeNewGeometry();
  ASSERT_NE(g, nullptr);
  const double restLow = g->restPositions.col(1).minCoeff();
  const double height = g->restPositions.col(1).maxCoeff() - restLow;
  SceneFrame frame = latest(controller);
  double deepest = 0.0, deepestTime = 0.0;
  std::vector<double> sag;
  for (int i = 0; i < 300; ++i) {
    controller.advance();
    ASSERT_TRUE(controller.fetchNewer(frame));
    ASSERT_TRUE(frame.lastStep.ok) << frame.lastStep.message;
    const double s = restLow - linearSurface(*g, frame.nodes).col(1).minCoeff();
    sag.push_back(s);
    if (s > deepest) deepest = s, deepestTime = frame.simulatedTime;
  }
  std::printf("[ measured ] sag (fraction of the height) at 0.25 s steps:");
  for (size_t i = 14; i < sag.size(); i += 15) std::printf(" %.4f", sag[i] / height);
  std::printf("\n[ measured ] deepest %.4f of the height at %.2f s; final %.4f\n",
              deepest / height, deepestTime, sag.back() / height);
  EXPECT_GT(sag[14], 0.02 * height);     // visible within a quarter of a second
  EXPECT_LT(deepest, 0.2 * height);      // not blown up
  EXPECT_GT(deepest, 1.05 * sag.back());  // it swung past its rest
  // ... and settled: over the last second it moves less than a tenth of that overshoot.
  const auto [low, high] = std::minmax_element(sag.end() - 60, sag.end());
  EXPECT_LT(*high - *low, 0.1 * (deepest - sag.back()));
}

TEST(SceneController, DisplayFirstShowsTheRestShapeBeforeThePhysics) {
  // Headless: advance(true) stops after phase 1 when nothing simulates yet; the next call runs
  // phase 2. A rebuild while a scene simulates still completes in one call.
  SceneController controller(false);
  controller.load(controlMesh("block3.json"), SceneSettings{});
  controller.advance(true);
  const std::shared_ptr<const SceneGeometry> g = controller.takeNewGeometry();
  ASSERT_NE(g, nullptr);
  SceneFrame frame = latest(controller);
  EXPECT_FALSE(frame.physicsReady);
  EXPECT_EQ(frame.nodes, g->cellMesh.positions);
  EXPECT_EQ(frame.cellYoungs.size(), g->cellMesh.numCells());
  EXPECT_TRUE(controller.buildStatus().running);
  controller.advance(true);
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_TRUE(frame.physicsReady);
  EXPECT_EQ(frame.sceneId, g->sceneId);
  EXPECT_EQ(controller.takeNewGeometry(), nullptr);  // handed over once
  EXPECT_FALSE(controller.buildStatus().running);

  SceneSettings settings;
  settings.level = 2;
  controller.applySettings(settings);
  controller.advance(true);
  const std::shared_ptr<const SceneGeometry> level2 = controller.takeNewGeometry();
  ASSERT_NE(level2, nullptr);
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_TRUE(frame.physicsReady);
  EXPECT_EQ(frame.sceneId, level2->sceneId);

  // A deferred phase 2 cancelled before it runs leaves the rest shape and no error.
  SceneController other(false);
  other.load(controlMesh("cube.json"), SceneSettings{});
  other.advance(true);
  ASSERT_NE(other.takeNewGeometry(), nullptr);
  EXPECT_EQ(other.source().path, kAssets + "cube.json");
  other.cancelBuild();
  other.advance(true);
  EXPECT_FALSE(other.buildStatus().running);
  EXPECT_EQ(other.buildStatus().error, "");
  SceneFrame otherFrame;
  ASSERT_TRUE(other.fetchNewer(otherFrame));
  EXPECT_FALSE(otherFrame.physicsReady);
}

TEST(SceneController, FieldsAreUniformMaterialAndStrainEnergySplitsByElement) {
  const SceneSettings settings;
  SceneController controller(false);
  controller.loop().setPlaying(false);
  controller.loop().setStrainEnergyShown(true);  // as the window asks while the field is shown
  controller.load(controlMesh("block3.json"), settings);
  controller.advance();
  const std::shared_ptr<const SceneGeometry> g = controller.takeNewGeometry();
  ASSERT_NE(g, nullptr);
  controller.loop().reset();
  controller.advance();
  SceneFrame frame = latest(controller);
  ASSERT_EQ(frame.cellYoungs.size(), g->cellMesh.numCells());
  for (size_t c = 0; c < frame.cellYoungs.size(); ++c) {
    ASSERT_FLOAT_EQ(frame.cellYoungs[c], static_cast<float>(settings.material.youngs));
    ASSERT_FLOAT_EQ(frame.cellDensity[c], static_cast<float>(settings.material.density));
  }
  // At rest: no strain energy (relative to E, the energy density of a unit strain).
  for (float w : frame.cellStrainEnergy) ASSERT_LE(std::abs(w), 1e-12 * settings.material.youngs);
  EXPECT_EQ(frame.simulatedTime, 0.0);
  for (int i = 0; i < 10; ++i) controller.loop().stepOnce();
  for (int i = 0; i < 10; ++i) controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_NEAR(frame.simulatedTime, 10.0 / 60.0, 1e-12);
  EXPECT_GT(*std::max_element(frame.cellStrainEnergy.begin(), frame.cellStrainEnergy.end()), 0.0f);

  // The per-element split, in double precision, against the kernel's total energy.
  std::unique_ptr<ScenePhysics> physics;
  {
    auto phase1 = buildSceneGeometry(controlMesh("block3.json"), settings, 7);
    ASSERT_TRUE(phase1);
    physics = ScenePhysics::build(phase1->geometry, phase1->solid, settings, nullptr, nullptr);
    ASSERT_NE(physics, nullptr);
  }
  for (int i = 0; i < 10; ++i) physics->step();
  Points femNodes;
  physics->model().nodesFromControl(physics->simulator().positions(), femNodes);
  ElasticKernel& elastic = physics->model().elastic();
  elastic.updateRotations(femNodes);
  const double total = elastic.energy(femNodes);
  std::vector<double> terms;
  elastic.elementEnergies(femNodes, terms);
  double sumTerms = 0.0, sumDensities = 0.0, volume = 0.0;
  for (size_t e = 0; e < terms.size(); ++e) {
    sumTerms += terms[e];
    sumDensities += physics->elementStrainEnergyDensity()[e] * physics->elementVolume()[e];
    volume += physics->elementVolume()[e];
  }
  std::printf(
      "[ measured ] block3 after 10 steps: elastic energy %.9g J, sum of densities x volumes "
      "%.9g J\n",
      total, sumDensities);
  ASSERT_GT(total, 0.0);
  EXPECT_NEAR(sumTerms, total, 1e-12 * total);
  EXPECT_NEAR(sumDensities, total, 1e-9 * total);
  EXPECT_NEAR(volume, physics->model().mesh().restVolume(), 1e-12 * volume);
  // The frame's cells carry their element's value while it is wanted, zeros otherwise.
  SceneFrame own;
  physics->fillFrame(own);
  for (float w : own.cellStrainEnergy) ASSERT_EQ(w, 0.0f);
  physics->setStrainEnergyWanted(true);
  physics->fillFrame(own);
  for (size_t c = 0; c < own.cellStrainEnergy.size(); ++c)
    ASSERT_EQ(own.cellStrainEnergy[c],
              static_cast<float>(
                  physics->elementStrainEnergyDensity()[physics->geometry().cellElement[c]]));
}

TEST(SceneController, ShowingTheStrainEnergyChangesNoBitOfTheMotion) {
  // Finding it takes the state's rotations, which are also the next step's warm start.
  auto run = [](bool shown) {
    const SceneSettings settings;
    auto phase1 = buildSceneGeometry(controlMesh("block3.json"), settings, 7);
    EXPECT_TRUE(phase1);
    auto physics = ScenePhysics::build(phase1->geometry, phase1->solid, settings, nullptr, nullptr);
    EXPECT_NE(physics, nullptr);
    physics->setStrainEnergyWanted(shown);
    for (int i = 0; i < 12; ++i) {
      physics->step();
      if (i == 5) physics->elementStrainEnergyDensity();  // asked once between steps
    }
    return Points(physics->simulator().positions() - physics->model().restControl());
  };
  const Points hidden = run(false), shown = run(true);
  EXPECT_GT(hidden.cwiseAbs().maxCoeff(), 1e-6);  // it moved
  EXPECT_TRUE(hidden == shown);
}

TEST(SceneController, LiveSettingsResetAndStepping) {
  SceneSettings settings;
  SceneController controller(false);
  controller.load(controlMesh("block3.json"), settings);
  controller.advance();
  const std::shared_ptr<const SceneGeometry> g = controller.takeNewGeometry();
  ASSERT_NE(g, nullptr);
  SceneFrame frame = latest(controller);
  for (int i = 0; i < 5; ++i) controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_GT((frame.nodes - g->cellMesh.positions).cwiseAbs().maxCoeff(), 0.0);

  // Reset: the rest nodes and control points exactly, time 0.
  controller.loop().setPlaying(false);
  EXPECT_FALSE(controller.loop().playing());
  controller.loop().reset();
  controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_EQ(frame.nodes, g->cellMesh.positions);
  EXPECT_EQ(frame.control, g->restControl);
  EXPECT_EQ(frame.simulatedTime, 0.0);
  // Paused: advance() does nothing; stepOnce() one step.
  controller.advance();
  EXPECT_FALSE(controller.fetchNewer(frame));
  controller.loop().stepOnce();
  controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_NEAR(frame.simulatedTime, 1.0 / 60.0, 1e-15);

  // Live: no gravity and a stiffer, denser material; no rebuild.
  settings.gravity.setZero();
  settings.material.youngs *= 2.0;
  settings.material.density = 1500.0;
  controller.applySettings(settings);
  EXPECT_FALSE(controller.buildStatus().running);
  controller.loop().reset();
  controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_EQ(controller.takeNewGeometry(), nullptr);
  EXPECT_FLOAT_EQ(frame.cellYoungs.front(), static_cast<float>(settings.material.youngs));
  EXPECT_FLOAT_EQ(frame.cellDensity.back(), 1500.0f);
  controller.loop().setPlaying(true);
  for (int i = 0; i < 10; ++i) controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  // Without gravity nothing moves the solid from rest.
  EXPECT_LT((frame.nodes - g->cellMesh.positions).cwiseAbs().maxCoeff(), 1e-12);
  settings.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
  controller.applySettings(settings);
  for (int i = 0; i < 10; ++i) controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_GT((frame.nodes - g->cellMesh.positions).cwiseAbs().maxCoeff(), 1e-6);

  // The time step and integrator apply live too; invalid settings are refused with a sentence.
  settings.timeStep = 1.0 / 120.0;
  settings.integrator = Integrator::Paper;
  controller.applySettings(settings);
  const double before = frame.simulatedTime;
  controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_NEAR(frame.simulatedTime - before, 1.0 / 120.0, 1e-12);
  SceneSettings bad = settings;
  bad.level = 4;
  EXPECT_THROW(controller.applySettings(bad), std::invalid_argument);
  bad = settings;
  bad.material.poisson = 0.5;
  EXPECT_THROW(controller.applySettings(bad), std::invalid_argument);
  EXPECT_EQ(controller.settings().level, 1);
}

TEST(SceneController, LevelChangeRebuildsAndCancelKeepsTheOldScene) {
  SceneSettings settings;
  settings.cageCellsAcross = 4.0;  // a coarser cage keeps the level-2 build short
  SceneController controller(false);
  controller.load({}, settings);
  controller.advance();
  const std::shared_ptr<const SceneGeometry> level1 = controller.takeNewGeometry();
  ASSERT_NE(level1, nullptr);
  SceneFrame frame = latest(controller);

  // Cancelled while subdividing: the old scene stays and keeps stepping; no error.
  settings.level = 2;
  bool sawSubdivision = false;
  controller.setProgressObserver([&](double, std::string_view stage) {
    if (stage == "subdividing the solid") {
      sawSubdivision = true;
      controller.cancelBuild();
    }
    return true;
  });
  controller.applySettings(settings);
  EXPECT_TRUE(controller.buildStatus().running);
  controller.advance();
  EXPECT_TRUE(sawSubdivision);
  EXPECT_FALSE(controller.buildStatus().running);
  EXPECT_EQ(controller.buildStatus().error, "");
  EXPECT_EQ(controller.takeNewGeometry(), nullptr);
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_EQ(frame.sceneId, level1->sceneId);
  EXPECT_EQ(frame.nodes.rows(), level1->cellMesh.positions.rows());
  EXPECT_EQ(controller.settings().level, 1);  // the scene shown

  // Cancelled before it ran: the same.
  controller.setProgressObserver(nullptr);
  controller.load(controller.source(), settings);
  controller.cancelBuild();
  controller.advance();
  EXPECT_EQ(controller.takeNewGeometry(), nullptr);
  EXPECT_FALSE(controller.buildStatus().running);

  // Level 2: every hexahedron of the level-1 solid becomes 8.
  controller.applySettings(settings);
  controller.advance();
  const std::shared_ptr<const SceneGeometry> level2 = controller.takeNewGeometry();
  ASSERT_NE(level2, nullptr);
  printStages("default scene at level 2, both phases", controller.buildStatus().stageMs);
  const auto total = [](const SceneGeometry& g) {
    return g.elementCounts[0] + g.elementCounts[1] + g.elementCounts[2];
  };
  EXPECT_EQ(total(*level2), 8 * total(*level1));
  EXPECT_EQ(level2->cellMesh.numCells(), 8 * level1->cellMesh.numCells());
  EXPECT_EQ(cellsPerKind(*level2), level2->elementCounts);
  // More of the cells are regular (tricubic) at level 2.
  EXPECT_GT(double(level2->elementCounts[0]) / total(*level2),
            double(level1->elementCounts[0]) / total(*level1));
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_EQ(frame.sceneId, level2->sceneId);
  EXPECT_TRUE(frame.physicsReady);
  EXPECT_EQ(frame.nodes.rows(), level2->cellMesh.positions.rows());
  controller.advance();
  ASSERT_TRUE(controller.fetchNewer(frame));
  expectFinite(frame);
}

TEST(SceneController, BadFilesReportASentenceAndKeepTheScene) {
  const fs::path dir = fs::temp_directory_path() / "sculpt_scene_controller_test";
  fs::create_directories(dir);
  {
    std::ofstream(dir / "broken.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
    std::ofstream(dir / "broken.json")
        << "{\"format\": \"sculpt-control-mesh\", \"vertices\": [[0,0";
    std::ofstream(dir / "surface.xyz") << "0 0 0\n";
    std::ofstream(dir / "inverted.json")
        << R"({"format": "sculpt-control-mesh", "version": 1, "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],
              "cells": [{"type": "tet", "vertices": [0, 2, 1, 3]}]})";
  }
  SceneController controller(false);
  controller.load(controlMesh("block3.json"), SceneSettings{});
  controller.advance();
  const std::shared_ptr<const SceneGeometry> g = controller.takeNewGeometry();
  ASSERT_NE(g, nullptr);
  SceneFrame frame = latest(controller);

  const std::vector<std::pair<SceneSource, std::string>> bad = {
      {{SceneKind::ImportedSurface, (dir / "missing.obj").string()}, "missing.obj"},
      {{SceneKind::ImportedSurface, (dir / "broken.obj").string()}, "broken.obj"},
      {{SceneKind::ImportedSurface, (dir / "surface.xyz").string()}, "surface.xyz"},
      {{SceneKind::ControlMesh, (dir / "missing.json").string()}, "missing.json"},
      {{SceneKind::ControlMesh, (dir / "broken.json").string()}, "broken.json"},
      {{SceneKind::ControlMesh, (dir / "inverted.json").string()}, "inverted.json"},
  };
  for (const auto& [source, name] : bad) {
    controller.load(source, SceneSettings{});
    controller.advance();
    const BuildStatus status = controller.buildStatus();
    std::printf("[ message  ] %s\n", status.error.c_str());
    EXPECT_FALSE(status.running);
    EXPECT_NE(status.error.find(name), std::string::npos) << status.error;
    EXPECT_EQ(status.error.find('\n'), std::string::npos);
    EXPECT_EQ(controller.takeNewGeometry(), nullptr);
    ASSERT_TRUE(controller.fetchNewer(frame));  // the old scene still steps
    EXPECT_EQ(frame.sceneId, g->sceneId);
  }
  // Rebuilds still concern the scene shown.
  EXPECT_EQ(controller.source().path, kAssets + "block3.json");
  // The next good load clears the error.
  controller.load(controlMesh("cube.json"), SceneSettings{});
  controller.advance();
  EXPECT_EQ(controller.buildStatus().error, "");
  EXPECT_NE(controller.takeNewGeometry(), nullptr);
  fs::remove_all(dir);
}

TEST(SceneController, ControlMeshScenes) {
  for (const char* name : {"block3.json", "house.json", "beam.json", "mixed.json", "tet.json"}) {
    SCOPED_TRACE(name);
    SceneController controller(false);
    controller.load(controlMesh(name), SceneSettings{});
    controller.advance();
    ASSERT_EQ(controller.buildStatus().error, "");
    const std::shared_ptr<const SceneGeometry> g = controller.takeNewGeometry();
    ASSERT_NE(g, nullptr);
    std::printf("[ measured ] %s: %zu triangles, %u cells, elements %u/%u/%u\n",
                g->description.c_str(), g->triangles.size() / 3, g->cellMesh.numCells(),
                g->elementCounts[0], g->elementCounts[1], g->elementCounts[2]);
    EXPECT_EQ(cellsPerKind(*g)[0], g->elementCounts[0]);
    EXPECT_EQ(cellsPerKind(*g)[1], g->elementCounts[1]);
    EXPECT_GE(cellsPerKind(*g)[2], g->elementCounts[2]);  // 1 or 2 tetrahedra per pyramid
    EXPECT_LE(cellsPerKind(*g)[2], 2 * g->elementCounts[2]);
    EXPECT_EQ(g->embedding.numPoints(), static_cast<uint32_t>(g->restPositions.rows()));
    for (int i = 0; i < 10; ++i) controller.advance();
    SceneFrame frame = latest(controller);
    expectFinite(frame);
    EXPECT_TRUE(frame.lastStep.ok) << frame.lastStep.message;
    EXPECT_GT((frame.control - g->restControl).cwiseAbs().maxCoeff(), 0.0);
    for (Eigen::Index v = 0; v < frame.control.rows(); ++v)
      if (g->pinned[static_cast<size_t>(v)]) {
        ASSERT_EQ(frame.control.row(v), g->restControl.row(v));
      }
  }
  // block3: 54 boundary quads refined 3 times, 2 triangles per quad.
  const auto block = buildSceneGeometry(controlMesh("block3.json"), SceneSettings{}, 1);
  ASSERT_TRUE(block);
  EXPECT_EQ(block->geometry->triangles.size(), 3u * 2u * 54u * 64u);
  // The beam's creases and corners make its limit surface the box [0,10] x [0,1] x [0,1]: every
  // surface point lies on a face of the box.
  const auto beam = buildSceneGeometry(controlMesh("beam.json"), SceneSettings{}, 2);
  ASSERT_TRUE(beam);
  const Points& p = beam->geometry->restPositions;
  for (Eigen::Index v = 0; v < p.rows(); ++v) {
    const double toFace =
        std::min({p(v, 0), 10.0 - p(v, 0), p(v, 1), 1.0 - p(v, 1), p(v, 2), 1.0 - p(v, 2)});
    ASSERT_NEAR(toFace, 0.0, 1e-12) << "vertex " << v;
  }
  // house.json has pyramids: their tetrahedra carry the pyramid elements of their faces.
  SceneSettings settings;
  const auto house = buildSceneGeometry(controlMesh("house.json"), settings, 3);
  ASSERT_TRUE(house);
  auto physics = ScenePhysics::build(house->geometry, house->solid, settings, nullptr, nullptr);
  ASSERT_NE(physics, nullptr);
  const FemMesh& mesh = physics->model().mesh();
  EXPECT_GT(mesh.counts().pyramid, 0u);
  for (size_t c = 0; c < house->geometry->cellKind.size(); ++c) {
    const uint32_t e = house->geometry->cellElement[c];
    ASSERT_EQ(static_cast<uint8_t>(mesh.elementType[e]), house->geometry->cellKind[c]);
  }
}

TEST(SceneController, PhaseTwoNeedsOnlyTheSolidPartOfPhaseOne) {
  // The window starts phase 2 on the solid part while the stencils and the surface are still
  // being made: the physics must build and step the same, reading none of their fields until
  // the stencils are announced, and the parts must give the geometry that phase 1 in one piece
  // gives.
  SceneSettings settings;
  settings.cageCellsAcross = 4.0;
  for (const SceneSource& source : {controlMesh("house.json"), SceneSource{}}) {
    SCOPED_TRACE(source.path.empty() ? "the bunny" : source.path);
    std::optional<SceneSolidPart> part = buildSceneSolid(source, settings, 1);
    ASSERT_TRUE(part);
    EXPECT_EQ(part->geometry->restPositions.rows(), 0);
    EXPECT_TRUE(part->geometry->triangles.empty());
    EXPECT_EQ(part->geometry->embedding.cells.size(), 0u);
    std::promise<void> stencils;
    std::thread rest([&] {
      EXPECT_TRUE(buildSceneStencils(source, *part));
      stencils.set_value();
      EXPECT_TRUE(buildSceneSurface(source, *part));
    });
    auto early = ScenePhysics::build(part->geometry, part->solid, settings, nullptr, nullptr,
                                     stencils.get_future().share());
    rest.join();
    ASSERT_NE(early, nullptr);

    const auto whole = buildSceneGeometry(source, settings, 1);
    ASSERT_TRUE(whole);
    const SceneGeometry& a = *part->geometry;
    const SceneGeometry& b = *whole->geometry;
    EXPECT_EQ(a.restPositions, b.restPositions);
    EXPECT_EQ(a.restNormals, b.restNormals);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.embedding.cells, b.embedding.cells);
    EXPECT_EQ(a.embedding.local, b.embedding.local);
    EXPECT_EQ(a.cellMesh.positions, b.cellMesh.positions);
    EXPECT_EQ(a.cellElement, b.cellElement);
    EXPECT_EQ(a.pinned, b.pinned);
    EXPECT_EQ(a.description, b.description);
    auto physics = ScenePhysics::build(whole->geometry, whole->solid, settings, nullptr, nullptr);
    ASSERT_NE(physics, nullptr);
    for (int step = 0; step < 5; ++step) {
      early->step();
      physics->step();
    }
    EXPECT_GT((physics->simulator().positions() - b.restControl).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(early->simulator().positions(), physics->simulator().positions());
    SceneFrame earlyFrame, frame;
    early->fillFrame(earlyFrame);
    physics->fillFrame(frame);
    EXPECT_EQ(earlyFrame.nodes, frame.nodes);
    EXPECT_TRUE(earlyFrame.gradients == frame.gradients);
  }
}

TEST(SceneController, ImportedSurfacesAreCagedAndDrawnAsIs) {
  // A cube of quadrilaterals, fanned into 12 triangles, in a cage of about 4 cells across.
  const fs::path dir = fs::temp_directory_path() / "sculpt_scene_controller_import";
  fs::create_directories(dir);
  std::ofstream(dir / "cube.obj")
      << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\n"
         "v 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\n"
         "f 3 4 8 7\nf 4 1 5 8\n";
  SceneSettings settings;
  settings.cageCellsAcross = 4.0;
  for (const auto& [path, triangles] : {std::pair{(dir / "cube.obj").string(), size_t(12)},
                                        std::pair{kAssets + "bunny.obj", size_t(3674)}}) {
    SCOPED_TRACE(path);
    SceneController controller(false);
    controller.load({SceneKind::ImportedSurface, path}, settings);
    controller.advance();
    ASSERT_EQ(controller.buildStatus().error, "");
    const std::shared_ptr<const SceneGeometry> g = controller.takeNewGeometry();
    ASSERT_NE(g, nullptr);
    std::printf("[ measured ] %s: %zu triangles, %u cells\n", g->description.c_str(),
                g->triangles.size() / 3, g->cellMesh.numCells());
    EXPECT_EQ(g->triangles.size(), 3 * triangles);
    EXPECT_EQ(g->embedding.outsideCount, 0u);
    // Unit area-weighted normals; the cube's corners point along the diagonals.
    for (Eigen::Index v = 0; v < g->restNormals.rows(); ++v)
      ASSERT_NEAR(g->restNormals.row(v).norm(), 1.0, 1e-12);
    if (triangles == 12) {
      const Eigen::RowVector3d centre(0.5, 0.5, 0.5);
      for (Eigen::Index v = 0; v < 8; ++v)
        EXPECT_GT(g->restNormals.row(v).dot((g->restPositions.row(v) - centre).normalized()), 0.5);
    }
    for (int i = 0; i < 5; ++i) controller.advance();
    SceneFrame frame = latest(controller);
    expectFinite(frame);
    EXPECT_TRUE(frame.physicsReady);
    EXPECT_LT(linearSurface(*g, frame.nodes).col(1).minCoeff(), g->restPositions.col(1).minCoeff());
  }
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// Threads

/// Polls until `done` (generous deadline: a missed deadline is a failure, not a timing test).
template <typename F>
bool waitFor(F done, double seconds = 300.0) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

/// Polls the published frames into `frame` until the physics of the scene runs.
bool waitForPhysics(SceneController& controller, SceneFrame& frame) {
  return waitFor([&] {
    controller.fetchNewer(frame);
    return frame.physicsReady;
  });
}

TEST(SceneControllerThreaded, ShowsTheRestShapeFirstThenSimulates) {
  SceneController controller(true);
  const auto start = std::chrono::steady_clock::now();
  controller.load({}, SceneSettings{});
  std::shared_ptr<const SceneGeometry> g;
  ASSERT_TRUE(waitFor([&] { return (g = controller.takeNewGeometry()) != nullptr; }));
  const double firstMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  SceneFrame frame;
  ASSERT_TRUE(controller.fetchNewer(frame));
  EXPECT_EQ(frame.sceneId, g->sceneId);
  std::printf("[ measured ] threaded: geometry after %.0f ms (frame %s)\n", firstMs,
              frame.physicsReady ? "simulated" : "at rest");
  ASSERT_TRUE(waitForPhysics(controller, frame));
  const double readyMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ measured ] threaded: simulating after %.0f ms\n", readyMs);
  EXPECT_EQ(controller.takeNewGeometry(), nullptr);  // the same scene: no second hand-over
  uint64_t last = frame.version;
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(waitFor([&] { return controller.fetchNewer(frame); }));
    EXPECT_GT(frame.version, last);
    EXPECT_EQ(frame.sceneId, g->sceneId);
    last = frame.version;
  }
  expectFinite(frame);
  // Pause: the frames stop; a single step gives exactly one more.
  controller.loop().setPlaying(false);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  controller.fetchNewer(frame);
  const double paused = frame.simulatedTime;
  controller.loop().stepOnce();
  ASSERT_TRUE(waitFor([&] { return controller.fetchNewer(frame); }));
  EXPECT_NEAR(frame.simulatedTime, paused + 1.0 / 60.0, 1e-12);
}

TEST(SceneControllerThreaded, CancelDuringALevelChangeKeepsTheSceneRunning) {
  SceneController controller(true);
  controller.load(controlMesh("block3.json"), SceneSettings{});
  SceneFrame frame;
  ASSERT_TRUE(waitForPhysics(controller, frame));
  const std::shared_ptr<const SceneGeometry> g = controller.takeNewGeometry();
  ASSERT_NE(g, nullptr);
  SceneSettings settings;
  settings.level = 3;
  controller.applySettings(settings);
  ASSERT_TRUE(waitFor([&] { return controller.buildStatus().fraction > 0.0; }));
  controller.cancelBuild();
  EXPECT_FALSE(controller.buildStatus().running);
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(waitFor([&] { return controller.fetchNewer(frame); }));
    EXPECT_EQ(frame.sceneId, g->sceneId);
  }
  EXPECT_EQ(controller.takeNewGeometry(), nullptr);
  EXPECT_EQ(controller.buildStatus().error, "");
}

TEST(SceneControllerThreaded, CommandsInAnyOrderKeepFramesAndGeometryConsistent) {
  // The UI thread fires loads, cancels, settings and transport commands while the threads build
  // and step; every frame fetched belongs to the geometry taken (or to the one about to be
  // taken), versions only grow, and the last load wins.
  SceneController controller(true);
  std::shared_ptr<const SceneGeometry> shown;
  SceneFrame frame;
  auto poll = [&] {
    if (auto g = controller.takeNewGeometry()) {
      if (shown) {
        EXPECT_GT(g->sceneId, shown->sceneId);
      }
      shown = g;
    }
    const uint64_t before = frame.version;
    if (!controller.fetchNewer(frame)) return;
    EXPECT_GT(frame.version, before);
    if (!shown || frame.sceneId != shown->sceneId) {  // a newer scene: its geometry is waiting
      const auto g = controller.takeNewGeometry();
      ASSERT_NE(g, nullptr);
      EXPECT_EQ(g->sceneId, frame.sceneId);
      shown = g;
    }
    ASSERT_NE(shown, nullptr);
    EXPECT_EQ(frame.nodes.rows(), shown->cellMesh.positions.rows());
    EXPECT_EQ(frame.cellYoungs.size(), shown->cellMesh.numCells());
  };
  SceneSettings settings;
  const char* meshes[] = {"block3.json", "cube.json", "house.json"};
  for (int i = 0; i < 40; ++i) {
    switch (i % 8) {
      case 0: controller.load(controlMesh(meshes[(i / 8) % 3]), settings); break;
      case 1: controller.loop().setPlaying(i % 3 != 0); break;
      case 2: controller.loop().stepOnce(); break;
      case 3:
        settings.material.youngs = 1e6 + 1e5 * i;
        controller.applySettings(settings);
        break;
      case 4: controller.loop().reset(); break;
      case 5: if (i % 3 == 0) controller.cancelBuild(); break;
      case 6: settings.gravity.y() = -9.81 * (i % 2); controller.applySettings(settings); break;
      default: controller.loop().setPlaying(true); break;
    }
    for (int k = 0; k < 3; ++k) {
      poll();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  controller.loop().setPlaying(true);
  controller.load(controlMesh("cube.json"), settings);
  ASSERT_TRUE(waitFor([&] {
    poll();
    return !controller.buildStatus().running && shown && frame.sceneId == shown->sceneId &&
           frame.physicsReady && shown->restControl.rows() == 8;
  }));
  EXPECT_EQ(controller.buildStatus().error, "");
  EXPECT_FLOAT_EQ(frame.cellYoungs.front(), static_cast<float>(settings.material.youngs));
}

TEST(SceneControllerThreaded, DestructionWhileBuildingOrSteppingIsClean) {
  {
    SceneController controller(true);  // destroyed while building phase 1
    controller.load({}, SceneSettings{});
    ASSERT_TRUE(waitFor([&] { return controller.buildStatus().fraction > 0.0; }));
  }
  {
    SceneController controller(true);  // destroyed right after a load
    controller.load(controlMesh("block3.json"), SceneSettings{});
  }
  {
    SceneController controller(true);  // destroyed while stepping, with a rebuild queued
    controller.load(controlMesh("block3.json"), SceneSettings{});
    SceneFrame frame;
    ASSERT_TRUE(waitForPhysics(controller, frame));
    SceneSettings settings;
    settings.level = 2;
    controller.applySettings(settings);
  }
  {
    SceneController controller(true);  // never loaded
  }
}

}  // namespace
}  // namespace sculpt

namespace sculpt {
namespace {

// A session script replays on the scene (sculpt --script): a grab that drags the middle of the
// hanging block along +x pulls the solid that way against the same scene without the script,
// its spring is published while it acts, and reset ends the script.
TEST(SceneControllerScript, GrabScriptPullsTheSolidAndResetEndsIt) {
  const SessionScript script = parseSessionScript(R"({"format": "sculpt-session", "version": 1,
    "events": [{"t": 0, "type": "grab", "point": [1.5, 1.0, 1.5],
                "path": [[0, 1.5, 1.0, 1.5], [0.2, 2.5, 1.0, 1.5]], "stiffness": 2e6}]})",
                                                  "pull.json");
  const auto meanX = [](const SceneFrame& frame) { return frame.control.col(0).mean(); };
  double pulledX = 0, freeX = 0;
  for (const bool withScript : {true, false}) {
    SceneController controller(false);
    controller.load(controlMesh("block3.json"), SceneSettings{});
    if (withScript) controller.loop().playScript(script);
    for (int i = 0; i < 20; ++i) controller.advance();
    ASSERT_EQ(controller.buildStatus().error, "");
    const SceneFrame frame = latest(controller);
    expectFinite(frame);
    if (withScript) {
      ASSERT_EQ(frame.springs.size(), 1u);
      // The material point has followed the target a good part of the way (x from 1.5 to 2.5).
      EXPECT_GT(frame.springs[0].point.x(), 1.8);
      EXPECT_EQ(frame.springs[0].target, Eigen::Vector3d(2.5, 1.0, 1.5));
      pulledX = meanX(frame);
      controller.loop().reset();
      controller.advance();
      EXPECT_TRUE(latest(controller).springs.empty());
    } else {
      EXPECT_TRUE(frame.springs.empty());
      freeX = meanX(frame);
    }
  }
  std::printf("[ measured ] mean control x after 20 steps: %.4f pulled, %.4f free\n", pulledX,
              freeX);
  EXPECT_GT(pulledX, freeX + 0.05);
}

// The window's pull tool through the controller: grab the material point at a rest position,
// drag the target, let go; the spring is published while it holds.
TEST(SceneControllerScript, MouseGrabPullsWhileHeldAndLetsGo) {
  SceneController controller(false);
  controller.load(controlMesh("block3.json"), SceneSettings{});
  controller.advance();
  ToolInput input;
  input.position = Eigen::Vector3d(1.5, 1.0, 1.5);
  input.restPoint = Eigen::Vector3d(1.5, 1.0, 1.5);
  const uint64_t stroke =
      controller.loop().beginStroke(std::make_unique<PullStroke>(PullStroke::Settings{}), input);
  for (int i = 0; i < 20; ++i) {
    input.position = Eigen::Vector3d(1.5 + 0.05 * (i + 1), 1.0, 1.5);  // a drag along +x
    input.restPoint.reset();
    controller.loop().updateStroke(stroke, input);
    controller.advance();
  }
  SceneFrame frame = latest(controller);
  ASSERT_EQ(frame.springs.size(), 1u);
  EXPECT_EQ(frame.springs[0].target, Eigen::Vector3d(2.5, 1.0, 1.5));
  EXPECT_GT(frame.springs[0].point.x(), 1.8);
  controller.loop().endStroke(stroke, input);
  controller.advance();
  frame = latest(controller);
  EXPECT_TRUE(frame.springs.empty());
  expectFinite(frame);
}

TEST(SceneControllerThreaded, BrushEditsAreCapturedAndRestoredOnTheSimulationThread) {
  // The window's paint and pin dabs, the capture that makes their undo entry, and the restore of
  // undo run on the simulation thread while it steps (ThreadSanitizer checks this test).
  SceneController controller(true);
  controller.load(controlMesh("block3.json"), SceneSettings{});
  SceneFrame frame;
  ASSERT_TRUE(waitForPhysics(controller, frame));
  const auto capture = [&controller] {
    controller.loop().requestEdits();
    std::optional<SceneEdits> edits;
    EXPECT_TRUE(waitFor([&] { return (edits = controller.loop().takeEdits()).has_value(); }));
    return edits.value_or(SceneEdits{});
  };
  const SceneEdits before = capture();
  MaterialBrushSettings brush;
  brush.radius = 0.8;
  brush.target.youngs = 5.0e7;
  brush.fields = {false, false, true, false};
  brush.mirror.x = false;
  const auto dab = [&controller](std::unique_ptr<Tool> tool, const Eigen::Vector3d& rest) {
    ToolInput input;
    input.restPoint = rest;
    controller.loop().endStroke(controller.loop().beginStroke(std::move(tool), input), input);
  };
  dab(std::make_unique<PaintStroke>(PaintStroke::Settings{brush, std::nullopt}),
      Eigen::Vector3d(1.5, 1.5, 1.5));
  dab(std::make_unique<PinStroke>(PinStroke::Settings{0.1, std::nullopt}),
      Eigen::Vector3d(0.0, 0.0, 0.0));
  const SceneEdits painted = capture();
  ASSERT_GT(before.materials.size(), 0u);
  ASSERT_EQ(painted.materials.size(), before.materials.size());
  size_t stiff = 0;
  for (const Material& m : painted.materials.materials) stiff += m.youngs > 1.0e7;
  EXPECT_GT(stiff, 0u);
  EXPECT_LT(stiff, painted.materials.size() / 2);
  EXPECT_EQ(painted.pins.size(), before.pins.size() + 1) << "the corner at the origin";
  // Undo: back to the captured state, bit for bit.
  controller.loop().restoreEdits(before.materials, before.pins);
  const SceneEdits restored = capture();
  EXPECT_TRUE(sameMaterialSamples(restored.materials, before.materials));
  EXPECT_EQ(restored.pins, before.pins);
  EXPECT_TRUE(controller.buildStatus().error.empty()) << controller.buildStatus().error;
}

}  // namespace
}  // namespace sculpt
