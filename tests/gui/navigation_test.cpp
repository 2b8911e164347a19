// Mouse presets and the key map (app/sculpt/navigation.h) as pure logic: each preset's gestures
// move the camera the documented way and by the documented amount, ImGui's capture blocks
// everything, a double click asks for a pivot and never strokes; the default key map holds the
// bindings of docs/design/ux.md without clashes and survives its text form.

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <glm/gtc/constants.hpp>

#include "render/camera.h"
#include "sculpt/navigation.h"

namespace sculpt::app {
namespace {

using render::Camera;

constexpr int kWidth = 800, kHeight = 600;

enum Button { kLeft, kMiddle, kRight };

/// Drives a Navigator with press / move / release frames of one button.
struct Driver {
  explicit Driver(NavigationPreset preset) : navigator(preset) {
    camera.setOrientation(0.4f, 0.2f);
    camera.frame(glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, float(kWidth) / float(kHeight));
  }
  PointerResult frame(PointerInput input) {
    input.x = x += input.dx;
    input.y = y += input.dy;
    return navigator.update(input, camera, kWidth, kHeight);
  }
  static PointerInput held(Button button, int modifiers = 0) {
    PointerInput input;
    input.left = button == kLeft;
    input.middle = button == kMiddle;
    input.right = button == kRight;
    input.modifiers = modifiers;
    return input;
  }
  PointerResult press(Button button, int modifiers = 0, bool overObject = false) {
    PointerInput input = held(button, modifiers);
    input.overObject = overObject;
    return frame(input);
  }
  PointerResult move(Button button, float dx, float dy, int modifiers = 0) {
    PointerInput input = held(button, modifiers);
    input.dx = dx;
    input.dy = dy;
    return frame(input);
  }
  PointerResult release() { return frame(PointerInput{}); }
  /// press, one move, release; returns the move's result.
  PointerResult drag(Button button, float dx, float dy, int modifiers = 0,
                     bool overObject = false) {
    press(button, modifiers, overObject);
    const PointerResult result = move(button, dx, dy, modifiers);
    release();
    return result;
  }

