// Friction (ch. 3): static and kinetic Coulomb friction, material pairs, angle of repose.
//
// Coulomb's model: a body at rest on a surface stays put while the tangential force on it is at
// most mu_s N (static friction then balances it exactly); beyond that it slides, and kinetic
// friction mu_k N opposes the sliding. N is the normal force (N), mu_s and mu_k dimensionless,
// usually mu_k < mu_s. The coefficients come from experiment and scatter a lot; the table below
// gives typical textbook values, not the book's (its friction table was lost). Every function
// validates its input and throws impetus::Error naming the offending parameter.
#pragma once

#include <impetus/core/constants.hpp>

#include <span>
#include <string_view>

namespace impetus {

/// The friction on a body that was at rest, under a tangential force.
struct FrictionResponse {
  bool slides;          ///< |appliedForce| > mu_s N
  double frictionForce; ///< N, signed, opposing: -appliedForce when it holds, -sgn(F) mu_k N when it slides
  double netForce;      ///< appliedForce + frictionForce, N (0 when it holds)
};

/// appliedForce: the tangential force (N, signed along the surface); normalForce >= 0 N;
/// 0 <= kineticCoefficient <= staticCoefficient. At exactly mu_s N static friction still holds.
[[nodiscard]] FrictionResponse frictionAtRest(double appliedForce, double normalForce, double staticCoefficient,
                                              double kineticCoefficient);

/// Kinetic friction on a sliding body: -sgn(v) mu_k N, N (zero when velocity = 0: a body at rest
/// is frictionAtRest's business).
[[nodiscard]] double kineticFrictionForce(double velocity, double normalForce, double kineticCoefficient);

/// A block of mass m at rest on level ground, pushed horizontally through its centre of
/// gravity (the book's Fig 3-1).
struct PushedBlock {
  bool slides;          ///< |pushForce| > mu_s m g
  double normalForce;   ///< N = m g, N
  double frictionForce; ///< N, signed, opposing the push
  double acceleration;  ///< (push + friction) / m, m/s^2 (0 when it holds)
};

/// mass > 0 kg, pushForce in N (signed), gravity >= 0 m/s^2.
[[nodiscard]] PushedBlock pushBlock(double mass, double pushForce, double staticCoefficient, double kineticCoefficient,
                                    double gravity = constants::standardGravity);

/// theta = atan(mu_s), rad: the steepest incline on which a body (or a heap of loose material)
/// stays at rest. staticCoefficient >= 0.
[[nodiscard]] double angleOfRepose(double staticCoefficient);

/// A block released at rest on an incline of angle theta.
struct BlockOnIncline {
  bool slides;          ///< tan(theta) > mu_s
  double normalForce;   ///< m g cos(theta), N
  double frictionForce; ///< up the slope, N: m g sin(theta) when it holds, mu_k N when it slides
  double acceleration;  ///< down the slope, m/s^2: g (sin(theta) - mu_k cos(theta)) or 0
};

/// mass > 0 kg; inclineAngle in [0, pi/2] rad; gravity >= 0 m/s^2.
[[nodiscard]] BlockOnIncline blockOnIncline(double mass, double inclineAngle, double staticCoefficient,
                                            double kineticCoefficient, double gravity = constants::standardGravity);

/// Typical friction coefficients of a pair of materials.
struct FrictionMaterial {
  std::string_view name;        ///< e.g. "rubber-concrete-dry"
  std::string_view description; ///< e.g. "rubber on dry concrete"
  double staticCoefficient;
  double kineticCoefficient;
  std::string_view source;
};

/// The table, in a fixed order. Sources (textbook values, typical of clean surfaces; real
/// values scatter by +-20 % or more): R. A. Serway and J. W. Jewett, *Physics for Scientists and
/// Engineers*, Table 5.1 "Coefficients of Friction"; and OpenStax *College Physics* (2012),
/// Table 5.1 "Coefficients of Static and Kinetic Friction". Not from Bourg and Bywalec, whose
/// table was lost (its only surviving values, rubber on pavement mu_s ~0.55 and mu_k ~0.4, are
/// used in its car chapter).
[[nodiscard]] std::span<const FrictionMaterial> frictionMaterials() noexcept;

/// The pair named `name`; throws impetus::Error (field "material") when there is none.
[[nodiscard]] const FrictionMaterial& frictionMaterial(std::string_view name);

} // namespace impetus
