#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/sensors/touch_tracker.hpp>

#include <algorithm>
#include <tuple>

namespace impetus::sensors {

TouchTracker::TouchTracker(double maxJump) : maxJump_(requirePositive(maxJump, "maxJump")) {}

std::size_t TouchTracker::activeCount() const noexcept {
  return static_cast<std::size_t>(
      std::count_if(frame_.begin(), frame_.end(), [](const TrackedTouch& t) { return t.phase != TouchPhase::ended; }));
}

void TouchTracker::reset() noexcept { frame_.clear(); }

std::span<const TrackedTouch> TouchTracker::update(double time, std::span<const Vec2d> points) {
  requireFinite(time, "time");
  if (time < lastTime_) {
    throwInvalid("time", time, "must not go back (frames arrive in order)");
  }
  for (const Vec2d& p : points) {
    requireFinite(p, "points");
  }
  lastTime_ = time;
  std::vector<TrackedTouch> previous;
  for (const TrackedTouch& t : frame_) {
    if (t.phase != TouchPhase::ended) {
      previous.push_back(t);
    }
  }
  // Every candidate pair within reach, nearest first.
  struct Pair {
    double d2;
    std::size_t touch;
    std::size_t point;
  };
  std::vector<Pair> pairs;
  const double reach2 = maxJump_ * maxJump_;
  for (std::size_t i = 0; i < previous.size(); ++i) {
    for (std::size_t j = 0; j < points.size(); ++j) {
      const double d2 = lengthSquared(points[j] - previous[i].position);
      if (d2 <= reach2) {
        pairs.push_back({d2, i, j});
      }
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return std::tie(a.d2, a.touch, a.point) < std::tie(b.d2, b.touch, b.point);
  });
  std::vector<bool> touchTaken(previous.size(), false);
  std::vector<bool> pointTaken(points.size(), false);
  std::vector<TrackedTouch> next;
  for (const Pair& p : pairs) {
    if (touchTaken[p.touch] || pointTaken[p.point]) {
      continue;
    }
    touchTaken[p.touch] = true;
    pointTaken[p.point] = true;
    TrackedTouch t = previous[p.touch];
    t.previous = t.position;
    t.position = points[p.point];
    t.phase = t.position == t.previous ? TouchPhase::stationary : TouchPhase::moved;
    next.push_back(t);
  }
  for (std::size_t i = 0; i < previous.size(); ++i) {
    if (!touchTaken[i]) {
      TrackedTouch t = previous[i];
      t.previous = t.position;
      t.phase = TouchPhase::ended;
      next.push_back(t);
    }
  }
  for (std::size_t j = 0; j < points.size(); ++j) {
    if (!pointTaken[j]) {
      TrackedTouch t;
      t.id = nextId_++;
      t.phase = TouchPhase::began;
      t.position = t.previous = t.start = points[j];
      t.startTime = time;
      next.push_back(t);
    }
  }
  std::sort(next.begin(), next.end(), [](const TrackedTouch& a, const TrackedTouch& b) { return a.id < b.id; });
  frame_ = std::move(next);
  return frame_;
}

} // namespace impetus::sensors