  Navigator navigator;
  Camera camera;
  float x = 400.0f, y = 300.0f;
};

struct Snapshot {
  explicit Snapshot(const Camera& c)
      : pivot(c.pivot()), yaw(c.yaw()), pitch(c.pitch()), distance(c.distance()) {}
  glm::vec3 pivot;
  float yaw, pitch, distance;
  bool operator==(const Snapshot&) const = default;
};

void expectOrbited(const Snapshot& before, const Camera& after, float dx, float dy) {
  EXPECT_NEAR(after.yaw(), before.yaw - Camera::kOrbitRadiansPerPixel * dx, 1e-6f);
  EXPECT_NEAR(after.pitch(), before.pitch + Camera::kOrbitRadiansPerPixel * dy, 1e-6f);
  EXPECT_EQ(after.pivot(), before.pivot);
  EXPECT_EQ(after.distance(), before.distance);
}

void expectPanned(const Snapshot& before, const Camera& after, float dx, float dy) {
  EXPECT_EQ(after.yaw(), before.yaw);
  EXPECT_EQ(after.pitch(), before.pitch);
  EXPECT_EQ(after.distance(), before.distance);
  const float pixel = after.pixelSizeAtPivot(kHeight);
  const glm::vec3 expected = before.pivot + pixel * (-dx * after.right() + dy * after.up());
  EXPECT_LT(glm::length(after.pivot() - expected), 1e-6f);
  EXPECT_GT(glm::length(after.pivot() - before.pivot), 0.0f);
}

void expectZoomed(const Snapshot& before, const Camera& after, float factor) {
  EXPECT_EQ(after.yaw(), before.yaw);
  EXPECT_EQ(after.pitch(), before.pitch);
  EXPECT_EQ(after.pivot(), before.pivot);
  EXPECT_NEAR(after.distance(), before.distance * factor, 1e-6f * before.distance);
}

// [Blender preset] ----------------------------------------------------------------------------

TEST(NavigatorBlender, MiddleDragOrbitsShiftPansCtrlZooms) {
  {
    Driver d(NavigationPreset::Blender);
    const Snapshot before(d.camera);
    EXPECT_EQ(d.press(kMiddle).gesture, Gesture::Orbit);
    const PointerResult moved = d.move(kMiddle, 30.0f, -12.0f);
    EXPECT_TRUE(moved.cameraChanged);
    EXPECT_FALSE(moved.strokeActive);
    expectOrbited(before, d.camera, 30.0f, -12.0f);
    EXPECT_EQ(d.release().gesture, Gesture::None);
  }
  {
    Driver d(NavigationPreset::Blender);
    const Snapshot before(d.camera);
    EXPECT_EQ(d.drag(kMiddle, -25.0f, 14.0f, GLFW_MOD_SHIFT).gesture, Gesture::Pan);
    expectPanned(before, d.camera, -25.0f, 14.0f);
  }
  {
    Driver d(NavigationPreset::Blender);
    const Snapshot before(d.camera);
    EXPECT_EQ(d.drag(kMiddle, 5.0f, -40.0f, GLFW_MOD_CONTROL).gesture, Gesture::Zoom);
    // Dragging up zooms in: exp(k * dy) < 1.
    expectZoomed(before, d.camera, std::exp(Navigator::kDragZoomPerPixel * -40.0f));
    EXPECT_LT(d.camera.distance(), before.distance);
  }
}

TEST(NavigatorBlender, AltLeftEmulatesTheMiddleButtonAndPlainLeftStrokes) {
  Driver d(NavigationPreset::Blender);
  Snapshot before(d.camera);
  d.drag(kLeft, 20.0f, 10.0f, GLFW_MOD_ALT);
  expectOrbited(before, d.camera, 20.0f, 10.0f);
  before = Snapshot(d.camera);
  d.drag(kLeft, 20.0f, 10.0f, GLFW_MOD_ALT | GLFW_MOD_SHIFT);
  expectPanned(before, d.camera, 20.0f, 10.0f);

  before = Snapshot(d.camera);
  const PointerResult began = d.press(kLeft);
  EXPECT_TRUE(began.strokeBegan);
  EXPECT_TRUE(began.strokeActive);
  const PointerResult active = d.move(kLeft, 30.0f, 30.0f);
  EXPECT_FALSE(active.strokeBegan);
  EXPECT_TRUE(active.strokeActive);
  EXPECT_FALSE(active.cameraChanged);
  const PointerResult ended = d.release();
  EXPECT_TRUE(ended.strokeEnded);
  EXPECT_FALSE(ended.strokeActive);
  EXPECT_EQ(Snapshot(d.camera), before);
}

TEST(NavigatorBlender, ModifiersCountAtThePressOnly) {
  Driver d(NavigationPreset::Blender);
  const Snapshot before(d.camera);
  d.press(kMiddle);
  d.move(kMiddle, 15.0f, 0.0f, GLFW_MOD_SHIFT);  // Shift pressed mid-drag: still an orbit
  expectOrbited(before, d.camera, 15.0f, 0.0f);
}

TEST(NavigatorBlender, TheRightButtonIsLeftToTheApplication) {
  Driver d(NavigationPreset::Blender);
  const Snapshot before(d.camera);
  EXPECT_EQ(d.drag(kRight, 50.0f, 50.0f).gesture, Gesture::None);
  EXPECT_EQ(Snapshot(d.camera), before);
}

// [Stylus preset] -----------------------------------------------------------------------------

TEST(NavigatorStylus, LeftDragOnTheBackgroundOrbitsOnTheObjectStrokes) {
  Driver d(NavigationPreset::Stylus);
  Snapshot before(d.camera);
  EXPECT_EQ(d.drag(kLeft, -18.0f, 22.0f).gesture, Gesture::Orbit);
  expectOrbited(before, d.camera, -18.0f, 22.0f);

  before = Snapshot(d.camera);
  const PointerResult began = d.press(kLeft, 0, /*overObject=*/true);
  EXPECT_TRUE(began.strokeBegan);
  // The cursor leaving the object mid-stroke changes nothing: the press decided.
  PointerInput moved = Driver::held(kLeft);
  moved.dx = 60.0f;
  moved.overObject = false;
  const PointerResult active = d.frame(moved);
  EXPECT_TRUE(active.strokeActive);
  EXPECT_FALSE(active.cameraChanged);
  EXPECT_TRUE(d.release().strokeEnded);
  EXPECT_EQ(Snapshot(d.camera), before);
}

TEST(NavigatorStylus, AltPansAnywhereShiftZoomsOnTheBackgroundRightOrbitsAnywhere) {
  Driver d(NavigationPreset::Stylus);
  Snapshot before(d.camera);
  EXPECT_EQ(d.drag(kLeft, 12.0f, -7.0f, GLFW_MOD_ALT, /*overObject=*/true).gesture, Gesture::Pan);
  expectPanned(before, d.camera, 12.0f, -7.0f);

  before = Snapshot(d.camera);
  EXPECT_EQ(d.drag(kLeft, 0.0f, 30.0f, GLFW_MOD_SHIFT).gesture, Gesture::Zoom);
  expectZoomed(before, d.camera, std::exp(Navigator::kDragZoomPerPixel * 30.0f));
  EXPECT_GT(d.camera.distance(), before.distance);  // dragging down zooms out

  before = Snapshot(d.camera);
  EXPECT_EQ(d.drag(kLeft, 0.0f, -30.0f, GLFW_MOD_ALT | GLFW_MOD_SHIFT, true).gesture,
            Gesture::Zoom);
  expectZoomed(before, d.camera, std::exp(Navigator::kDragZoomPerPixel * -30.0f));

  before = Snapshot(d.camera);
  EXPECT_EQ(d.drag(kRight, 9.0f, 4.0f, 0, /*overObject=*/true).gesture, Gesture::Orbit);
  expectOrbited(before, d.camera, 9.0f, 4.0f);

  // Shift on the object is a stroke (for the tools), not a zoom.
  before = Snapshot(d.camera);
  EXPECT_TRUE(d.press(kLeft, GLFW_MOD_SHIFT, true).strokeBegan);
  d.move(kLeft, 0.0f, 30.0f, GLFW_MOD_SHIFT);
  d.release();
  EXPECT_EQ(Snapshot(d.camera), before);
}

// [Both presets] ------------------------------------------------------------------------------

TEST(Navigator, PositiveWheelZoomsInInBothPresets) {
  for (const NavigationPreset preset : {NavigationPreset::Blender, NavigationPreset::Stylus}) {
    Driver d(preset);
    const Snapshot before(d.camera);
    PointerInput input;
    input.wheel = 2.0f;
    EXPECT_TRUE(d.frame(input).cameraChanged);
    expectZoomed(before, d.camera, Navigator::kWheelZoomStep * Navigator::kWheelZoomStep);
    EXPECT_LT(Navigator::kWheelZoomStep, 1.0f);
    input.wheel = -2.0f;
    d.frame(input);
    EXPECT_NEAR(d.camera.distance(), before.distance, 1e-5f * before.distance);
  }
}

TEST(Navigator, ImGuiCaptureBlocksEverything) {
  for (const NavigationPreset preset : {NavigationPreset::Blender, NavigationPreset::Stylus}) {
    for (const Button button : {kLeft, kMiddle, kRight})
      for (const int modifiers : {0, GLFW_MOD_SHIFT, GLFW_MOD_CONTROL, GLFW_MOD_ALT})
        for (const bool overObject : {false, true}) {
          Driver d(preset);
          const Snapshot before(d.camera);
          PointerInput input = Driver::held(button, modifiers);
          input.uiWantsMouse = true;
          input.overObject = overObject;
          input.wheel = 1.0f;
          PointerResult pressed = d.frame(input);
          input.dx = 40.0f, input.dy = -25.0f;
          PointerResult moved = d.frame(input);
          for (const PointerResult& r : {pressed, moved}) {
            EXPECT_FALSE(r.cameraChanged);
            EXPECT_FALSE(r.strokeBegan);
            EXPECT_FALSE(r.strokeActive);
            EXPECT_FALSE(r.setPivotRequested);
          }
          EXPECT_EQ(Snapshot(d.camera), before);
        }
  }
}

TEST(Navigator, ADragBegunOverTheUiStaysIgnoredAfterLeavingIt) {
  for (const NavigationPreset preset : {NavigationPreset::Blender, NavigationPreset::Stylus}) {
    const Button button = preset == NavigationPreset::Blender ? kMiddle : kLeft;
    Driver d(preset);
    const Snapshot before(d.camera);
    PointerInput input = Driver::held(button);
    input.uiWantsMouse = true;
    EXPECT_EQ(d.frame(input).gesture, Gesture::Ignored);
    input.uiWantsMouse = false;  // the cursor is now over the 3D view, button still held
    input.dx = 50.0f;
    input.dy = 20.0f;
    const PointerResult moved = d.frame(input);
    EXPECT_EQ(moved.gesture, Gesture::Ignored);
    EXPECT_FALSE(moved.cameraChanged);
    EXPECT_FALSE(moved.strokeActive);
    EXPECT_EQ(Snapshot(d.camera), before);
    // After the release the next drag works.
    EXPECT_EQ(d.release().gesture, Gesture::None);
    d.drag(button, 10.0f, 0.0f);
    expectOrbited(before, d.camera, 10.0f, 0.0f);
  }
}

TEST(Navigator, DoubleClickRequestsThePivotAndNeverStrokes) {
  for (const NavigationPreset preset : {NavigationPreset::Blender, NavigationPreset::Stylus}) {
    Driver d(preset);
    // First click: a click stroke on the object.
    EXPECT_TRUE(d.press(kLeft, 0, true).strokeBegan);
    EXPECT_TRUE(d.release().strokeEnded);
    const Snapshot before(d.camera);
    // Second press, flagged as a double click.
    PointerInput input = Driver::held(kLeft);
    input.overObject = true;
    input.doubleClick = true;
    const PointerResult second = d.frame(input);
    EXPECT_TRUE(second.setPivotRequested);
    EXPECT_FALSE(second.strokeBegan);
    EXPECT_FALSE(second.strokeActive);
    // Dragging on after the double click neither strokes nor moves the camera.
    input.doubleClick = false;
    input.dx = 30.0f;
    const PointerResult held = d.frame(input);
    EXPECT_FALSE(held.strokeActive);
    EXPECT_FALSE(held.setPivotRequested);
    EXPECT_FALSE(d.release().strokeEnded);
    EXPECT_EQ(Snapshot(d.camera), before);
  }
}

TEST(Navigator, BadViewportThrows) {
  Driver d(NavigationPreset::Blender);
  EXPECT_THROW(d.navigator.update(PointerInput{}, d.camera, 0, 10), std::invalid_argument);
}

// [Key map] -----------------------------------------------------------------------------------

TEST(KeyMap, DefaultsHoldTheBindingsOfUx) {
  const KeyMap keys = KeyMap::defaults();
  const std::pair<std::pair<int, int>, Action> expected[] = {
      {{GLFW_KEY_F, 0}, Action::FrameModel},
      {{GLFW_KEY_HOME, 0}, Action::FrameAll},
      {{GLFW_KEY_KP_1, 0}, Action::ViewFront},
      {{GLFW_KEY_KP_3, 0}, Action::ViewRight},
      {{GLFW_KEY_KP_7, 0}, Action::ViewTop},
      {{GLFW_KEY_KP_1, GLFW_MOD_CONTROL}, Action::ViewBack},
      {{GLFW_KEY_KP_3, GLFW_MOD_CONTROL}, Action::ViewLeft},
      {{GLFW_KEY_KP_7, GLFW_MOD_CONTROL}, Action::ViewBottom},
      {{GLFW_KEY_KP_5, 0}, Action::ToggleOrthographic},
      {{GLFW_KEY_1, 0}, Action::ViewFront},  // laptop fallbacks
      {{GLFW_KEY_3, 0}, Action::ViewRight},
      {{GLFW_KEY_7, 0}, Action::ViewTop},
      {{GLFW_KEY_1, GLFW_MOD_CONTROL}, Action::ViewBack},
      {{GLFW_KEY_5, 0}, Action::ToggleOrthographic},
      {{GLFW_KEY_SLASH, GLFW_MOD_SHIFT}, Action::ToggleHelp},  // '?'
      {{GLFW_KEY_F1, 0}, Action::ToggleHelp},
      {{GLFW_KEY_SPACE, 0}, Action::PlayPause},
      {{GLFW_KEY_PERIOD, 0}, Action::StepOnce},
      {{GLFW_KEY_RIGHT, 0}, Action::StepOnce},
      {{GLFW_KEY_R, GLFW_MOD_SHIFT}, Action::ResetSimulation},
      {{GLFW_KEY_R, 0}, Action::ToggleRecord},
      {{GLFW_KEY_Z, 0}, Action::ToggleWireframe},
      {{GLFW_KEY_F12, 0}, Action::Screenshot},
      {{GLFW_KEY_Q, GLFW_MOD_CONTROL}, Action::Quit},
  };
  for (const auto& [chord, action] : expected)
    EXPECT_EQ(keys.actionFor(chord.first, chord.second), action)
        << chordName(chord.first, chord.second);
  // Lock keys do not change the chord; other modifiers do.
  EXPECT_EQ(keys.actionFor(GLFW_KEY_KP_1, GLFW_MOD_NUM_LOCK), Action::ViewFront);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_F, GLFW_MOD_CAPS_LOCK), Action::FrameModel);
  EXPECT_FALSE(keys.actionFor(GLFW_KEY_Q, 0).has_value());
  EXPECT_FALSE(keys.actionFor(GLFW_KEY_F, GLFW_MOD_ALT).has_value());
  // docs/design/ux.md "Undo" and "Files": Ctrl+Z, Ctrl+Shift+Z (and Ctrl+Y), Ctrl+S; [ and ] step
  // the brush.
  EXPECT_EQ(keys.actionFor(GLFW_KEY_Z, GLFW_MOD_CONTROL), Action::Undo);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT), Action::Redo);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_Y, GLFW_MOD_CONTROL), Action::RedoAlternative);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_S, GLFW_MOD_CONTROL), Action::Save);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_O, GLFW_MOD_CONTROL), Action::Open);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_S, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT), Action::SaveAs);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_LEFT_BRACKET, 0), Action::BrushSmaller);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_RIGHT_BRACKET, 0), Action::BrushLarger);
}

