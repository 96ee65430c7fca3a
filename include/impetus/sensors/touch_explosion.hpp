// The book's touch-screen particle explosion (ch. 20): each finger that touches the screen sets
// off the ch. 2 particle explosion (mechanics/explosion.hpp) where it touched.
//
// The book's iOS program stores the first touch's view coordinates in touchesBegan and starts the
// explosion there; its multitouch version enables multiple-touch delivery, keeps a dictionary from
// each touch to its begin point and runs one explosion per touch. Here the touches come from a
// TouchTracker (stable ids: a finger held down or dragged does not explode again), the screen
// points (pixels, y down, as touch APIs report them) are mapped to world metres (y up), and
// explosions run on simulated time, so recorded input replays identically. The book warns that
// many simultaneous explosions may need a lower update rate; here at most `maxExplosions` run at
// once and the oldest gives way.
#pragma once

#include <impetus/math/vec2.hpp>
#include <impetus/mechanics/explosion.hpp>
#include <impetus/sensors/touch_tracker.hpp>

#include <cstddef>
#include <deque>
#include <span>

namespace impetus::sensors {

/// Screen pixels (x right, y down, origin top-left) to world metres (x right, y up, origin at
/// the bottom-left corner of the screen).
struct ScreenToWorld {
  double screenHeight = 480.0;  ///< px (> 0)
  double pixelsPerMetre = 20.0; ///< px/m (> 0)

  [[nodiscard]] Vec2d toWorld(const Vec2d& px) const noexcept {
    return {px.x / pixelsPerMetre, (screenHeight - px.y) / pixelsPerMetre};
  }
  [[nodiscard]] Vec2d toScreen(const Vec2d& m) const noexcept {
    return {m.x * pixelsPerMetre, screenHeight - m.y * pixelsPerMetre};
  }
};

struct TouchExplosionSettings {
  ExplosionSettings explosion{}; ///< every field but origin and seed is used for each burst
  ScreenToWorld screen{};
  double maxJump = 60.0;         ///< px a finger moves between frames (tracker)
  std::size_t maxExplosions = 8; ///< running at once (>= 1)
  bool multitouch = true;        ///< false: the book's first version, only a lone finger explodes
};

struct TouchBurst {
  KinematicExplosion explosion;
  double start = 0.0; ///< s
  int touchId = 0;    ///< the finger that set it off
};

class TouchExplosions {
public:
  /// Throws impetus::Error naming the setting (the explosion's own checks included).
  explicit TouchExplosions(const TouchExplosionSettings& settings);

  /// One frame of touch input at `time` (s, non-decreasing): every finger that began sets off a
  /// burst; bursts whose particles are all dead are dropped. Returns how many began this frame.
  std::size_t update(double time, std::span<const Vec2d> screenPoints);

  /// The settings of the bursts to come (a game's strength or direction control; origin and
  /// seed are ignored). Throws impetus::Error as the explosion would.
  void setExplosion(const ExplosionSettings& explosion);

  [[nodiscard]] const std::deque<TouchBurst>& bursts() const noexcept { return bursts_; }
  /// Particles alive at `time` over every burst.
  [[nodiscard]] std::size_t aliveParticles(double time) const noexcept;
  /// Bursts set off so far (including those already over or pushed out).
  [[nodiscard]] std::size_t burstCount() const noexcept { return started_; }
  [[nodiscard]] const TouchTracker& tracker() const noexcept { return tracker_; }
  [[nodiscard]] const TouchExplosionSettings& settings() const noexcept { return settings_; }

private:
  TouchExplosionSettings settings_;
  TouchTracker tracker_;
  std::deque<TouchBurst> bursts_;
  std::size_t started_ = 0;
};

} // namespace impetus::sensors
