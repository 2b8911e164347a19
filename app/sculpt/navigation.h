#pragma once
// How the keyboard and the mouse drive the window, as logic without a window (see
// docs/design/ux.md, Navigation): a remappable key map with a text form for the preferences file,
// and the two mouse presets that turn pointer input into camera motion or tool strokes.
//
// Key codes are GLFW's (GLFW_KEY_*; Dear ImGui 1.86 uses the same codes) and modifiers GLFW's
// GLFW_MOD_SHIFT | _CONTROL | _ALT | _SUPER bits; Caps Lock / Num Lock bits are ignored.
//
// Mouse presets (drag = press, move, release; the modifiers and the place count at the press):
//   Blender: middle drag orbits, Shift+middle pans, Ctrl+middle zooms (drag up = in), wheel zooms;
//            Alt+left stands in for the middle button (Blender's "emulate 3 button mouse");
//            a left drag is a tool stroke.
//   Stylus (tablets and pens without a middle button, like ZBrush and SculptGL):
//            a left drag that starts on the object is a tool stroke; one that starts on the
//            empty background orbits, with Shift it zooms; Alt+left pans and Alt+Shift+left
//            zooms wherever they start; a right drag (pen barrel button) orbits anywhere;
//            the middle button and the wheel work as in the Blender preset.
//   Both: a double click asks for the pivot to be set on the surface under the cursor and never
//         starts a stroke; a press while ImGui wants the mouse is ignored until its release.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/camera.h"

namespace sculpt::app {

/// What a key can do. The text names (actionName) are what the preferences file stores.
enum class Action {
  // View
  FrameModel,
  FrameAll,
  ViewFront,
  ViewBack,
  ViewRight,
  ViewLeft,
  ViewTop,
  ViewBottom,
  ToggleOrthographic,
  OrbitLeft,
  OrbitRight,
  OrbitUp,
  OrbitDown,
  ZoomIn,
  ZoomOut,
  // Simulation
  PlayPause,
  StepOnce,
  ResetSimulation,
  ToggleRecord,
  // Display
  ToggleWireframe,
  ToggleFlatShading,
  ToggleCellEdges,
  ToggleSlice,
  CycleField,
  CycleDeformation,
  // Edit and brushes
  Undo,
  Redo,
  RedoAlternative,
  BrushSmaller,
  BrushLarger,
  // File and window
  Open,
  Save,
  SaveAs,
  ToggleHelp,
  Screenshot,
  Quit,
};
inline constexpr int kActionCount = static_cast<int>(Action::Quit) + 1;

/// The groups of the help overlay.
enum class ActionGroup { View, Simulation, Display, Edit, File };

/// Stable snake_case name for files ("view_back"), human label ("Back view"), group.
std::string_view actionName(Action action);
std::string_view actionLabel(Action action);
ActionGroup actionGroup(Action action);
std::string_view actionGroupLabel(ActionGroup group);
/// The action of a text name, or nullopt.
std::optional<Action> actionFromName(std::string_view name);

/// GLFW modifier bits that bindings distinguish (Shift, Ctrl, Alt, Super).
int normalizedModifiers(int modifiers);

struct KeyBinding {
  int key = 0;        ///< GLFW_KEY_*
  int modifiers = 0;  ///< GLFW_MOD_* bits (normalized)
  Action action = Action::FrameModel;
  bool operator==(const KeyBinding&) const = default;
};

/// Token of a key in the text form ("Numpad1", "F", "Slash"); empty for codes without a name.
std::string keyName(int key);
/// The key code of a token, or nullopt.
std::optional<int> keyFromName(std::string_view name);
/// Text form of key + modifiers: "Ctrl+Numpad1", "Shift+Slash".
std::string chordName(int key, int modifiers);
/// What the help overlay shows: "Ctrl+Numpad 1", "?" for Shift+Slash, "." for Period.
std::string chordLabel(int key, int modifiers);

class KeyMap {
 public:
  /// An empty map.
  KeyMap() = default;
  /// The bindings of docs/design/ux.md (numpad views with top-row digit fallbacks, F, Home, ?, F1,
  /// ...).
  static KeyMap defaults();

