// Shortcuts go to the 3D view whenever no text is being typed: while a text field is being
// edited its keys are its own, even with the pointer over the view, and once it is left the
// view's shortcuts act again. File > Open's dialog takes the keyboard as it opens.

#include <gtest/gtest.h>

#include "sculpt/sculpt_app.h"
#include "gui/sculpt_session.h"

namespace sculpt::app {
namespace {

TEST_F(SculptSession, ShortcutsActOverTheViewUnlessATextFieldIsBeingEdited) {
  open();
  frames(3);
  const ViewRect view = app_->viewRect();
  const ImVec2 middle(0.5f * (view.min.x + view.max.x), 0.5f * (view.min.y + view.max.y));
  const bool wireframe = app_->model().display.wireframe;

  // Z over the view toggles the wireframe.
  pointer_.x = middle.x, pointer_.y = middle.y;
  frames(1);
  press(GLFW_KEY_Z, false);
  EXPECT_NE(app_->model().display.wireframe, wireframe);

  // A click into the Scene panel's path field (right panel, first text field): Z types there.
  const ImVec2 field(view.max.x + 0.3f * (1280.0f - view.max.x), view.min.y + 90.0f);
  drag(field, 0, 0, 1);
  release();
  ASSERT_TRUE(ImGui::GetIO().WantTextInput) << "no text field at " << field.x << ", " << field.y;
  pointer_.x = middle.x, pointer_.y = middle.y;
  frames(1);
  press(GLFW_KEY_Z, false);
  EXPECT_NE(app_->model().display.wireframe, wireframe) << "Z went to the view while typing";

  // A click on the view's empty background leaves the field; Z over the view acts again.
  drag(ImVec2(view.min.x + 10.0f, view.min.y + 10.0f), 0, 0, 1);
  release();
  frames(1);
  ASSERT_FALSE(ImGui::GetIO().WantTextInput);
  pointer_.x = middle.x, pointer_.y = middle.y;
  frames(1);
  press(GLFW_KEY_Z, false);
  EXPECT_EQ(app_->model().display.wireframe, wireframe);
}

TEST_F(SculptSession, FileOpenFocusesItsPathField) {
  open();
  frames(3);
  ASSERT_FALSE(ImGui::GetIO().WantTextInput);
  press(GLFW_KEY_O, true);  // Ctrl+O
  frames(2);
  // The dialog's field has the keyboard: typed text goes there, not to the Scene panel's field.
  EXPECT_TRUE(ImGui::GetIO().WantTextInput);
  press(GLFW_KEY_Z, false);
  EXPECT_FALSE(app_->model().display.wireframe) << "Z reached the view with the dialog open";
}

}  // namespace
}  // namespace sculpt::app
