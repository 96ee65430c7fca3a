#include "app.hpp"

#include "camera.hpp"
#include "display.hpp"
#include "draw_batch.hpp"
#include "gl_renderer.hpp"
#include "sample.hpp"
#include "screenshot.hpp"
#include "ui.hpp"

#include <SDL.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>
#include <imgui_internal.h> // ErrorCheckEndFrameRecover: close what a throwing panel left open

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace impetus::samples {
namespace {

constexpr float frameTime = 1.0f / 60.0f; ///< s of simulation per frame at time scale 1, headless
constexpr int maxStepsPerFrame = 64;      ///< so a slow sample slows down instead of spiralling

/// A sample that threw or went non-finite.
class SampleFailure : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Creates and destroys the Dear ImGui context (before and after everything that uses it).
struct ImGuiContextOwner {
  ImGuiContextOwner() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // the layout is fixed by the app: no imgui.ini in the working directory
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
  }
  ~ImGuiContextOwner() { ImGui::DestroyContext(); }
  ImGuiContextOwner(const ImGuiContextOwner&) = delete;
  ImGuiContextOwner& operator=(const ImGuiContextOwner&) = delete;
};

ImU32 toImGui(const Color& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a)); }

/// Grid spacing of 1, 2 or 5 times a power of ten, at least `minPixels` apart on screen.
float gridSpacing(float pixelSize, float minPixels) {
  const float target = pixelSize * minPixels;
  const float decade = std::pow(10.0f, std::floor(std::log10(target)));
  for (const float f : {1.0f, 2.0f, 5.0f, 10.0f}) {
    if (f * decade >= target) {
      return f * decade;
    }
  }
  return 10.0f * decade;
}

/// Puts the next button on this line if a button labelled `label` fits there, else on the next.
void sameLineIfFits(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float buttonWidth = ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x;
  const float lineEnd = ImGui::GetItemRectMax().x + style.ItemSpacing.x + buttonWidth;
  if (lineEnd <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) {
    ImGui::SameLine();
  }
}

class App {
public:
  App(const AppOptions& options, std::size_t sampleIndex) : options_(options) {
    if (!options.noRender) {
      display_ = std::make_unique<Display>("Impetus samples", options.width, options.height, options.headless());
      renderer_ = std::make_unique<GlRenderer>();
      loadFont(display_->uiScale());
    } else {
      loadFont(1.0f);
      // No backends: ImGui still lays the panels out (exercising every sample's ui()), it just
      // never draws them. Its font atlas must be built for that.
      ImGuiIO& io = ImGui::GetIO();
      unsigned char* pixels = nullptr;
      int w = 0;
      int h = 0;
      io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
      io.DisplaySize = ImVec2(static_cast<float>(options.width), static_cast<float>(options.height));
    }
    select(sampleIndex);
    applyPending();
  }

  int run();

private:
  void select(std::size_t index) { pendingSelect_ = index; }
  void reset() { pendingReset_ = true; }
  /// Switches sample or resets between frames (never inside a panel): setup() may throw.
  void applyPending();
  void processEvents();
  void handleKey(SDL_Keycode key);
  void beginFrame(float dt);
  void layout();
  void simulate(float dt);
  void samplesPanel();
  void samplePanel();
  void measureOverflow();
  void drawScene();
  void render();
  void screenshot(const std::filesystem::path& path);
  [[nodiscard]] std::string name() const { return sampleRegistry()[index_].fullName(); }

