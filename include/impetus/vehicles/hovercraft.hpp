// The book's ch. 9 hovercraft on the 2D engine: a rigid body driven by an aft propeller (thrust
// through the centre of mass), steered by two bow thrusters, and slowed by aerodynamic drag acting
// at a centre of drag aft of the centre of mass, which gives it weathervane stability. Ch. 10
// crashes two of them together ("bumper cars").
//
// Units: the book's numbers, read as SI (m, kg, N, s) with a render scale instead of pixels: a
// 20 m x 10 m x 5 m craft of 100 kg (light: the book's numbers are for feel, not a real craft),
// 0-10 N of thrust. The air density the book never states; 0.0023769 (its aircraft chapters'
// slug/ft^3 value, taken as kg/m^3 here) gives the book's handling: about 9.5 m/s at full thrust.
// With real air (1.225 kg/m^3) the same craft tops out at 0.42 m/s.
//
// Body frame: +x forward (the bow), +y to port (left), so a positive angle turns the bow to port.
// (The book's screen frame has +y down, hence +y to starboard there and mirrored signs: the
// port thruster at its (L/2, -W/2) turns the craft to starboard; here it sits at (L/2, +W/2) and
// does the same.)
#pragma once

#include <impetus/rigid2d/world.hpp>

#include <array>

namespace impetus::vehicles {

struct HovercraftParams {
  float mass = 100.0f;                        ///< kg
  float inertia = 500.0f;                     ///< kg m^2 about the centre of mass (the book's; not a uniform box's)
  float length = 20.0f;                       ///< m, along x
  float width = 10.0f;                        ///< m, along y
  float height = 5.0f;                        ///< m: with length and width, the projected area (L + W) / 2 H = 75 m^2
  float minThrust = 0.0f;                     ///< N (the book's _MINTHRUST: no reverse)
  float maxThrust = 10.0f;                    ///< N
  float thrustRate = 1.0f;                    ///< N/s while the throttle is held (the book: 0.001 per 0.001 s step)
  float steeringForce = 3.0f;                 ///< N, each bow thruster
  float dragCoefficient = 1.25f;              ///< the book's _LINEARDRAGCOEFFICIENT, used as C_d
  float airDensity = 0.0023769f;              ///< kg/m^3 (see above)
  Vec2f centreOfDrag{-5.0f, 0.0f};            ///< m, body frame: a quarter length aft
  Vec2f portThrusterPoint{10.0f, 5.0f};       ///< m, body frame: the port bow corner
  Vec2f starboardThrusterPoint{10.0f, -5.0f}; ///< m, body frame: the starboard bow corner
  float restitution = 0.5f;                   ///< for ch. 10's collisions
};

/// Controls for one step.
struct HovercraftControls {
  int throttle = 0;               ///< +1 more thrust, -1 less, 0 hold
  bool portThruster = false;      ///< pushes the bow to starboard: a right turn
  bool starboardThruster = false; ///< pushes the bow to port: a left turn
};

/// The loads of one step (for inspection and tests): total force (world frame, N) and moment
/// about the centre of mass (N m, counter-clockwise positive).
struct HovercraftLoads {
  Vec2f force;
  float moment = 0.0f;
  Vec2f dragForce; ///< world frame, N
};

class Hovercraft {
public:
  /// Creates the craft's body (a box of length x width, with the book's mass and inertia) in
  /// `world` at `position` (m) heading `angle` (rad). Throws impetus::Error naming the field
  /// for a non-positive mass, inertia or size, or thrust limits out of order.
  Hovercraft(rigid2d::World& world, const HovercraftParams& params, const Vec2f& position, float angle,
             float initialThrust = 5.0f);

  /// The book's CalcLoads for the coming step of dt seconds: updates the thrust from the
  /// throttle, computes propeller, drag and bow-thruster forces in the body frame and applies
  /// them to the body (world frame) for the next world.step(dt).
  HovercraftLoads applyLoads(const HovercraftControls& controls, float dt);

  [[nodiscard]] rigid2d::BodyId body() const noexcept { return body_; }
  [[nodiscard]] float thrust() const noexcept { return thrust_; }
  void setThrust(float thrust);
  [[nodiscard]] const HovercraftParams& params() const noexcept { return params_; }
  /// The drawn outline in the body frame: the hull rectangle and the pointed bow at 0.75 L.
  [[nodiscard]] std::array<Vec2f, 5> outline() const noexcept;

private:
  rigid2d::World* world_;
  HovercraftParams params_;
  rigid2d::BodyId body_;
  float thrust_ = 0.0f;
};

} // namespace impetus::vehicles