TEST(KeyMap, NoTwoDefaultBindingsShareAChordAndEveryActionIsBound) {
  const KeyMap keys = KeyMap::defaults();
  std::set<std::pair<int, int>> chords;
  for (const KeyBinding& b : keys.bindings()) {
    EXPECT_TRUE(chords.insert({b.key, b.modifiers}).second) << chordName(b.key, b.modifiers);
    EXPECT_FALSE(keyName(b.key).empty());
  }
  for (int a = 0; a < kActionCount; ++a)
    EXPECT_FALSE(keys.bindingsOf(static_cast<Action>(a)).empty())
        << actionName(static_cast<Action>(a));
}

TEST(KeyMap, ActionAndKeyNamesAreUniqueAndRoundTrip) {
  std::set<std::string_view> names;
  for (int a = 0; a < kActionCount; ++a) {
    const auto action = static_cast<Action>(a);
    EXPECT_TRUE(names.insert(actionName(action)).second);
    EXPECT_EQ(actionFromName(actionName(action)), action);
    EXPECT_FALSE(actionLabel(action).empty());
  }
  EXPECT_FALSE(actionFromName("fly").has_value());
  for (int key = 0; key <= GLFW_KEY_LAST; ++key) {
    const std::string name = keyName(key);
    if (!name.empty()) {
      EXPECT_EQ(keyFromName(name), key) << name;
    }
  }
  EXPECT_EQ(keyFromName("Numpad1"), GLFW_KEY_KP_1);
  EXPECT_EQ(chordName(GLFW_KEY_KP_1, GLFW_MOD_CONTROL), "Ctrl+Numpad1");
  EXPECT_EQ(chordLabel(GLFW_KEY_KP_1, GLFW_MOD_CONTROL), "Ctrl+Numpad 1");
  EXPECT_EQ(chordLabel(GLFW_KEY_SLASH, GLFW_MOD_SHIFT), "?");
  EXPECT_EQ(chordLabel(GLFW_KEY_PERIOD, 0), ".");
}