  AppOptions options_;
  std::unique_ptr<Display> display_;     // null without rendering
  std::unique_ptr<GlRenderer> renderer_; // destroyed before the display's GL context
  std::size_t index_ = 0;
  std::unique_ptr<Sample> sample_;
  Camera camera_;
  DrawBatch batch_;
  bool fitView_ = true; // follow the sample's view until the user pans or zooms
  bool paused_ = false;
  bool singleStep_ = false;
  float timeScale_ = 1.0f;
  float accumulator_ = 0.0f;
  double simulatedTime_ = 0.0;
  long steps_ = 0;
  bool quit_ = false;
  bool leftCollapsed_ = false;
  float leftWidth_ = 0.0f;
  float rightWidth_ = 0.0f;
  std::string problem_; // interactive: why the sample stopped (exception, NaN)
  bool panning_ = false;
  int screenshotCount_ = 0;
  int frame_ = 0;
  float panelOverflow_ = 0.0f; // px: how far the widest panel line ran past its panel's edge
  std::string overflowingPanel_;
  std::optional<std::size_t> pendingSelect_;
  bool pendingReset_ = false;
};

void App::applyPending() {
  if (!pendingSelect_ && !pendingReset_) {
    return;
  }
  try {
    if (pendingSelect_) {
      index_ = *pendingSelect_;
      sample_ = sampleRegistry()[index_].create();
      fitView_ = true;
    }
    pendingSelect_.reset();
    pendingReset_ = false;
    accumulator_ = 0.0f;
    simulatedTime_ = 0.0;
    steps_ = 0;
    problem_.clear();
    sample_->setup();
  } catch (const std::exception& e) {
    throw SampleFailure(std::string("setup threw: ") + e.what());
  }
}

void App::handleKey(SDL_Keycode key) {
  switch (key) {
  case SDLK_p:
    paused_ = !paused_;
    break;
  case SDLK_o:
    paused_ = true;
    singleStep_ = true;
    break;
  case SDLK_r:
    reset();
    break;
  case SDLK_F12:
    screenshot("impetus-samples-" + std::to_string(++screenshotCount_) + ".png");
    break;
  case SDLK_ESCAPE:
    quit_ = true;
    break;
  default:
    break;
  }
}

void App::processEvents() {
  if (!display_) {
    return;
  }
  SDL_Event event;
  const ImGuiIO& io = ImGui::GetIO();
  while (SDL_PollEvent(&event) != 0) {
    ImGui_ImplSDL2_ProcessEvent(&event);
    switch (event.type) {
    case SDL_QUIT:
      quit_ = true;
      break;
    case SDL_KEYDOWN:
      if (!io.WantCaptureKeyboard && event.key.repeat == 0) {
        handleKey(event.key.keysym.sym);
      }
      break;
    case SDL_MOUSEBUTTONDOWN: {
      if (io.WantCaptureMouse) {
        break;
      }
      const Vec2f screen{static_cast<float>(event.button.x), static_cast<float>(event.button.y)};
      if (event.button.button == SDL_BUTTON_RIGHT) {
        panning_ = true;
        fitView_ = false;
      } else if (event.button.button == SDL_BUTTON_LEFT || event.button.button == SDL_BUTTON_MIDDLE) {
        sample_->mouseDown(camera_.screenToWorld(screen),
                           event.button.button == SDL_BUTTON_LEFT ? MouseButton::left : MouseButton::middle);
      }
      break;
    }
    case SDL_MOUSEBUTTONUP: {
      const Vec2f screen{static_cast<float>(event.button.x), static_cast<float>(event.button.y)};
      if (event.button.button == SDL_BUTTON_RIGHT) {
        panning_ = false;
      } else if (event.button.button == SDL_BUTTON_LEFT || event.button.button == SDL_BUTTON_MIDDLE) {
        sample_->mouseUp(camera_.screenToWorld(screen),
                         event.button.button == SDL_BUTTON_LEFT ? MouseButton::left : MouseButton::middle);
      }
      break;
    }
    case SDL_MOUSEMOTION: {
      const Vec2f screen{static_cast<float>(event.motion.x), static_cast<float>(event.motion.y)};
      if (panning_) {
        camera_.pan({static_cast<float>(event.motion.xrel), static_cast<float>(event.motion.yrel)});
      }
      sample_->mouseMove(camera_.screenToWorld(screen));
      break;
    }
    case SDL_MOUSEWHEEL: {
      if (io.WantCaptureMouse || event.wheel.y == 0) {
        break;
      }
      int x = 0;
      int y = 0;
      SDL_GetMouseState(&x, &y);
      camera_.zoomAt({static_cast<float>(x), static_cast<float>(y)},
                     std::pow(1.15f, static_cast<float>(event.wheel.y)));
      fitView_ = false;
      break;
    }
    default:
      break;
    }
  }
}

