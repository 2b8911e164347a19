// A tool that exists only in this file works end to end through the one tool interface: begun,
// updated and ended on a running scene by the scene controller's simulation loop (as the window
// and a haptic device drive tools), its effect measured on the solid, its spring published in
// the frames and the probe. Nothing in the product knows about it.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

#include "scene/scene_controller.h"
#include "sim/load_forms.h"
#include "tools/tool.h"

namespace sculpt {
namespace {

// Pushes the material under the stylus along the stylus' axis (its orientation's z) with a force
// proportional to the stylus pressure: orientation and pressure of ToolInput, used by no product
// tool today.
class StylusPushTool : public Tool {
 public:
  explicit StylusPushTool(double maxForce) : maxForce_(maxForce) {}
  const char* name() const override { return "stylus push"; }
  void begin(ToolContext& context, const ToolInput& input) override {
    std::optional<MaterialPoint> point =
        context.locator().locate(restPointOf(context, input, name()));
    if (!point) throw std::invalid_argument("stylus push: nothing there.");
    point_ = *point;
    simulator_ = &context.simulator();
    model_ = &context.model();
    apply(input);
  }
  void update(ToolContext&, const ToolInput& input) override { apply(input); }
  void end(ToolContext&, const ToolInput&) override { clear(); }
  void clear() override {
    if (form_) simulator_->removeLoad(form_);
    form_ = nullptr;
  }
  bool holdsLoads() const override { return form_ != nullptr; }
  void springs(const Simulator& simulator, std::vector<ToolSpring>& out) const override {
    if (!form_) return;
    ToolSpring spring;
    Points nodes;
    model_->nodesFromControl(simulator.positions(), nodes);
    spring.point = materialPointPosition(model_->mesh(), nodes, point_);
    spring.target = spring.point + force_ / maxForce_;
    out.push_back(spring);
  }

 private:
  void apply(const ToolInput& input) {
    const Eigen::Quaterniond q = input.orientation.value_or(Eigen::Quaterniond::Identity());
    force_ = maxForce_ * input.pressure * (q * Eigen::Vector3d::UnitZ());
    clear();
    form_ =
        simulator_->addLoad(std::make_unique<PointForceForm>(simulator_->model(), point_, force_));
  }
  double maxForce_;
  MaterialPoint point_;
  Simulator* simulator_ = nullptr;
  const FemModel* model_ = nullptr;
  Form* form_ = nullptr;
  Eigen::Vector3d force_ = Eigen::Vector3d::Zero();
};

SceneFrame waitForSteps(SceneController& controller, double simulatedTime) {
  SceneFrame frame;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    controller.fetchNewer(frame);
    if (frame.physicsReady && frame.simulatedTime >= simulatedTime) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return frame;
}

TEST(CustomTool, AToolDefinedInATestDrivesTheRunningScene) {
  const std::string block = std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json";
  double pushedX = 0.0, freeX = 0.0;
  for (const bool push : {true, false}) {
    SceneController controller(true);
    SceneSettings settings;
    settings.gravity = Eigen::Vector3d::Zero();
    controller.load(SceneSource(SceneKind::ControlMesh, block), settings);
    std::shared_ptr<ProbeChannel> probe = controller.loop().openProbe();
    SceneFrame frame = waitForSteps(controller, 0.0);
    ASSERT_TRUE(frame.physicsReady) << controller.buildStatus().error;
    if (push) {
      ToolInput input;
      input.restPoint = Eigen::Vector3d(1.5, 1.5, 3.0);  // the middle of the +z face
      input.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
      input.pressure = 0.25;  // the stylus' axis is now +x
      const uint64_t stroke =
          controller.loop().beginStroke(std::make_unique<StylusPushTool>(4.0e6), input);
      input.pressure = 1.0;  // pressed harder
      controller.loop().updateStroke(stroke, input);
      frame = waitForSteps(controller, 0.5);
      ASSERT_EQ(frame.springs.size(), 1u);
      const Eigen::Vector3d direction = frame.springs[0].target - frame.springs[0].point;
      EXPECT_NEAR(direction.x(), 1.0, 1e-9) << "full pressure along the stylus' axis";
      EXPECT_NEAR(direction.norm(), 1.0, 1e-9);
      const SceneProbe& seen = probe->read();
      ASSERT_EQ(seen.strokeCount, 1);
      EXPECT_EQ(seen.strokes[0].strokeId, stroke);
      controller.loop().endStroke(stroke, input);
      const double ended = frame.simulatedTime;
      frame = waitForSteps(controller, ended + 0.05);
      EXPECT_TRUE(frame.springs.empty()) << "the load went with the stroke";
      pushedX = frame.control.col(0).mean();
    } else {
      frame = waitForSteps(controller, 0.55);
      freeX = frame.control.col(0).mean();
    }
    EXPECT_TRUE(controller.buildStatus().error.empty()) << controller.buildStatus().error;
  }
  std::printf("[ measured ] mean control x after the push: %.4f pushed, %.4f free\n", pushedX,
              freeX);
  EXPECT_GT(pushedX, freeX + 0.01);
}

}  // namespace
}  // namespace sculpt