  /// The action bound to key + modifiers (lock bits ignored), or nullopt.
  std::optional<Action> actionFor(int key, int modifiers) const;
  /// Binds key + modifiers to action, replacing what that chord did before. Throws
  /// std::invalid_argument for a key code without a name (see keyName) or unknown modifier bits.
  void bind(int key, int modifiers, Action action);
  /// Removes the binding of key + modifiers; false when there was none.
  bool unbind(int key, int modifiers);
  /// Removes every binding of the action; returns how many there were.
  int unbindAction(Action action);
  /// The chords of an action, in table order.
  std::vector<KeyBinding> bindingsOf(Action action) const;
  const std::vector<KeyBinding>& bindings() const { return bindings_; }

  /// One line per binding, "Ctrl+Numpad1 = view_back", in table order.
  std::string toText() const;
  /// Parses toText's form ('#' comments and blank lines allowed). A bad line (unknown key,
  /// modifier or action, missing '=', a chord bound twice) is skipped and described in *error as
  /// a sentence naming its line ("line 3: unknown action 'fly'."; all bad lines, one per line);
  /// with error == nullptr the first bad line throws std::invalid_argument instead.
  static KeyMap fromText(std::string_view text, std::string* error);

  bool operator==(const KeyMap&) const = default;

 private:
  std::vector<KeyBinding> bindings_;
};

/// Applies the actions that only move the camera (standard views, orthographic toggle, orbit and
/// zoom steps); false for every other action (framing needs the scene's bounds: the app does it).
bool applyCameraAction(Action action, render::Camera& camera);

enum class NavigationPreset { Blender, Stylus };
std::string_view presetName(NavigationPreset preset);

/// What a drag currently does.
enum class Gesture { None, Ignored, Orbit, Pan, Zoom, Stroke };

/// Pointer state of one frame, from GLFW and ImGui.
struct PointerInput {
  float x = 0.0f, y = 0.0f;                          ///< cursor, window pixels, y down
  float dx = 0.0f, dy = 0.0f;                        ///< cursor motion since the previous update
  bool left = false, middle = false, right = false;  ///< buttons held now
  int modifiers = 0;                                 ///< GLFW_MOD_* bits held now
  float wheel = 0.0f;         ///< vertical wheel steps this frame (positive: away from the user)
  bool doubleClick = false;   ///< a press this frame is the second click of a double click
  bool overObject = false;    ///< a surface pixel is under the cursor (depth < 1)
  bool uiWantsMouse = false;  ///< ImGui's io.WantCaptureMouse
};

struct PointerResult {
  bool cameraChanged = false;
  bool setPivotRequested = false;   ///< read the depth under the cursor, then camera.setPivot
  bool strokeBegan = false;         ///< a tool stroke starts at the cursor this frame
  bool strokeActive = false;        ///< a stroke is in progress (also true on its first frame)
  bool strokeEnded = false;         ///< the stroke's button was released this frame
  Gesture gesture = Gesture::None;  ///< the drag in progress after this update
};

/// Turns pointer input into camera motion and strokes; call update() once per frame.
class Navigator {
 public:
  /// Wheel zoom factor per step (positive wheel zooms in), drag zoom per pixel (exp(k * dy)).
  static constexpr float kWheelZoomStep = 0.85f;
  static constexpr float kDragZoomPerPixel = 0.005f;

  explicit Navigator(NavigationPreset preset = NavigationPreset::Blender) : preset_(preset) {}
  NavigationPreset preset() const { return preset_; }
  /// The new preset applies from the next press; a drag in progress goes on as it began.
  void setPreset(NavigationPreset preset) { preset_ = preset; }

  /// Moves the camera by this frame's input (the motion of a press frame is not applied: it
  /// happened before the press). Throws std::invalid_argument for a non-positive viewport.
  PointerResult update(const PointerInput& input, render::Camera& camera, int viewportWidth,
                       int viewportHeight);
  Gesture gesture() const { return gesture_; }

 private:
  /// What a press of this button (0 left, 1 middle, 2 right) starts under this preset.
  Gesture gestureForPress(int button, const PointerInput& input) const;

  NavigationPreset preset_;
  Gesture gesture_ = Gesture::None;
  int dragButton_ = -1;
  bool held_[3] = {false, false, false};
};

}  // namespace sculpt::app