void App::beginFrame(float dt) {
  if (display_) {
    display_->newFrame();
  }
  ImGuiIO& io = ImGui::GetIO();
  if (options_.headless()) {
    // The same frame every run: a fixed clock and no pointer (the screenshot must not depend on
    // where the mouse happens to be or how fast the machine is).
    io.DeltaTime = dt;
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
  }
  ImGui::NewFrame();
}

void App::layout() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const float w = size.x;
  const float h = size.y;
  if (options_.hideUi) {
    leftWidth_ = rightWidth_ = 0.0f;
  } else {
    // The panels grow with the font up to a share of the window; the scene keeps the rest.
    // The samples list is as wide as its longest name needs, up to 30% of the window.
    const ImGuiStyle& style = ImGui::GetStyle();
    float widest = ImGui::CalcTextSize("pause (P)  step (O)").x;
    for (const SampleInfo& info : sampleRegistry()) {
      widest = std::max(widest, ImGui::CalcTextSize(info.name.c_str()).x);
    }
    const float needed = widest + 2.0f * style.WindowPadding.x + style.ScrollbarSize + style.ItemSpacing.x;
    leftWidth_ = std::clamp(needed, 120.0f, 0.3f * w);
    const float em = ImGui::GetFontSize() / panelFontPixels;
    rightWidth_ = std::clamp(0.36f * w, 120.0f, 400.0f * em);
  }
  const float left = leftCollapsed_ ? 0.0f : leftWidth_;
  camera_.setViewport(static_cast<int>(left), 0, static_cast<int>(w - left - rightWidth_), static_cast<int>(h));
  if (fitView_) {
    camera_.setView(sample_->initialView());
  }
}

void App::simulate(float dt) {
  if (!problem_.empty()) {
    return;
  }
  const float step = sample_->timeStep();
  int todo = 0;
  if (singleStep_) {
    todo = 1;
    singleStep_ = false;
  } else if (!paused_) {
    accumulator_ += dt * timeScale_;
    todo = static_cast<int>(std::floor(accumulator_ / step + 1e-4f));
    todo = std::min(todo, maxStepsPerFrame);
    accumulator_ = std::max(0.0f, accumulator_ - static_cast<float>(todo) * step);
  }
  for (int i = 0; i < todo; ++i) {
    try {
      sample_->step(step);
    } catch (const std::exception& e) {
      throw SampleFailure(std::string("threw: ") + e.what());
    }
    simulatedTime_ += step;
    ++steps_;
  }
  if (!sample_->finite()) {
    throw SampleFailure("its state is not finite (NaN or infinity) after " + std::to_string(steps_) + " steps");
  }
}

void App::samplesPanel() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(leftWidth_, size.y), ImGuiCond_Always);
  // Below the smallest window the panels are laid out for (800 x 450), the list starts collapsed
  // so that the scene and the sample's panel keep the room.
  constexpr float smallestLaidOutWidth = 800.0f; // px
  ImGui::SetNextWindowCollapsed(size.x < smallestLaidOutWidth, ImGuiCond_Once);
  const bool open = ImGui::Begin("Samples", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  leftCollapsed_ = ImGui::IsWindowCollapsed();
  if (open) {
    ImGui::Checkbox("pause (P)", &paused_);
    sameLineIfFits("step (O)");
    if (ImGui::Button("step (O)")) {
      paused_ = true;
      singleStep_ = true;
    }
    sameLineIfFits("reset (R)");
    if (ImGui::Button("reset (R)")) {
      reset();
    }
    sameLineIfFits("view");
    if (ImGui::Button("view")) {
      fitView_ = true;
    }
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::SliderFloat("##timescale", &timeScale_, 0.05f, 4.0f, "time scale %.2fx", ImGuiSliderFlags_Logarithmic);
    textWrapped("t = %.2f s, %ld steps of %.1f ms", simulatedTime_, steps_,
                static_cast<double>(sample_->timeStep() * 1000.0f));
    ImGui::Separator();
    const auto& registry = sampleRegistry();
    std::string category;
    bool categoryOpen = false;
    for (std::size_t i = 0; i < registry.size(); ++i) {
      if (registry[i].category != category) {
        category = registry[i].category;
        ImGui::SetNextItemOpen(true, ImGuiCond_Once);
        categoryOpen = ImGui::CollapsingHeader(category.c_str()); // no indent: the names keep the width
      }
      if (categoryOpen && ImGui::Selectable(registry[i].name.c_str(), i == index_)) {
        if (i != index_) {
          select(i);
        }
      }
      if (categoryOpen && ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s", registry[i].description.c_str());
      }
    }
    measureOverflow();
  }
  ImGui::End();
}

