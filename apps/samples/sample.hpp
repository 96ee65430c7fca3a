// A sample: one program of the book or one engine feature, with its parameters and plots.
//
// The app owns the current sample and drives it every frame:
//   setup()      builds the scene from the sample's parameters (once, and again on reset: R);
//   keys(k)      the keyboard state, once a frame (the book's programs poll keys, e.g. the
//                hovercraft's thrusters);
//   step(dt)     advances the simulation by one fixed step of timeStep() seconds (the app steps
//                as often as the frame's simulated time needs: time scale x 1/60 s a frame);
//   finite()     whether the state is finite (checked after each frame; a NaN fails a headless run);
//   draw(d)      draws the scene through DebugDraw, in metres;
//   ui()         the sample's panel: a control for each parameter (units in the labels) and live
//                plots of what matters (energy, speed, error against the closed form).
// Mouse input arrives in world coordinates (m).
//
// Samples register themselves: a file defines its class and a static SampleRegistrar
// {"Category", "Name", "what it shows", factory}. The registry lists them sorted by category and
// name; `impetus-samples --list` prints them.
#pragma once

#include "camera.hpp"
#include "draw.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impetus::samples {

/// The keys samples may use, held down this frame (arrows and a few letters, as in the book).
struct KeyState {
  bool up = false;
  bool down = false;
  bool left = false;
  bool right = false;
  bool space = false;
  bool a = false;
  bool d = false;
  bool s = false;
  bool w = false;
};

enum class MouseButton { left, middle };

class Sample {
public:
  Sample() = default;
  virtual ~Sample() = default;
  Sample(const Sample&) = delete;
  Sample& operator=(const Sample&) = delete;

  /// Builds (or rebuilds) the scene from the current parameters.
  virtual void setup() = 0;
  /// One fixed step of timeStep() seconds.
  virtual void step(float dt) = 0;
  virtual void draw(DebugDraw& draw) = 0;
  /// The sample's panel: parameters and plots. Changing a parameter that needs a new scene
  /// calls setup() itself (or says "press R").
  virtual void ui() {}
  /// Whether every number of the state is finite.
  [[nodiscard]] virtual bool finite() const = 0;

  /// The fixed step, s (1/60 unless the model needs smaller steps).
  [[nodiscard]] virtual float timeStep() const { return 1.0f / 60.0f; }
  /// Where the camera starts.
  [[nodiscard]] virtual CameraView initialView() const { return {}; }
  /// One sentence on the state now, printed at the end of a headless run (bodies, energy...).
  [[nodiscard]] virtual std::string summary() const { return {}; }
  /// One line on the keys and mouse, shown in the panel ("" when only the common controls apply).
  [[nodiscard]] virtual std::string_view controls() const { return {}; }

  virtual void keys(const KeyState& /*keys*/) {}
  /// True when the sample takes the press (so the app does not pan).
  virtual bool mouseDown(const Vec2f& /*world*/, MouseButton /*button*/) { return false; }
  virtual void mouseMove(const Vec2f& /*world*/) {}
  virtual void mouseUp(const Vec2f& /*world*/, MouseButton /*button*/) {}
};

using SampleFactory = std::function<std::unique_ptr<Sample>()>;

struct SampleInfo {
  std::string category;
  std::string name;
  std::string description; ///< one sentence: what it shows
  SampleFactory create;

  /// "Category/Name": how the command line names it.
  [[nodiscard]] std::string fullName() const { return category + "/" + name; }
};

/// Every registered sample, sorted by category, then name.
[[nodiscard]] const std::vector<SampleInfo>& sampleRegistry();
/// The index of the sample called "Category/Name", if any.
[[nodiscard]] std::optional<std::size_t> findSample(std::string_view fullName);

/// Registers a sample at static initialisation: `static const SampleRegistrar r{...};`.
struct SampleRegistrar {
  SampleRegistrar(std::string category, std::string name, std::string description, SampleFactory create);
};

} // namespace impetus::samples
