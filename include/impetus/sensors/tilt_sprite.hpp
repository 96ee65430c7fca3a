// The book's tilt-controlled sprite (ch. 21) as a model: a ball on a tilted screen, 2 degrees of
// freedom, with friction and the screen's edges.
//
// The book's SpriteView gets the accelerometer reading (in g) 60 times a second and moves the
// sprite as a body under the constant acceleration a g over the measured interval dt:
//   dx = v dt + a g dt^2 / 2,   v += a g dt            (per axis; nothing moves on the first call)
// in a world of kWorldWidth x kWorldHeight metres scaled to the view (convertX = view px / world
// m). At an edge the position is clamped and that velocity component zeroed. The book suggests
// friction, drag and bouncing off the edges; here they are:
// - the pull in the screen's plane is the in-plane part of gravity, g (g_x, g_y) with g_x, g_y
//   the reading in the gravity-direction convention (the ball rolls downhill); the screen
//   presses on the ball with g |g_z| per kg;
// - Coulomb friction: at rest the ball stays while |pull| <= mu_s g |g_z|; sliding, friction
//   mu_k g |g_z| opposes the velocity, and a step in which it would reverse the velocity stops
//   the ball where the velocity reaches zero instead (friction never pushes);
// - linear drag -c v (1/s);
// - edges: the velocity component into the edge is reversed and scaled by the restitution e
//   (e = 0: the book's stop).
// World axes: x right, y up, origin at the bottom-left of the screen; `position` is the sprite's
// bottom-left corner. The book's listing mixes the sign of a_y (docs/book-errata.md); here the
// device's y axis (towards its top edge) is the world's +y throughout.
#pragma once

#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>
#include <impetus/sensors/tilt.hpp>

#include <optional>

namespace impetus::sensors {

struct TiltSpriteSettings {
  Vec2d worldSize{0.5, 0.75};   ///< m, the screen's extent in the world (kWorldWidth, kWorldHeight)
  Vec2d spriteSize{0.05, 0.05}; ///< m
  double gravity = 9.8;         ///< m/s^2 per g of reading (the book's; any acceleration scale)
  double staticFriction = 0.0;  ///< mu_s (>= mu_k)
  double kineticFriction = 0.0; ///< mu_k
  double drag = 0.0;            ///< linear drag c, 1/s
  double restitution = 0.0;     ///< at the edges, [0, 1]
  AccelConvention convention = AccelConvention::gravityDirection; ///< the book's (iOS) readings
};

class TiltSprite {
public:
  /// Starts at rest, centred. Throws impetus::Error naming the setting (sizes > 0 and the sprite
  /// no larger than the world, gravity >= 0, 0 <= mu_k <= mu_s, drag >= 0, e in [0, 1]).
  explicit TiltSprite(const TiltSpriteSettings& settings);

  /// The book's callback: a reading (g) with its timestamp (s). The first call only stores the
  /// time; each later one advances by the real interval since the previous call. Returns that
  /// interval (0 on the first call). Throws impetus::Error for a non-finite reading or a
  /// timestamp that goes back (field "timestamp").
  double update(const Vec3d& readingG, double timestamp);

  /// Advances by dt s (>= 0) under the reading, held constant over the step.
  void step(const Vec3d& readingG, double dt);

  [[nodiscard]] const Vec2d& position() const noexcept { return position_; }
  [[nodiscard]] const Vec2d& velocity() const noexcept { return velocity_; }
  /// Edge hits so far: arrivals at an edge (resting against one counts once).
  [[nodiscard]] int edgeHits() const noexcept { return edgeHits_; }
  [[nodiscard]] const TiltSpriteSettings& settings() const noexcept { return settings_; }
  /// The largest position the corner can reach: world - sprite.
  [[nodiscard]] Vec2d maxPosition() const noexcept { return settings_.worldSize - settings_.spriteSize; }

  void setState(const Vec2d& position, const Vec2d& velocity);

  /// Where to draw the sprite's top-left corner in a view of `viewPixels` (x right, y down):
  /// the book's position x convertX, with convertX = view width / world width.
  [[nodiscard]] Vec2d screenPosition(const Vec2d& viewPixels) const noexcept;

private:
  TiltSpriteSettings settings_;
  Vec2d position_;
  Vec2d velocity_;
  std::optional<double> lastTime_;
  int edgeHits_ = 0;
  int contact_[2] = {0, 0}; ///< per axis: 0 free, 1 at the low edge, 2 at the high edge
};

} // namespace impetus::sensors