TEST(KeyMap, TextRoundTripIsTheIdentity) {
  KeyMap keys = KeyMap::defaults();
  const std::string text = keys.toText();
  EXPECT_NE(text.find("Ctrl+Numpad1 = view_back\n"), std::string::npos) << text;
  std::string error = "stale";
  EXPECT_EQ(KeyMap::fromText(text, &error), keys);
  EXPECT_EQ(error, "");
  EXPECT_EQ(KeyMap::fromText(text, &error).toText(), text);
  // Also after remapping, and for the empty map.
  keys.bind(GLFW_KEY_KP_1, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT | GLFW_MOD_ALT | GLFW_MOD_SUPER,
            Action::Quit);
  keys.bind(GLFW_KEY_F, 0, Action::FrameAll);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_F, 0), Action::FrameAll);
  EXPECT_EQ(KeyMap::fromText(keys.toText(), nullptr), keys);
  EXPECT_EQ(KeyMap::fromText(KeyMap().toText(), nullptr), KeyMap());
  // Comments, blank lines, spacing and case are forgiven.
  const KeyMap loose = KeyMap::fromText("# mine\n\n  ctrl + numpad1=VIEW_BACK  # back\n", &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(loose.actionFor(GLFW_KEY_KP_1, GLFW_MOD_CONTROL), Action::ViewBack);
}

