// Pressure-sensitive (analog) buttons and button mashing (ch. 23).
//
// Sony's analog button is a conductive rubber dome over a fixed contact: the harder it is
// pressed, the flatter the dome, the larger the contact area, the higher the conductance and the
// current. The depression fraction s = I / I_max in [0, 1] is sent as 8 bits, 0-255. Games map it
// to zones (the book's example: raise the weapon, shoulder it, fire; its bounds 0-127, 127-250,
// 250-255 overlap at 127 and 250, so here they are half-open: [0, 127), [127, 250), [250, 255])
// or to a continuous control (throttle = s x maximum thrust).
//
// Force and pressure: the dome is a spring, so the finger's force is about F = k s d (stiffness
// k, full travel d), and the fingertip feels the pressure P = F / A over its contact area A
// (about 1 cm^2 for a thumb on a button).
//
// Mashing: pressing a button as fast as possible. A press is counted when s rises through the
// press level after having fallen below the (lower) release level: the gap between the levels
// (hysteresis) keeps the jitter of a half-pressed button from counting as many presses. The rate
// is the presses in a sliding window over the window's length (Hz).
#pragma once

#include <deque>
#include <span>
#include <string_view>

namespace impetus::sensors {

/// s = raw / 255 for an 8-bit reading raw in [0, 255] (field "raw").
[[nodiscard]] double buttonDepression(int raw);

/// s = I / I_max (I_max > 0, 0 <= I <= I_max; fields "current", "maxCurrent").
[[nodiscard]] double depressionFromCurrent(double current, double maxCurrent);

struct ButtonZone {
  std::string_view name;
  int lower = 0; ///< first raw value in the zone
  int upper = 0; ///< first raw value past it (256 for the last zone)
};

/// The book's three zones, half-open: raise [0, 127), shoulder [127, 250), fire [250, 256).
[[nodiscard]] std::span<const ButtonZone> bookButtonZones() noexcept;

/// The zone holding `raw` (0-255), or "" when none does. Throws impetus::Error (field "raw").
[[nodiscard]] std::string_view buttonZone(int raw, std::span<const ButtonZone> zones = bookButtonZones());

/// The dome as a spring: stiffness k (N/m), full travel d (m) and the finger's contact area A (m^2).
struct ButtonDome {
  double stiffness = 2000.0;   ///< N/m: 2 N at 1 mm, a typical game-pad button
  double travel = 1.0e-3;      ///< m
  double contactArea = 1.0e-4; ///< m^2 (1 cm^2)

  /// F = k s d, N, for s in [0, 1] (field "depression").
  [[nodiscard]] double force(double depression) const;
  /// P = F / A, Pa.
  [[nodiscard]] double fingertipPressure(double depression) const;
};

class ButtonMash {
public:
  /// window > 0 s; 0 <= releaseLevel < pressLevel <= 1. Throws impetus::Error naming the field.
  explicit ButtonMash(double window = 1.0, double pressLevel = 0.6, double releaseLevel = 0.4);

  /// One sample of the depression s (in [0, 1]) at `time` (s, non-decreasing). Returns true when
  /// it completes a press.
  bool update(double time, double depression);

  /// Presses per second over the last window (up to the latest sample's time).
  [[nodiscard]] double rate() const noexcept;
  /// Every press so far.
  [[nodiscard]] int presses() const noexcept { return total_; }
  /// The mean of the deepest s of each press in the window (0 when none): how hard the mashing is.
  [[nodiscard]] double meanPeakDepression() const noexcept;

private:
  struct Press {
    double time;
    double peak;
  };
  double window_;
  double pressLevel_;
  double releaseLevel_;
  bool down_ = false;
  double lastTime_ = -1.0e300;
  double now_ = 0.0;
  int total_ = 0;
  std::deque<Press> recent_;
  void forget() noexcept;
};

} // namespace impetus::sensors
