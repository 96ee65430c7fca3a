#include "display.hpp"

#include <SDL.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace impetus::samples {
namespace {

bool hasDisplay() { return std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr; }

/// Opens SDL video, a window and a GL 3.3 core context; the error text when it cannot.
std::string open(const std::string& title, int width, int height, bool hidden, SDL_Window*& window, void*& context) {
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    return std::string("SDL_Init: ") + SDL_GetError();
  }
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
  SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 8);
  Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_ALLOW_HIGHDPI;
  flags |= hidden ? SDL_WINDOW_HIDDEN : SDL_WINDOW_RESIZABLE;
  window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, flags);
  if (window == nullptr) {
    const std::string error = std::string("SDL_CreateWindow: ") + SDL_GetError();
    SDL_Quit();
    return error;
  }
  context = SDL_GL_CreateContext(window);
  if (context == nullptr) {
    const std::string error = std::string("OpenGL 3.3 core context: ") + SDL_GetError();
    SDL_DestroyWindow(window);
    window = nullptr;
    SDL_Quit();
    return error;
  }
  return {};
}

} // namespace

Display::Display(const std::string& title, int width, int height, bool headless) : headless_(headless) {
  const bool userDriver = std::getenv("SDL_VIDEODRIVER") != nullptr;
  std::string error;
  if (headless && !userDriver) {
    SDL_SetHint(SDL_HINT_VIDEODRIVER, "offscreen");
    error = open(title, width, height, true, window_, context_);
    if (!error.empty() && hasDisplay()) {
      SDL_SetHint(SDL_HINT_VIDEODRIVER, "");
      const std::string offscreenError = error;
      error = open(title, width, height, true, window_, context_);
      if (!error.empty()) {
        error = "offscreen driver: " + offscreenError + "; display: " + error;
      }
    }
    if (!error.empty()) {
      throw std::runtime_error(
          "cannot render without a display: " + error +
          ". The headless mode needs SDL's offscreen driver with EGL and Mesa's software OpenGL (Debian: "
          "libegl-mesa0 libgl1-mesa-dri), or an X server: xvfb-run -a impetus-samples ...");
    }
  } else {
    error = open(title, width, height, headless, window_, context_);
    if (!error.empty()) {
      throw std::runtime_error("cannot open the window: " + error +
                               (hasDisplay() ? std::string()
                                             : std::string(" (no $DISPLAY or $WAYLAND_DISPLAY: for pictures without "
                                                           "a display, use --screenshot)")));
    }
  }
  sdlInitialised_ = true;
  try {
    SDL_GL_MakeCurrent(window_, context_);
    SDL_GL_SetSwapInterval(headless ? 0 : 1); // vsync when someone watches
    if (!ImGui_ImplSDL2_InitForOpenGL(window_, context_)) {
      throw std::runtime_error("Dear ImGui's SDL2 backend did not start");
    }
    imguiSdl_ = true;
    if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
      throw std::runtime_error("Dear ImGui's OpenGL3 backend did not start");
    }
    imguiGl_ = true;
  } catch (...) {
    close();
    throw;
  }
}

Display::~Display() { close(); }

void Display::close() noexcept {
  if (imguiGl_) {
    ImGui_ImplOpenGL3_Shutdown();
  }
  if (imguiSdl_) {
    ImGui_ImplSDL2_Shutdown();
  }
  if (context_ != nullptr) {
    SDL_GL_DeleteContext(context_);
  }
  if (window_ != nullptr) {
    SDL_DestroyWindow(window_);
  }
  if (sdlInitialised_) {
    SDL_Quit();
  }
  imguiGl_ = imguiSdl_ = sdlInitialised_ = false;
  context_ = nullptr;
  window_ = nullptr;
}

void Display::newFrame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplSDL2_NewFrame();
}

void Display::renderUi() { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }

void Display::swap() { SDL_GL_SwapWindow(window_); }

std::array<int, 2> Display::windowSize() const {
  std::array<int, 2> size{};
  SDL_GetWindowSize(window_, &size[0], &size[1]);
  return size;
}

std::array<int, 2> Display::drawableSize() const {
  std::array<int, 2> size{};
  SDL_GL_GetDrawableSize(window_, &size[0], &size[1]);
  return size;
}

float Display::uiScale() const {
  constexpr float referenceDpi = 96.0f; // the dpi at which ImGui's sizes are one pixel per unit
  constexpr float maxScale = 4.0f;      // beyond any real screen: a display reporting nonsense
  float diagonal = 0.0f;
  float horizontal = 0.0f;
  float vertical = 0.0f;
  if (headless_ || SDL_GetDisplayDPI(SDL_GetWindowDisplayIndex(window_), &diagonal, &horizontal, &vertical) != 0 ||
      !(horizontal > 0.0f)) {
    return 1.0f;
  }
  return std::clamp(horizontal / referenceDpi, 1.0f, maxScale);
}

std::string Display::driver() const {
  const char* name = SDL_GetCurrentVideoDriver();
  return name != nullptr ? name : "";
}

} // namespace impetus::samples