void App::samplePanel() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x - rightWidth_, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(rightWidth_, size.y), ImGuiCond_Always);
  const SampleInfo& info = sampleRegistry()[index_];
  if (ImGui::Begin(info.fullName().c_str(), nullptr,
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse)) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(info.description.c_str());
    if (!sample_->controls().empty()) {
      ImGui::TextColored(ImVec4(0.6f, 0.8f, 1.0f, 1.0f), "%.*s", static_cast<int>(sample_->controls().size()),
                         sample_->controls().data());
    }
    if (!problem_.empty()) {
      ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "Stopped: %s. Press R to reset.", problem_.c_str());
    }
    ImGui::PopTextWrapPos();
    ImGui::Separator();
    ImGui::PushItemWidth(-FLT_MIN);
    try {
      sample_->ui();
    } catch (const std::exception& e) {
      throw SampleFailure(std::string("its panel threw: ") + e.what());
    }
    ImGui::PopItemWidth();
    measureOverflow();
  }
  ImGui::End();
}

void App::measureOverflow() {
  constexpr int settleFrames = 2; // ImGui sizes a window's scroll bar from the frame before
  if (frame_ < settleFrames) {
    return;
  }
  const ImGuiWindow* window = ImGui::GetCurrentWindow();
  const float overflow = window->DC.CursorMaxPos.x - window->WorkRect.Max.x;
  if (overflow > panelOverflow_) {
    panelOverflow_ = overflow;
    overflowingPanel_ = window->Name;
  }
}

void App::drawScene() {
  batch_.begin(camera_.pixelSize());
  const auto [lower, upper] = camera_.visibleBox();
  batch_.grid(lower, upper, gridSpacing(camera_.pixelSize(), 48.0f), palette::grid);
  if (problem_.empty()) { // a failed sample's state is not drawn again
    try {
      sample_->draw(batch_);
    } catch (const std::exception& e) {
      throw SampleFailure(std::string("its drawing threw: ") + e.what());
    }
    if (!batch_.finite()) {
      throw SampleFailure("it drew a point that is not finite (NaN or infinity)");
    }
  }
  // Labels go through ImGui's background list: under the panels, over the scene.
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const auto x0 = static_cast<float>(camera_.x());
  list->PushClipRect(ImVec2(x0, 0.0f),
                     ImVec2(x0 + static_cast<float>(camera_.width()), static_cast<float>(camera_.height())));
  for (const DrawLabel& label : batch_.labels()) {
    const Vec2f p = camera_.worldToScreen(label.position);
    list->AddText(ImVec2(std::round(p.x), std::round(p.y)), toImGui(label.color), label.text.c_str());
  }
  list->PopClipRect();
}

