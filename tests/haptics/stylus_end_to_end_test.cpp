// The stylus end to end: the mock PHANTOM-class device, the 1 kHz servo thread, the haptic
// session and the real FEM running on the scene's simulation thread (the scene controller, as
// the window runs it). Run under ThreadSanitizer too (scripts/test.sh --tsan).

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include <nlohmann/json.hpp>

#include "haptics/mock/device_script.h"
#include "haptics/mock/mock_phantom.h"
#include "haptics/session/haptic_session.h"
#include "scene/scene_controller.h"
#include "support/paced_rate.h"

namespace sculpt::haptics {
namespace {

using Clock = std::chrono::steady_clock;

// block3: the control box [0, 3]^3, no gravity, its back face (z = 0) pinned once built.
struct BlockScene {
  SceneController controller{true};
  HapticScene scene;
  explicit BlockScene() {
    SceneSettings settings;
    settings.gravity = Eigen::Vector3d::Zero();
    controller.load(
        SceneSource(SceneKind::ControlMesh, std::string(SCULPT_SOURCE_DIR) + "/assets/block3.json"),
        settings);
    scene.centre = Eigen::Vector3d(1.5, 1.5, 1.5);
    scene.radius = std::sqrt(27.0) / 2;
    scene.youngs = settings.material.youngs;
  }
  // Waits for the physics and pins the control points of the back face (the pin tool's box).
  bool ready() {
    if (!waitFor(0.0).physicsReady) return false;
    PinStroke::Settings pins;
    pins.box = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(4, 4, 0.1));
    const ToolInput anywhere;
    const uint64_t stroke =
        controller.loop().beginStroke(std::make_unique<PinStroke>(pins), anywhere);
    controller.loop().endStroke(stroke, anywhere);
    return true;
  }
  SceneFrame waitFor(double simulatedTime, double timeoutSeconds = 60) {
    SceneFrame frame;
    const auto deadline = Clock::now() + std::chrono::duration<double>(timeoutSeconds);
    while (Clock::now() < deadline) {
      controller.fetchNewer(frame);
      if (frame.physicsReady && frame.simulatedTime >= simulatedTime) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return frame;
  }
  // Scripts are written in simulated seconds; `stretch` turns them into the clock's. It is 1
  // where the simulation steps several times faster than the clock. Where it cannot (a sanitizer
  // build: 45 ms a step here, against 0.8 ms in Release), the simulation is slowed to a third of
  // what it can do, and the script follows, so that its holds last as long as written.
  double stretch = 1.0;
  void paceForThisBuild() {
    const SceneFrame frame = waitFor(waitFor(0.0).simulatedTime + 0.1);
    const double rate = test::pacedRate(1.0, SceneSettings().timeStep, 1e-3 * frame.stepMs, 3.0);
    if (rate < 1.0) {
      controller.loop().setRealTimeRate(rate);
      stretch = 1.0 / rate;
    }
    std::printf("[ measured ] script times stretched %.2fx to the simulation's pace\n", stretch);
  }
  // Clock seconds for `t` seconds of the script.
  double wall(double t) const { return stretch * t; }
  // A key of a device script at `t` seconds of the script.
  nlohmann::json key(double t, const Eigen::Vector3d& p, int buttons) const {
    return {{"t", wall(t)}, {"position", {p.x(), p.y(), p.z()}}, {"buttons", buttons}};
  }
  // Records of ticks in [from, to) s of the script.
  std::vector<ServoRecord> between(const std::vector<ServoRecord>& records, double from,
                                   double to) const {
    std::vector<ServoRecord> out;
    for (const ServoRecord& r : records)
      if (r.time >= wall(from) && r.time < wall(to)) out.push_back(r);
    return out;
  }
  // Device coordinates of a scene point under the default mapping (Touch).
  Eigen::Vector3d device(const Eigen::Vector3d& scenePoint) const {
    return WorkspaceMapping::fit(0.075, scene.centre, scene.radius).toDevice(scenePoint);
  }
};


TEST(StylusEndToEnd, APullMovesTheSolidWithEqualAndOppositeForcesAndUnpluggingZeroesAtOnce) {
  BlockScene block;
  ASSERT_TRUE(block.ready()) << block.controller.buildStatus().error;
  const SceneFrame rest = block.waitFor(0.02);
  const double restZ = rest.control.col(2).mean();

  // Grab just inside the +z face, low on it (the top is pinned), pull 1 cm (device) along +z,
  // hold, and unplug while holding: the times below in simulated seconds.
  block.paceForThisBuild();
  Clock::time_point started;
  const auto after = [&](double seconds) {
    return started + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(block.wall(seconds)));
  };
  const Eigen::Vector3d grab = block.device(Eigen::Vector3d(1.5, 0.8, 2.8));
  const Eigen::Vector3d pulled = grab + Eigen::Vector3d(0, 0, 0.01);
  const nlohmann::json json = {{"version", 1}, {"model", "touch"}, {"mode", "trajectory"},
                               {"keys", {block.key(0, grab, 0), block.key(0.2, grab, 1),
                                         block.key(1.2, pulled, 1), block.key(3.0, pulled, 1)}}};
  MockPhantom device(parseDeviceScript(json));
  HapticSessionSettings settings;
  settings.tool = HapticTool::Pull;
  settings.recordTicks = static_cast<size_t>(std::ceil(1000 * block.wall(5.0)));
  HapticSession session(block.controller.loop(), device, block.scene, settings);
  const ForceScale scale = session.status().scale;
  ASSERT_GT(scale.sceneNewtonsPerDeviceNewton, 1.0) << scale.describe();
  session.start();
  started = Clock::now();

