#include "sculpt/navigation.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace sculpt::app {
namespace {

// [Actions] -----------------------------------------------------------------------------------

struct ActionInfo {
  Action action;
  const char* name;
  const char* label;
  ActionGroup group;
};

// One row per Action, in enum order (checked by actionInfo()).
constexpr std::array<ActionInfo, kActionCount> kActions{{
    {Action::FrameModel, "frame_model", "Frame the model", ActionGroup::View},
    {Action::FrameAll, "frame_all", "Frame everything", ActionGroup::View},
    {Action::ViewFront, "view_front", "Front view", ActionGroup::View},
    {Action::ViewBack, "view_back", "Back view", ActionGroup::View},
    {Action::ViewRight, "view_right", "Right view", ActionGroup::View},
    {Action::ViewLeft, "view_left", "Left view", ActionGroup::View},
    {Action::ViewTop, "view_top", "Top view", ActionGroup::View},
    {Action::ViewBottom, "view_bottom", "Bottom view", ActionGroup::View},
    {Action::ToggleOrthographic, "toggle_orthographic", "Perspective / orthographic",
     ActionGroup::View},
    {Action::OrbitLeft, "orbit_left", "Orbit left 15 degrees", ActionGroup::View},
    {Action::OrbitRight, "orbit_right", "Orbit right 15 degrees", ActionGroup::View},
    {Action::OrbitUp, "orbit_up", "Orbit up 15 degrees", ActionGroup::View},
    {Action::OrbitDown, "orbit_down", "Orbit down 15 degrees", ActionGroup::View},
    {Action::ZoomIn, "zoom_in", "Zoom in", ActionGroup::View},
    {Action::ZoomOut, "zoom_out", "Zoom out", ActionGroup::View},
    {Action::PlayPause, "play_pause", "Play / pause the simulation", ActionGroup::Simulation},
    {Action::StepOnce, "step_once", "Step once (when paused)", ActionGroup::Simulation},
    {Action::ResetSimulation, "reset_simulation", "Reset to the rest shape",
     ActionGroup::Simulation},
    {Action::ToggleRecord, "toggle_record", "Record / stop recording", ActionGroup::Simulation},
    {Action::ToggleWireframe, "toggle_wireframe", "Wireframe on / off", ActionGroup::Display},
    {Action::ToggleFlatShading, "toggle_flat_shading", "Flat / smooth shading",
     ActionGroup::Display},
    {Action::ToggleCellEdges, "toggle_cell_edges", "Simulation cell edges on / off",
     ActionGroup::Display},
    {Action::ToggleSlice, "toggle_slice", "Clipping-plane slice on / off", ActionGroup::Display},
    {Action::CycleField, "cycle_field", "Next colour field", ActionGroup::Display},
    {Action::CycleDeformation, "cycle_deformation", "Next deformation method",
     ActionGroup::Display},
    {Action::Undo, "undo", "Undo", ActionGroup::Edit},
    {Action::Redo, "redo", "Redo", ActionGroup::Edit},
    {Action::RedoAlternative, "redo_alternative", "Redo", ActionGroup::Edit},
    {Action::BrushSmaller, "brush_smaller", "Smaller brush (F + drag: radius)", ActionGroup::Edit},
    {Action::BrushLarger, "brush_larger", "Larger brush (Shift+F + drag: strength)",
     ActionGroup::Edit},
    {Action::Open, "open", "Open a project or a scene", ActionGroup::File},
    {Action::Save, "save", "Save the project", ActionGroup::File},
    {Action::SaveAs, "save_as", "Save the project as", ActionGroup::File},
    {Action::ToggleHelp, "toggle_help", "This help", ActionGroup::File},
    {Action::Screenshot, "screenshot", "Save a screenshot", ActionGroup::File},
    {Action::Quit, "quit", "Quit", ActionGroup::File},
}};

const ActionInfo& actionInfo(Action action) {
  const auto index = static_cast<size_t>(action);
  if (index >= kActions.size() || kActions[index].action != action)
    throw std::invalid_argument("unknown action " + std::to_string(index));
  return kActions[index];
}

// [Keys] --------------------------------------------------------------------------------------

struct KeyInfo {
  int key;
  std::string name;   // token of the text form
  std::string label;  // what the help shows
};

const std::vector<KeyInfo>& keyTable() {
  static const std::vector<KeyInfo> table = [] {
    std::vector<KeyInfo> keys;
    // GLFW's letter and digit codes are their ASCII characters.
    for (int c = 'A'; c <= 'Z'; ++c)
      keys.push_back({c, std::string(1, char(c)), std::string(1, char(c))});
    for (int c = '0'; c <= '9'; ++c)
      keys.push_back({c, std::string(1, char(c)), std::string(1, char(c))});
    // (Appending rather than "F" + std::to_string(f) avoids a GCC 12 -Wrestrict false positive.)
    for (int f = 1; f <= 25; ++f) {
      std::string name("F");
      name.append(std::to_string(f));
      keys.push_back({GLFW_KEY_F1 + f - 1, name, name});
    }
    for (int d = 0; d <= 9; ++d) {
      std::string name("Numpad"), label("Numpad ");
      name.append(std::to_string(d));
      label.append(std::to_string(d));
      keys.push_back({GLFW_KEY_KP_0 + d, name, label});
    }
    const std::vector<KeyInfo> named = {
        {GLFW_KEY_KP_DECIMAL, "NumpadDecimal", "Numpad ."},
        {GLFW_KEY_KP_DIVIDE, "NumpadDivide", "Numpad /"},
        {GLFW_KEY_KP_MULTIPLY, "NumpadMultiply", "Numpad *"},
        {GLFW_KEY_KP_SUBTRACT, "NumpadSubtract", "Numpad -"},
        {GLFW_KEY_KP_ADD, "NumpadAdd", "Numpad +"},
        {GLFW_KEY_KP_ENTER, "NumpadEnter", "Numpad Enter"},
        {GLFW_KEY_KP_EQUAL, "NumpadEqual", "Numpad ="},
        {GLFW_KEY_SPACE, "Space", "Space"},
        {GLFW_KEY_APOSTROPHE, "Apostrophe", "'"},
        {GLFW_KEY_COMMA, "Comma", ","},
        {GLFW_KEY_MINUS, "Minus", "-"},
        {GLFW_KEY_PERIOD, "Period", "."},
        {GLFW_KEY_SLASH, "Slash", "/"},
        {GLFW_KEY_SEMICOLON, "Semicolon", ";"},
        {GLFW_KEY_EQUAL, "Equal", "="},
        {GLFW_KEY_LEFT_BRACKET, "LeftBracket", "["},
        {GLFW_KEY_BACKSLASH, "Backslash", "\\"},
        {GLFW_KEY_RIGHT_BRACKET, "RightBracket", "]"},
        {GLFW_KEY_GRAVE_ACCENT, "GraveAccent", "`"},
        {GLFW_KEY_ESCAPE, "Escape", "Esc"},
        {GLFW_KEY_ENTER, "Enter", "Enter"},
        {GLFW_KEY_TAB, "Tab", "Tab"},
        {GLFW_KEY_BACKSPACE, "Backspace", "Backspace"},
        {GLFW_KEY_INSERT, "Insert", "Insert"},
        {GLFW_KEY_DELETE, "Delete", "Delete"},
        {GLFW_KEY_RIGHT, "Right", "Right arrow"},
        {GLFW_KEY_LEFT, "Left", "Left arrow"},
        {GLFW_KEY_DOWN, "Down", "Down arrow"},
        {GLFW_KEY_UP, "Up", "Up arrow"},
        {GLFW_KEY_PAGE_UP, "PageUp", "Page Up"},
        {GLFW_KEY_PAGE_DOWN, "PageDown", "Page Down"},
        {GLFW_KEY_HOME, "Home", "Home"},
        {GLFW_KEY_END, "End", "End"},
        {GLFW_KEY_PRINT_SCREEN, "PrintScreen", "Print Screen"},
        {GLFW_KEY_PAUSE, "Pause", "Pause"},
        {GLFW_KEY_MENU, "Menu", "Menu"},
    };
    keys.insert(keys.end(), named.begin(), named.end());
    return keys;
  }();
  return table;
}

const KeyInfo* findKey(int key) {
  for (const KeyInfo& info : keyTable())
    if (info.key == key) return &info;
  return nullptr;
}

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

constexpr int kModifierMask = GLFW_MOD_SHIFT | GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER;

// Text form order: Ctrl before Shift before Alt before Super, as most programs write them.
struct ModifierInfo {
  int bit;
  const char* name;
};
constexpr std::array<ModifierInfo, 4> kModifiers{{{GLFW_MOD_CONTROL, "Ctrl"},
                                                  {GLFW_MOD_SHIFT, "Shift"},
                                                  {GLFW_MOD_ALT, "Alt"},
                                                  {GLFW_MOD_SUPER, "Super"}}};

std::string modifierPrefix(int modifiers) {
  std::string out;
  for (const ModifierInfo& m : kModifiers)
    if (modifiers & m.bit) out += std::string(m.name) + "+";
  return out;
}

std::string_view trim(std::string_view s) {
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace

std::string_view actionName(Action action) { return actionInfo(action).name; }
std::string_view actionLabel(Action action) { return actionInfo(action).label; }
ActionGroup actionGroup(Action action) { return actionInfo(action).group; }

std::string_view actionGroupLabel(ActionGroup group) {
  switch (group) {
    case ActionGroup::View:
      return "View";
    case ActionGroup::Simulation:
      return "Simulation";
    case ActionGroup::Display:
      return "Display";
    case ActionGroup::Edit:
      return "Edit and brushes";
    case ActionGroup::File:
      return "File and window";
  }
  return "";
}

std::optional<Action> actionFromName(std::string_view name) {
  for (const ActionInfo& info : kActions)
    if (equalsIgnoreCase(info.name, name)) return info.action;
  return std::nullopt;
}

int normalizedModifiers(int modifiers) { return modifiers & kModifierMask; }

std::string keyName(int key) {
  const KeyInfo* info = findKey(key);
  return info ? info->name : std::string();
}

std::optional<int> keyFromName(std::string_view name) {
  for (const KeyInfo& info : keyTable())
    if (equalsIgnoreCase(info.name, name)) return info.key;
  return std::nullopt;
}

std::string chordName(int key, int modifiers) {
  return modifierPrefix(normalizedModifiers(modifiers)) + keyName(key);
}

std::string chordLabel(int key, int modifiers) {
  modifiers = normalizedModifiers(modifiers);
  // '?' is Shift+/ on US layouts; show the character the user looks for.
  if (key == GLFW_KEY_SLASH && (modifiers & GLFW_MOD_SHIFT))
    return modifierPrefix(modifiers & ~GLFW_MOD_SHIFT) + "?";
  const KeyInfo* info = findKey(key);
  return modifierPrefix(modifiers) + (info ? info->label : "key " + std::to_string(key));
}

// [KeyMap] ------------------------------------------------------------------------------------

KeyMap KeyMap::defaults() {
  KeyMap map;
  const auto bind = [&map](int key, int modifiers, Action action) {
    map.bind(key, modifiers, action);
  };
  constexpr int kNone = 0, kCtrl = GLFW_MOD_CONTROL, kShift = GLFW_MOD_SHIFT;
  // View (Blender's numpad; the top-row digits stand in on laptops without a numpad)
  bind(GLFW_KEY_F, kNone, Action::FrameModel);
  bind(GLFW_KEY_HOME, kNone, Action::FrameAll);
  for (int numpad : {1, 0}) {
    const auto key = [numpad](int digit) {
      return numpad ? GLFW_KEY_KP_0 + digit : GLFW_KEY_0 + digit;
    };
    bind(key(1), kNone, Action::ViewFront);
    bind(key(1), kCtrl, Action::ViewBack);
    bind(key(3), kNone, Action::ViewRight);
    bind(key(3), kCtrl, Action::ViewLeft);
    bind(key(7), kNone, Action::ViewTop);
    bind(key(7), kCtrl, Action::ViewBottom);
    bind(key(5), kNone, Action::ToggleOrthographic);
  }
  bind(GLFW_KEY_KP_4, kNone, Action::OrbitLeft);
  bind(GLFW_KEY_KP_6, kNone, Action::OrbitRight);
  bind(GLFW_KEY_KP_8, kNone, Action::OrbitUp);
  bind(GLFW_KEY_KP_2, kNone, Action::OrbitDown);
  bind(GLFW_KEY_KP_ADD, kNone, Action::ZoomIn);
  bind(GLFW_KEY_KP_SUBTRACT, kNone, Action::ZoomOut);
  bind(GLFW_KEY_EQUAL, kNone, Action::ZoomIn);
  bind(GLFW_KEY_MINUS, kNone, Action::ZoomOut);
  // Simulation
  bind(GLFW_KEY_SPACE, kNone, Action::PlayPause);
  bind(GLFW_KEY_PERIOD, kNone, Action::StepOnce);
  bind(GLFW_KEY_RIGHT, kNone, Action::StepOnce);
  bind(GLFW_KEY_R, kShift, Action::ResetSimulation);
  bind(GLFW_KEY_R, kNone, Action::ToggleRecord);
  // Display
  bind(GLFW_KEY_Z, kNone, Action::ToggleWireframe);
  bind(GLFW_KEY_Z, kShift, Action::ToggleFlatShading);
  bind(GLFW_KEY_E, kNone, Action::ToggleCellEdges);
  bind(GLFW_KEY_C, kShift, Action::ToggleSlice);
  bind(GLFW_KEY_V, kNone, Action::CycleField);
  bind(GLFW_KEY_D, kNone, Action::CycleDeformation);
  // Edit and brushes
  bind(GLFW_KEY_Z, kCtrl, Action::Undo);
  bind(GLFW_KEY_Z, kCtrl | kShift, Action::Redo);
  bind(GLFW_KEY_Y, kCtrl, Action::RedoAlternative);
  bind(GLFW_KEY_LEFT_BRACKET, kNone, Action::BrushSmaller);
  bind(GLFW_KEY_RIGHT_BRACKET, kNone, Action::BrushLarger);
  // File and window
  bind(GLFW_KEY_O, kCtrl, Action::Open);
  bind(GLFW_KEY_S, kCtrl, Action::Save);
  bind(GLFW_KEY_S, kCtrl | kShift, Action::SaveAs);
  bind(GLFW_KEY_SLASH, kShift, Action::ToggleHelp);  // '?'
  bind(GLFW_KEY_F1, kNone, Action::ToggleHelp);
  bind(GLFW_KEY_F12, kNone, Action::Screenshot);
  bind(GLFW_KEY_Q, kCtrl, Action::Quit);
  return map;
}

std::optional<Action> KeyMap::actionFor(int key, int modifiers) const {
  modifiers = normalizedModifiers(modifiers);
  for (const KeyBinding& b : bindings_)
    if (b.key == key && b.modifiers == modifiers) return b.action;
  return std::nullopt;
}

void KeyMap::bind(int key, int modifiers, Action action) {
  if (!findKey(key))
    throw std::invalid_argument("cannot bind key code " + std::to_string(key) +
                                ": it is not a key the key map knows");
  if (modifiers & ~(kModifierMask | GLFW_MOD_CAPS_LOCK | GLFW_MOD_NUM_LOCK))
    throw std::invalid_argument("unknown modifier bits " + std::to_string(modifiers) +
                                " (use GLFW_MOD_SHIFT, _CONTROL, _ALT, _SUPER)");
  actionInfo(action);  // validates the enum value
  modifiers = normalizedModifiers(modifiers);
  for (KeyBinding& b : bindings_)
    if (b.key == key && b.modifiers == modifiers) {
      b.action = action;
      return;
    }
  bindings_.push_back({key, modifiers, action});
}

bool KeyMap::unbind(int key, int modifiers) {
  modifiers = normalizedModifiers(modifiers);
  const auto it = std::find_if(bindings_.begin(), bindings_.end(), [&](const KeyBinding& b) {
    return b.key == key && b.modifiers == modifiers;
  });
  if (it == bindings_.end()) return false;
  bindings_.erase(it);
  return true;
}

int KeyMap::unbindAction(Action action) {
  return static_cast<int>(
      std::erase_if(bindings_, [action](const KeyBinding& b) { return b.action == action; }));
}

std::vector<KeyBinding> KeyMap::bindingsOf(Action action) const {
  std::vector<KeyBinding> out;
  for (const KeyBinding& b : bindings_)
    if (b.action == action) out.push_back(b);
  return out;
}

std::string KeyMap::toText() const {
  std::string text;
  for (const KeyBinding& b : bindings_)
    text += chordName(b.key, b.modifiers) + " = " + std::string(actionName(b.action)) + "\n";
  return text;
}

KeyMap KeyMap::fromText(std::string_view text, std::string* error) {
  KeyMap map;
  std::string errors;
  std::vector<int> boundOnLine;  // parallel to map.bindings_
  const auto fail = [&](int line, const std::string& message) {
    const std::string sentence = "line " + std::to_string(line) + ": " + message;
    if (!error) throw std::invalid_argument("key map " + sentence);
    errors += (errors.empty() ? "" : "\n") + sentence;
  };
  int lineNumber = 0;
  while (!text.empty()) {
    ++lineNumber;
    const size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    if (const size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;
    const size_t equals = line.find('=');
    if (equals == std::string_view::npos) {
      fail(lineNumber, "expected 'keys = action', e.g. 'Ctrl+Numpad1 = view_back'.");
      continue;
    }
    const std::string_view actionText = trim(line.substr(equals + 1));
    const std::optional<Action> action = actionFromName(actionText);
    if (!action) {
      fail(lineNumber, "unknown action '" + std::string(actionText) + "'.");
      continue;
    }
    // Chord: modifiers and the key joined by '+' (no key token contains '+').
    std::string_view chord = trim(line.substr(0, equals));
    int modifiers = 0;
    std::optional<int> key;
    bool bad = false;
    while (!bad) {
      const size_t plus = chord.find('+');
      const std::string_view part = trim(chord.substr(0, plus));
      if (plus == std::string_view::npos) {
        key = keyFromName(part);
        if (!key) {
          fail(lineNumber, "unknown key '" + std::string(part) + "'.");
          bad = true;
        }
        break;
      }
      const auto modifier =
          std::find_if(kModifiers.begin(), kModifiers.end(),
                       [&](const ModifierInfo& m) { return equalsIgnoreCase(m.name, part); });
      if (modifier == kModifiers.end()) {
        fail(lineNumber,
             "unknown modifier '" + std::string(part) + "' (use Ctrl, Shift, Alt or Super).");
        bad = true;
        break;
      }
      modifiers |= modifier->bit;
      chord.remove_prefix(plus + 1);
    }
    if (bad) continue;
    if (const std::optional<Action> previous = map.actionFor(*key, modifiers)) {
      size_t index = 0;
      while (map.bindings_[index].key != *key || map.bindings_[index].modifiers != modifiers)
        ++index;
      fail(lineNumber, chordName(*key, modifiers) + " is already bound on line " +
                           std::to_string(boundOnLine[index]) + ".");
      continue;
    }
    map.bind(*key, modifiers, *action);
    boundOnLine.push_back(lineNumber);
  }
  if (error) *error = errors;
  return map;
}

// [Camera actions] ----------------------------------------------------------------------------

bool applyCameraAction(Action action, render::Camera& camera) {
  constexpr float kStep = glm::pi<float>() / 12.0f;  // 15 degrees, as Blender's numpad
  switch (action) {
    case Action::ViewFront:
      camera.setStandardView(render::StandardView::Front);
      return true;
    case Action::ViewBack:
      camera.setStandardView(render::StandardView::Back);
      return true;
    case Action::ViewRight:
      camera.setStandardView(render::StandardView::Right);
      return true;
    case Action::ViewLeft:
      camera.setStandardView(render::StandardView::Left);
      return true;
    case Action::ViewTop:
      camera.setStandardView(render::StandardView::Top);
      return true;
    case Action::ViewBottom:
      camera.setStandardView(render::StandardView::Bottom);
      return true;
    case Action::ToggleOrthographic:
      camera.toggleOrthographic();
      return true;
    case Action::OrbitLeft:
      camera.orbitBy(-kStep, 0.0f);
      return true;
    case Action::OrbitRight:
      camera.orbitBy(kStep, 0.0f);
      return true;
    case Action::OrbitUp:
      camera.orbitBy(0.0f, kStep);
      return true;
    case Action::OrbitDown:
      camera.orbitBy(0.0f, -kStep);
      return true;
    case Action::ZoomIn:
      camera.zoom(Navigator::kWheelZoomStep);
      return true;
    case Action::ZoomOut:
      camera.zoom(1.0f / Navigator::kWheelZoomStep);
      return true;
    default:
      return false;
  }
}

// [Navigator] ---------------------------------------------------------------------------------

std::string_view presetName(NavigationPreset preset) {
  return preset == NavigationPreset::Blender ? "Blender" : "Stylus";
}

Gesture Navigator::gestureForPress(int button, const PointerInput& input) const {
  const int mods = normalizedModifiers(input.modifiers);
  const bool shift = mods & GLFW_MOD_SHIFT, ctrl = mods & GLFW_MOD_CONTROL,
             alt = mods & GLFW_MOD_ALT;
  // The middle button of both presets, and Blender's Alt+left emulation of it.
  const auto middle = [&] { return ctrl ? Gesture::Zoom : shift ? Gesture::Pan : Gesture::Orbit; };
  if (button == 1) return middle();
  if (preset_ == NavigationPreset::Blender) {
    if (button == 0) return alt ? middle() : Gesture::Stroke;
    return Gesture::None;  // the right button is left to context menus
  }
  // Stylus
  if (button == 2) return Gesture::Orbit;
  if (alt) return shift ? Gesture::Zoom : Gesture::Pan;  // anywhere, also over the object
  if (input.overObject) return Gesture::Stroke;
  return shift ? Gesture::Zoom : Gesture::Orbit;
}

PointerResult Navigator::update(const PointerInput& input, render::Camera& camera,
                                int viewportWidth, int viewportHeight) {
  if (viewportWidth <= 0 || viewportHeight <= 0)
    throw std::invalid_argument("Navigator::update needs a viewport of positive size");
  PointerResult result;
  const bool down[3] = {input.left, input.middle, input.right};

  // Releasing the drag's button ends the drag.
  if (gesture_ != Gesture::None && !down[dragButton_]) {
    result.strokeEnded = gesture_ == Gesture::Stroke;
    gesture_ = Gesture::None;
    dragButton_ = -1;
  }

  // Continue the drag with this frame's motion.
  const bool moved =
      (input.dx != 0.0f || input.dy != 0.0f) && std::isfinite(input.dx) && std::isfinite(input.dy);
  if (moved && gesture_ == Gesture::Orbit) {
    camera.orbit(input.dx, input.dy);
    result.cameraChanged = true;
  } else if (moved && gesture_ == Gesture::Pan) {
    camera.pan(input.dx, input.dy, viewportHeight);
    result.cameraChanged = true;
  } else if (moved && gesture_ == Gesture::Zoom && input.dy != 0.0f) {
    // Vertical motion only: dragging up (dy < 0) zooms in. The clamp keeps a wild event finite.
    camera.zoom(std::exp(std::clamp(kDragZoomPerPixel * input.dy, -5.0f, 5.0f)));
    result.cameraChanged = true;
  }
  result.strokeActive = gesture_ == Gesture::Stroke;

  // A fresh press starts a drag when none is in progress (middle first, as it never strokes).
  for (int button : {1, 0, 2}) {
    const bool pressed = down[button] && !held_[button];
    if (!pressed || gesture_ != Gesture::None) continue;
    if (input.uiWantsMouse) {
      gesture_ = Gesture::Ignored;  // the press belongs to ImGui until it is released
    } else if (input.doubleClick) {
      result.setPivotRequested = true;
      gesture_ = Gesture::Ignored;  // the second press of a double click starts nothing
    } else {
      gesture_ = gestureForPress(button, input);
    }
    if (gesture_ == Gesture::None) continue;
    dragButton_ = button;
    if (gesture_ == Gesture::Stroke) result.strokeBegan = result.strokeActive = true;
  }

  // The wheel zooms unless the cursor is over the UI.
  if (!input.uiWantsMouse && input.wheel != 0.0f && std::isfinite(input.wheel)) {
    camera.zoom(std::pow(kWheelZoomStep, std::clamp(input.wheel, -20.0f, 20.0f)));
    result.cameraChanged = true;
  }

  std::copy(down, down + 3, held_);
  result.gesture = gesture_;
  return result;
}

}  // namespace sculpt::app
