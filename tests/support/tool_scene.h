#pragma once
// The scene the physical-tool tests replay session scripts on: block3 (the unit-cell cube
// [0,3]^3) at level 1, E = 1e5 Pa, rho = 1000, mass-proportional damping 2000 kg/(m^3 s)
// (amplitudes decay like exp(-t)), steps of 0.02 s, implicit integrator; and helpers to play a
// script and read material points.

#include <gtest/gtest.h>

#include <memory>

#include "fem/fem_model.h"
#include "sim/material_point.h"
#include "sim/simulator.h"
#include "support/fem_builders.h"
#include "tools/session_script.h"

namespace sculpt::test {

struct ToolScene {
  std::unique_ptr<FemModel> model;
  std::unique_ptr<Simulator> simulator;
};

inline ToolScene makeToolScene() {
  FemSetup setup;
  setup.level = 1;
  setup.material.damping = 2000;
  ToolScene s;
  s.model = buildModel(block3(), setup);
  if (!s.model) return s;
  SimulationSettings settings;
  settings.integrator = Integrator::Implicit;
  settings.timeStep = 0.02;
  s.simulator = std::make_unique<Simulator>(*s.model, settings);
  return s;
}

/// Steps the player until its time reaches `until` (s), failing on a failed step.
inline void play(ScriptPlayer& player, double until) {
  while (player.time() < until - 1e-9) ASSERT_TRUE(player.step().ok) << "t=" << player.time();
}

inline Points nodesOf(const FemModel& model, const Points& control) {
  Points nodes;
  model.nodesFromControl(control, nodes);
  return nodes;
}

inline Eigen::Vector3d pointAt(const FemModel& model, const Points& control,
                               const MaterialPoint& p) {
  return materialPointPosition(model.mesh(), nodesOf(model, control), p);
}

}  // namespace sculpt::test