  // Steady hold from 2.0 s: the simulation's own spring against the servo's force.
  std::this_thread::sleep_until(after(2.3));
  SceneFrame held;
  block.controller.fetchNewer(held);
  ASSERT_EQ(held.springs.size(), 1u) << "the stylus' pull spring is in the scene";
  const ToolSpring spring = held.springs[0];
  const Eigen::Vector3d simulationForce = spring.stiffness * (spring.target - spring.point);
  const double heldZ = held.control.col(2).mean();
  device.setConnected(false);
  std::this_thread::sleep_until(after(2.6));
  const SceneFrame unplugged = block.waitFor(held.simulatedTime + 0.1);
  session.stop();

  EXPECT_GT(heldZ - restZ, 0.01) << "the pull moved the solid along +z";
  EXPECT_TRUE(unplugged.springs.empty()) << "unplugging ended the stroke";

  const std::vector<ServoRecord>& records = session.servo().records();
  ASSERT_GT(records.size(), 2000u);
  // Ticks of the hold, connected: the force on the solid and the force sent to the hand are
  // equal and opposite before clamping (up to the coupling's damping, small at rest).
  double worst = 0, meanOnSolid = 0;
  int n = 0;
  std::vector<ServoRecord> hold;
  for (const ServoRecord& r : block.between(records, 2.0, 2.29))
    if (r.connected && r.acting) hold.push_back(r);
  ASSERT_GT(hold.size(), 200u);
  for (const ServoRecord& r : hold) {
    const Eigen::Vector3d handInScene = r.desired * scale.sceneNewtonsPerDeviceNewton;
    worst = std::max(worst, (handInScene + r.onSolid).norm() / r.onSolid.norm());
    meanOnSolid += r.onSolid.z(), ++n;
  }
  meanOnSolid /= n;
  EXPECT_LT(worst, 0.02) << "hand force x S = -(force on the solid)";
  // And the servo's force on the solid is the simulation's spring force.
  EXPECT_NEAR(meanOnSolid, simulationForce.z(), 0.05 * std::abs(simulationForce.z()));
  EXPECT_GT(simulationForce.z(), 0);