TEST(KeyMap, MalformedLinesAreReportedByLineNumber) {
  const std::string text =
      "F = frame_model\n"
      "Ctrl+Numpad1 = fly\n"
      "Hyper+A = quit\n"
      "Numpad42 = quit\n"
      "Space play_pause\n"
      "F = frame_all\n"
      "Home = frame_all\n";
  std::string error;
  const KeyMap keys = KeyMap::fromText(text, &error);
  EXPECT_NE(error.find("line 2: unknown action 'fly'"), std::string::npos) << error;
  EXPECT_NE(error.find("line 3: unknown modifier 'Hyper'"), std::string::npos) << error;
  EXPECT_NE(error.find("line 4: unknown key 'Numpad42'"), std::string::npos) << error;
  EXPECT_NE(error.find("line 5: expected 'keys = action'"), std::string::npos) << error;
  EXPECT_NE(error.find("line 6: F is already bound on line 1"), std::string::npos) << error;
  // The good lines are kept.
  ASSERT_EQ(keys.bindings().size(), 2u);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_F, 0), Action::FrameModel);
  EXPECT_EQ(keys.actionFor(GLFW_KEY_HOME, 0), Action::FrameAll);
  // Without an error string the first bad line throws.
  try {
    KeyMap::fromText(text, nullptr);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
}