void App::render() {
  ImGui::Render();
  if (!display_) {
    return;
  }
  const auto [dw, dh] = display_->drawableSize();
  const auto [ww, wh] = display_->windowSize();
  const float scale = ww > 0 ? static_cast<float>(dw) / static_cast<float>(ww) : 1.0f;
  glViewport(0, 0, dw, dh);
  glClearColor(palette::background.r, palette::background.g, palette::background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  renderer_->render(batch_, camera_, scale, dh);
  glViewport(0, 0, dw, dh);
  display_->renderUi();
}

void App::screenshot(const std::filesystem::path& path) {
  if (!display_) {
    return;
  }
  const auto [dw, dh] = display_->drawableSize();
  saveScreenshot(path, dw, dh);
  std::printf("impetus-samples: wrote %s (%d x %d)\n", path.c_str(), dw, dh);
}

int App::run() {
  using clock = std::chrono::steady_clock;
  auto last = clock::now();
  while (!quit_ && (!options_.frames || frame_ < *options_.frames)) {
    float dt = frameTime;
    if (!options_.headless()) {
      const auto now = clock::now();
      dt = std::min(std::chrono::duration<float>(now - last).count(), 0.1f); // a stall is not a leap
      last = now;
    }
    processEvents();
    if (display_ && !options_.headless() && !paused_ && problem_.empty()) {
      // The book's programs poll the keyboard every frame.
      const Uint8* state = SDL_GetKeyboardState(nullptr);
      KeyState keys;
      if (!ImGui::GetIO().WantCaptureKeyboard) {
        keys = {state[SDL_SCANCODE_UP] != 0,    state[SDL_SCANCODE_DOWN] != 0,  state[SDL_SCANCODE_LEFT] != 0,
                state[SDL_SCANCODE_RIGHT] != 0, state[SDL_SCANCODE_SPACE] != 0, state[SDL_SCANCODE_A] != 0,
                state[SDL_SCANCODE_D] != 0,     state[SDL_SCANCODE_S] != 0,     state[SDL_SCANCODE_W] != 0};
      }
      sample_->keys(keys);
    }
    beginFrame(dt);
    try {
      applyPending();
      layout();
      simulate(dt);
      if (!options_.hideUi) {
        samplesPanel();
        samplePanel();
      }
      drawScene();
    } catch (const SampleFailure& e) {
      const std::string message = "sample '" + name() + "' " + e.what() + " (frame " + std::to_string(frame_ + 1) + ")";
      ImGui::ErrorCheckEndFrameRecover(nullptr);
      ImGui::EndFrame();
      std::fprintf(stderr, "impetus-samples: %s\n", message.c_str());
      if (options_.headless()) {
        return 1;
      }
      problem_ = e.what();
      paused_ = true;
      continue;
    }
    render();
    ++frame_;
    if (options_.screenshot && options_.frames && frame_ == *options_.frames) {
      screenshot(*options_.screenshot);
    }
    if (display_) {
      display_->swap();
    }
  }
  if (options_.headless()) {
    std::printf("impetus-samples: %s: %d frames, %ld steps, %.3f s simulated, state finite\n", name().c_str(), frame_,
                steps_, simulatedTime_);
    constexpr float overflowTolerance = 1.0f; // px: rounding of item widths
    if (panelOverflow_ > overflowTolerance) {
      std::printf("impetus-samples: %s: panel text runs %.0f px past the edge of the panel %s\n", name().c_str(),
                  static_cast<double>(panelOverflow_), overflowingPanel_.c_str());
    } else {
      std::printf("impetus-samples: %s: panels fit\n", name().c_str());
    }
    if (const std::string summary = sample_->summary(); !summary.empty()) {
      std::printf("impetus-samples: %s: %s\n", name().c_str(), summary.c_str());
    }
  }
  return 0;
}

} // namespace

int runApp(const AppOptions& options, std::size_t sampleIndex) {
  try {
    const ImGuiContextOwner imgui;
    App app(options, sampleIndex);
    return app.run();
  } catch (const SampleFailure& e) {
    std::fprintf(stderr, "impetus-samples: sample '%s' %s\n", sampleRegistry()[sampleIndex].fullName().c_str(),
                 e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "impetus-samples: %s\n", e.what());
    return 1;
  }
}

} // namespace impetus::samples