  // Unplugged: the first disconnected tick sends exactly zero, and so does every one after.
  bool seen = false;
  for (const ServoRecord& r : records) {
    if (r.connected) continue;
    if (!seen)
      std::printf("[ measured ] first unplugged tick at %.4f s: |F| = %g N\n", r.time,
                  r.commanded.norm());
    seen = true;
    EXPECT_EQ(r.commanded.norm(), 0.0) << "at " << r.time;
  }
  EXPECT_TRUE(seen);
  std::printf("[ measured ] pull: solid moved %.4f m in z; simulation spring %.4g N, servo %.4g N; "
              "worst |F_hand S + F_solid| / |F_solid| = %.2e; scale %s\n",
              heldZ - restZ, simulationForce.z(), meanOnSolid, worst, scale.describe().c_str());
}

TEST(StylusEndToEnd, ProbingARegionPaintedTenTimesStifferPushesBackHarder) {
  BlockScene block;
  ASSERT_TRUE(block.ready()) << block.controller.buildStatus().error;
  // Paint the left half of the +z face 10x stiffer (a stroke of the product's paint tool).
  PaintStroke::Settings paint;
  paint.brush.radius = 0.9;
  paint.brush.target = SceneSettings().material;
  paint.brush.target.youngs *= 10;
  paint.brush.mirror.x = false;  // the default mirrors across x = 1.5, onto the other probe
  ToolInput at;
  at.restPoint = Eigen::Vector3d(0.6, 1.0, 3.0);
  const uint64_t painted =
      block.controller.loop().beginStroke(std::make_unique<PaintStroke>(paint), at);
  block.controller.loop().endStroke(painted, at);

  // Press the stylus 0.2 m (scene) into the face at x = 0.6 (stiff), withdraw, the same at
  // x = 2.4 (as painted), withdraw: the times below in simulated seconds.
  block.paceForThisBuild();
  const double depth = 0.2;
  auto p = [&](double x, double z) { return block.device(Eigen::Vector3d(x, 1.0, z)); };
  auto keyAt = [&](double t, const Eigen::Vector3d& position) { return block.key(t, position, 0); };
  const nlohmann::json json = {
      {"version", 1}, {"model", "touch"}, {"mode", "trajectory"},
      {"keys", {keyAt(0, p(0.6, 3.3)), keyAt(0.3, p(0.6, 3.3)), keyAt(0.6, p(0.6, 3 - depth)),
                keyAt(1.6, p(0.6, 3 - depth)), keyAt(1.9, p(0.6, 3.3)), keyAt(2.2, p(2.4, 3.3)),
                keyAt(2.5, p(2.4, 3 - depth)), keyAt(3.5, p(2.4, 3 - depth)),
                keyAt(3.8, p(2.4, 3.3))}}};
  MockPhantom device(parseDeviceScript(json));
  HapticSessionSettings settings;
  settings.tool = HapticTool::Probe;
  settings.recordTicks = static_cast<size_t>(std::ceil(1000 * block.wall(6.0)));
  HapticSession session(block.controller.loop(), device, block.scene, settings);
  session.start();
  std::this_thread::sleep_for(std::chrono::duration<double>(block.wall(3.9)));
  session.stop();

  const auto meanForce = [&](double from, double to) {
    double sum = 0;
    int n = 0;
    for (const ServoRecord& r : block.between(session.servo().records(), from, to))
      if (r.acting) sum += r.commanded.norm(), ++n;
    return n > 100 ? sum / n : 0.0;
  };
  const double stiff = meanForce(1.1, 1.6), soft = meanForce(3.0, 3.5);
  std::printf("[ measured ] probe 0.2 m deep: painted 10x stiffer %.3f N, as painted %.3f N\n",
              stiff, soft);
  ASSERT_GT(soft, 0.02) << "the contact pushes back";
  // 1.6x in Release, and under both sanitizers with the script paced (1.17x under
  // ThreadSanitizer before the pacing). The margin asked for stays small: larger, not a
  // calibrated ratio.
  EXPECT_GT(stiff, 1.05 * soft);
  EXPECT_LE(stiff, device.info().maxForce);
  // Out of the surface, nothing: the last 0.1 s are above the face.
  EXPECT_EQ(meanForce(3.8, 3.9), 0.0);
}

}  // namespace
}  // namespace sculpt::haptics
