// Multitouch tracking (ch. 20): stable ids for touches across frames.
//
// A multitouch controller reports an unordered set of contact points every scan (about 60-500
// per second). Gestures need to know which point is which finger from one frame to the next:
// the book's multitouch explosion keeps a dictionary from each touch to its begin point, and a
// pinch compares the same two fingers over time. Between scans a finger moves little, so the
// tracker pairs each point with the nearest touch of the previous frame: all pairs closer than
// `maxJump` are taken in order of increasing distance (ties by index, so the result is
// deterministic), each touch and point at most once. An unpaired point is a new finger (a new id:
// ids are never reused), an unpaired touch has lifted.
#pragma once

#include <impetus/math/vec2.hpp>

#include <span>
#include <vector>

namespace impetus::sensors {

enum class TouchPhase {
  began,      ///< first frame of this finger
  moved,      ///< still down and moved since the last frame
  stationary, ///< still down, same position
  ended,      ///< lifted: reported once, in the frame where it is gone
};

struct TrackedTouch {
  int id = 0; ///< stable from began to ended; 1, 2, 3... never reused
  TouchPhase phase = TouchPhase::began;
  Vec2d position;         ///< now (for ended: the last position seen)
  Vec2d previous;         ///< in the last frame (== position when it began)
  Vec2d start;            ///< where it began
  double startTime = 0.0; ///< s
};

class TouchTracker {
public:
  /// `maxJump`: the farthest a finger moves between two frames, in the unit of the points
  /// (pixels or m; > 0). Throws impetus::Error (field "maxJump").
  explicit TouchTracker(double maxJump);

  /// A new frame at `time` (s, not before the last frame's) with the points seen now. Returns
  /// the touches still down (began, moved or stationary) and those that ended, ordered by id.
  /// Throws impetus::Error naming "time" or "points" for bad input.
  std::span<const TrackedTouch> update(double time, std::span<const Vec2d> points);

  /// The last frame's touches (as update returned them).
  [[nodiscard]] std::span<const TrackedTouch> touches() const noexcept { return frame_; }
  /// Touches down now (not ended).
  [[nodiscard]] std::size_t activeCount() const noexcept;
  /// Lifts every finger: the next update reports none of the old ids.
  void reset() noexcept;

private:
  double maxJump_;
  double lastTime_ = -1.0e300;
  int nextId_ = 1;
  std::vector<TrackedTouch> frame_;
};

} // namespace impetus::sensors
