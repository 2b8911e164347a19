// A take seen at a fraction of its frame rate (the export dialog's "every n-th frame"): frame f of
// TakeSurface(take, range, n) is the take's frame range.first + f n, at fps / n, and the segments
// (one per scene the take was recorded on) are cut where the take's are.

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "anim/take.h"
#include "anim/take_surface.h"
#include "scene/scene_builder.h"
#include "scene/scene_physics.h"

namespace sculpt {
namespace {

// Ten frames of block3 under gravity: frames 0-4 on one built scene, 5-9 on a second build of the
// same file (a second segment, as after a rebuild).
std::shared_ptr<const Take> twoSegmentTake() {
  const SceneSource source{SceneKind::ControlMesh, SCULPT_SOURCE_DIR "/assets/block3.json"};
  auto take = std::make_shared<Take>(30.0);
  for (int scene = 0; scene < 2; ++scene) {
    std::optional<SceneBuildPhase1> phase1 = buildSceneGeometry(source, SceneSettings{}, 1);
    std::unique_ptr<ScenePhysics> physics =
        ScenePhysics::build(phase1->geometry, phase1->solid, SceneSettings{}, nullptr, nullptr);
    for (int f = 0; f < 5; ++f) {
      physics->step();
      take->append(physics->surfaceMap(), physics->simulator().positions());
    }
  }
  return take;
}

TEST(TakeSurface, EveryNthFrameIsTheTakesFrameAtAFractionOfItsRate) {
  const std::shared_ptr<const Take> take = twoSegmentTake();
  ASSERT_EQ(take->frameCount(), 10u);
  ASSERT_EQ(take->segments().size(), 2u);
  const TakeSurface all(take);
  const TakeSurface third(take, FrameRange{1, 9}, 3);  // take frames 1, 4, 7
  EXPECT_EQ(third.frameCount(), 3u);
  EXPECT_DOUBLE_EQ(third.fps(), 10.0);
  ASSERT_EQ(third.segmentCount(), 2u);
  EXPECT_EQ(third.segment(0).first, 0u);
  EXPECT_EQ(third.segment(0).count, 2u);  // take frames 1 and 4
  EXPECT_EQ(third.segment(1).first, 2u);
  EXPECT_EQ(third.segment(1).count, 1u);  // take frame 7
  SurfaceFrameData a, b;
  SolidFrameData solidA, solidB;
  for (uint32_t f = 0; f < third.frameCount(); ++f) {
    third.evaluateSurface(f, a);
    all.evaluateSurface(1 + 3 * f, b);
    EXPECT_EQ(a.positions, b.positions) << "frame " << f;
    EXPECT_EQ(a.normals, b.normals) << "frame " << f;
    third.evaluateSolid(f, solidA);
    all.evaluateSolid(1 + 3 * f, solidB);
    EXPECT_EQ(solidA.nodes, solidB.nodes) << "frame " << f;
  }
  EXPECT_THROW(third.evaluateSurface(3, a), std::out_of_range);

  // A range inside the second segment only, and a step longer than the range.
  const TakeSurface late(take, FrameRange{6, 4}, 2);  // take frames 6, 8
  EXPECT_EQ(late.frameCount(), 2u);
  ASSERT_EQ(late.segmentCount(), 1u);
  EXPECT_EQ(late.segment(0).count, 2u);
  const TakeSurface one(take, FrameRange{2, 3}, 50);  // take frame 2 alone
  EXPECT_EQ(one.frameCount(), 1u);
  EXPECT_THROW(TakeSurface(take, FrameRange{}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace sculpt
