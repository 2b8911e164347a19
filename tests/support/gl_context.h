#pragma once
// GUI tests: a hidden GLFW window with an OpenGL 3.3 core context for each test (the same
// context the window asks for), and a headless Dear ImGui context for panel tests.

#include <gtest/gtest.h>

#include <cstdlib>

#include "render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace sculpt::testing {

/// A hidden window with a current OpenGL 3.3 core context (glfwInit must have succeeded);
/// null when it cannot be created.
inline GLFWwindow* hiddenGlWindow(int width, int height) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(width, height, "sculpt gui test", nullptr, nullptr);
  if (window) glfwMakeContextCurrent(window);
  return window;
}

/// Fixture: a current OpenGL 3.3 core context on a hidden 64x64 window (needs an X display; the
/// GUI tests run under xvfb-run).
class GlContextTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NE(std::getenv("DISPLAY"), nullptr)
        << "no X display: run the GUI tests under xvfb-run (scripts/test.sh does)";
    const char* why = nullptr;
    ASSERT_TRUE(glfwInit()) << (glfwGetError(&why), why ? why : "glfwInit failed");
    window_ = hiddenGlWindow(64, 64);
    ASSERT_NE(window_, nullptr);
  }
  void TearDown() override {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
  }
  GLFWwindow* window_ = nullptr;
};

/// Fixture: an ImGui context with a 1280x800 display and a built font atlas, no window or GL
/// (frames are built and rendered to draw lists only).
class ImGuiContextTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1280.0f, 800.0f);
    io.DeltaTime = 1.0f / 60.0f;
    io.IniFilename = nullptr;
    io.Fonts->Build();
  }
  void TearDown() override { ImGui::DestroyContext(); }
};

}  // namespace sculpt::testing
