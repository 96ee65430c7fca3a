// Touch gestures (ch. 20): tap, drag, pinch and rotate from tracked touches, with thresholds.
//
// A gesture is a pattern in the touches' tracks (touch_tracker.hpp), told apart by thresholds so
// that the jitter of a resting finger does not start one:
// - tap: one finger down and up within `tapMaxDuration` s, never farther than `slop` from where
//   it began;
// - drag: one finger moved farther than `slop`: began, then changed every frame it moves, ended
//   when it lifts; the translation is measured from where the finger began;
// - pinch: two fingers; scale s = d / d0, the distance between them over the distance when the
//   second one came down. It begins once |s - 1| > `pinchThreshold`;
// - rotate: two fingers; the angle of the line between them less its angle when the second came
//   down, rad, counter-clockwise positive in a y-up frame (clockwise on a y-down screen), summed
//   frame to frame so that it passes +-pi without a jump. It begins once |angle| > `rotateThreshold`.
// Pinch and rotate are independent (a twist with spread fingers gives both). Once a second finger
// comes down, the touch sequence is a two-finger one until every finger lifts: no tap or drag.
#pragma once

#include <impetus/math/vec2.hpp>
#include <impetus/sensors/touch_tracker.hpp>

#include <optional>
#include <span>
#include <vector>

namespace impetus::sensors {

struct GestureSettings {
  double tapMaxDuration = 0.3;    ///< s (> 0)
  double slop = 10.0;             ///< distance a finger may wander and still tap, unit of the points (>= 0)
  double pinchThreshold = 0.05;   ///< relative change of the finger distance that starts a pinch (>= 0)
  double rotateThreshold = 0.087; ///< rad (5 degrees) that start a rotation (>= 0)
};

enum class GestureKind { tap, drag, pinch, rotate };
enum class GesturePhase { began, changed, ended };

/// "tap", "drag", "pinch", "rotate"; "began", "changed", "ended" (for logs and tools).
[[nodiscard]] const char* gestureKindName(GestureKind kind) noexcept;
[[nodiscard]] const char* gesturePhaseName(GesturePhase phase) noexcept;

struct GestureEvent {
  GestureKind kind = GestureKind::tap;
  GesturePhase phase = GesturePhase::ended; ///< a tap is reported once, as ended
  double time = 0.0;                        ///< s
  Vec2d position;                           ///< tap and drag: the finger; pinch and rotate: the midpoint of the two
  Vec2d translation;                        ///< drag: from where the finger began; pinch/rotate: of the midpoint
  double scale = 1.0;                       ///< pinch: d / d0
  double rotation = 0.0;                    ///< rotate: rad
};

class GestureRecognizer {
public:
  /// Throws impetus::Error naming the setting that is negative, zero (tapMaxDuration) or NaN.
  explicit GestureRecognizer(const GestureSettings& settings = {});

  /// Reads one frame of tracked touches (as TouchTracker::update returns them) and returns the
  /// gesture events it completes or advances, in the order tap, drag, pinch, rotate.
  std::vector<GestureEvent> update(double time, std::span<const TrackedTouch> touches);

  [[nodiscard]] const GestureSettings& settings() const noexcept { return settings_; }

private:
  struct Pair {
    int first = 0;
    int second = 0;
    double startDistance = 0.0;
    double lastAngle = 0.0;
    double rotation = 0.0;
    Vec2d startMidpoint;
    bool pinching = false;
    bool rotating = false;
  };

  GestureSettings settings_;
  std::optional<int> single_; ///< the one finger of a tap or drag candidate
  bool dragging_ = false;
  bool wandered_ = false; ///< the single finger went beyond the slop
  bool multi_ = false;    ///< a second finger came down in this sequence
  std::optional<Pair> pair_;
};

} // namespace impetus::sensors
