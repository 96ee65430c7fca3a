// The app's window and its OpenGL 3.3 core context, with Dear ImGui's SDL2 and OpenGL3 backends.
//
// Headless (a screenshot run), it asks SDL for its "offscreen" video driver, which makes the GL
// context through EGL on Mesa's software rasteriser (llvmpipe): no X server, no GPU. When that
// fails and a display is available ($DISPLAY or $WAYLAND_DISPLAY, e.g. under `xvfb-run -a`), it
// falls back to SDL's default driver with a hidden window. Setting SDL_VIDEODRIVER yourself
// overrides the choice.
#pragma once

#include <array>
#include <string>

struct SDL_Window;

namespace impetus::samples {

class Display {
public:
  /// Opens it; the Dear ImGui context must exist. Throws std::runtime_error saying what failed
  /// and what to try.
  Display(const std::string& title, int width, int height, bool headless);
  ~Display();
  Display(const Display&) = delete;
  Display& operator=(const Display&) = delete;

  /// The backends' part of ImGui's new frame.
  void newFrame();
  /// Draws ImGui's draw data for this frame.
  void renderUi();
  void swap();

  /// Window size in screen units (what mouse events and ImGui use) and in framebuffer pixels.
  [[nodiscard]] std::array<int, 2> windowSize() const;
  [[nodiscard]] std::array<int, 2> drawableSize() const;
  /// How much larger than a 96-dpi screen the window's display draws a point: the display's
  /// horizontal dpi over 96, at least 1 (1 when SDL cannot tell, and always 1 headless so
  /// pictures do not depend on the machine).
  [[nodiscard]] float uiScale() const;
  /// The SDL video driver in use ("offscreen", "x11", "wayland").
  [[nodiscard]] std::string driver() const;

private:
  void close() noexcept;

  SDL_Window* window_ = nullptr; // owned: SDL's handle, destroyed in the destructor
  void* context_ = nullptr;      // owned: SDL_GLContext
  bool sdlInitialised_ = false;
  bool imguiSdl_ = false;
  bool imguiGl_ = false;
  bool headless_ = false;
};

} // namespace impetus::samples