TEST(KeyMap, BindUnbindAndBadCodes) {
  KeyMap keys;
  keys.bind(GLFW_KEY_A, GLFW_MOD_SHIFT, Action::CycleField);
  keys.bind(GLFW_KEY_B, 0, Action::CycleField);
  EXPECT_EQ(keys.bindingsOf(Action::CycleField).size(), 2u);
  EXPECT_TRUE(keys.unbind(GLFW_KEY_A, GLFW_MOD_SHIFT));
  EXPECT_FALSE(keys.unbind(GLFW_KEY_A, GLFW_MOD_SHIFT));
  EXPECT_FALSE(keys.actionFor(GLFW_KEY_A, GLFW_MOD_SHIFT).has_value());
  EXPECT_EQ(keys.unbindAction(Action::CycleField), 1);
  EXPECT_TRUE(keys.bindings().empty());
  EXPECT_THROW(keys.bind(-1, 0, Action::Quit), std::invalid_argument);
  EXPECT_THROW(keys.bind(GLFW_KEY_LEFT_SHIFT, 0, Action::Quit), std::invalid_argument);
  EXPECT_THROW(keys.bind(GLFW_KEY_A, 0x400, Action::Quit), std::invalid_argument);
  EXPECT_THROW(keys.bind(GLFW_KEY_A, 0, static_cast<Action>(999)), std::invalid_argument);
}

TEST(KeyMap, CameraActionsMoveTheCamera) {
  Camera camera;
  camera.frame(glm::vec3(0.0f), 1.0f, 1.0f);
  EXPECT_TRUE(applyCameraAction(Action::ViewTop, camera));
  EXPECT_LT(glm::length(glm::normalize(camera.eye() - camera.pivot()) - glm::vec3(0, 1, 0)), 1e-6f);
  EXPECT_TRUE(applyCameraAction(Action::ViewBack, camera));
  EXPECT_LT(glm::length(glm::normalize(camera.eye() - camera.pivot()) - glm::vec3(0, 0, -1)),
            1e-6f);
  EXPECT_TRUE(applyCameraAction(Action::ToggleOrthographic, camera));
  EXPECT_TRUE(camera.orthographic());
  const float distance = camera.distance();
  EXPECT_TRUE(applyCameraAction(Action::ZoomIn, camera));
  EXPECT_LT(camera.distance(), distance);
  const float yaw = camera.yaw();
  EXPECT_TRUE(applyCameraAction(Action::OrbitRight, camera));
  EXPECT_NEAR(std::remainder(camera.yaw() - yaw - glm::radians(15.0f), glm::two_pi<float>()), 0.0f,
              1e-5f);
  EXPECT_FALSE(applyCameraAction(Action::FrameModel, camera));  // needs the scene: the app's job
  EXPECT_FALSE(applyCameraAction(Action::PlayPause, camera));
}

}  // namespace
}  // namespace sculpt::app
