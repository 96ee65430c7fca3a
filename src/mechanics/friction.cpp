#include <impetus/error.hpp>
#include <impetus/mechanics/friction.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace impetus {
namespace {

void requireCoefficients(double staticCoefficient, double kineticCoefficient) {
  requireNonNegative(staticCoefficient, "staticCoefficient");
  requireNonNegative(kineticCoefficient, "kineticCoefficient");
  // mu_k > mu_s would make a body that starts to slide feel more friction than held it: the
  // friction would then reverse the push. No real pair behaves so.
  if (kineticCoefficient > staticCoefficient) {
    throwInvalid("kineticCoefficient", kineticCoefficient, "must not exceed staticCoefficient");
  }
}

constexpr std::string_view serway = "Serway & Jewett, Physics for Scientists and Engineers, Table 5.1";
constexpr std::string_view openstax = "OpenStax College Physics (2012), Table 5.1";

// Typical values for clean, dry surfaces unless the name says otherwise. Where Serway gives a
// range (wood on wood, 0.25-0.5) the single value of the OpenStax table is used instead.
constexpr std::array materials{
    FrictionMaterial{"rubber-concrete-dry", "rubber on dry concrete", 1.0, 0.8, serway},
    FrictionMaterial{"rubber-concrete-wet", "rubber on wet concrete", 0.7, 0.5, openstax},
    FrictionMaterial{"steel-steel", "steel on steel, dry", 0.74, 0.57, serway},
    FrictionMaterial{"steel-steel-oiled", "steel on steel, oiled", 0.05, 0.03, openstax},
    FrictionMaterial{"metal-metal-lubricated", "metal on metal, lubricated", 0.15, 0.06, serway},
    FrictionMaterial{"aluminum-steel", "aluminum on steel", 0.61, 0.47, serway},
    FrictionMaterial{"copper-steel", "copper on steel", 0.53, 0.36, serway},
    FrictionMaterial{"glass-glass", "glass on glass", 0.94, 0.4, serway},
    FrictionMaterial{"wood-wood", "wood on wood", 0.5, 0.3, openstax},
    FrictionMaterial{"metal-wood", "metal on wood", 0.5, 0.3, openstax},
    FrictionMaterial{"shoes-wood", "shoes on wood", 0.9, 0.7, openstax},
    FrictionMaterial{"shoes-ice", "shoes on ice", 0.1, 0.05, openstax},
    FrictionMaterial{"ice-ice", "ice on ice", 0.1, 0.03, serway},
    FrictionMaterial{"steel-ice", "steel on ice", 0.4, 0.02, openstax},
    FrictionMaterial{"waxed-wood-wet-snow", "waxed wood on wet snow", 0.14, 0.1, serway},
    FrictionMaterial{"teflon-teflon", "Teflon on Teflon", 0.04, 0.04, serway},
    FrictionMaterial{"teflon-steel", "Teflon on steel", 0.04, 0.04, openstax},
    FrictionMaterial{"synovial-joint", "synovial joints in humans", 0.01, 0.003, serway},
};

} // namespace

FrictionResponse frictionAtRest(double appliedForce, double normalForce, double staticCoefficient,
                                double kineticCoefficient) {
  requireFinite(appliedForce, "appliedForce");
  requireNonNegative(normalForce, "normalForce");
  requireCoefficients(staticCoefficient, kineticCoefficient);
  FrictionResponse r{};
  r.slides = std::abs(appliedForce) > staticCoefficient * normalForce;
  r.frictionForce = r.slides ? -std::copysign(kineticCoefficient * normalForce, appliedForce) : -appliedForce;
  r.netForce = r.slides ? appliedForce + r.frictionForce : 0.0;
  return r;
}

double kineticFrictionForce(double velocity, double normalForce, double kineticCoefficient) {
  requireFinite(velocity, "velocity");
  requireNonNegative(normalForce, "normalForce");
  requireNonNegative(kineticCoefficient, "kineticCoefficient");
  if (velocity == 0.0) {
    return 0.0;
  }
  return -std::copysign(kineticCoefficient * normalForce, velocity);
}

PushedBlock pushBlock(double mass, double pushForce, double staticCoefficient, double kineticCoefficient,
                      double gravity) {
  requirePositive(mass, "mass");
  requireNonNegative(gravity, "gravity");
  requireFinite(pushForce, "pushForce"); // here, or frictionAtRest would name it appliedForce
  PushedBlock b{};
  b.normalForce = mass * gravity;
  const FrictionResponse f = frictionAtRest(pushForce, b.normalForce, staticCoefficient, kineticCoefficient);
  b.slides = f.slides;
  b.frictionForce = f.frictionForce;
  b.acceleration = f.netForce / mass;
  return b;
}

double angleOfRepose(double staticCoefficient) {
  return std::atan(requireNonNegative(staticCoefficient, "staticCoefficient"));
}

BlockOnIncline blockOnIncline(double mass, double inclineAngle, double staticCoefficient, double kineticCoefficient,
                              double gravity) {
  requirePositive(mass, "mass");
  requireFinite(inclineAngle, "inclineAngle");
  if (inclineAngle < 0.0 || inclineAngle > std::numbers::pi / 2.0) {
    throwInvalid("inclineAngle", inclineAngle, "must be in [0, pi/2] rad");
  }
  requireCoefficients(staticCoefficient, kineticCoefficient);
  requireNonNegative(gravity, "gravity");
  const double weight = mass * gravity;
  // cos(pi/2) in double is 6.1e-17, not 0: the vertical wall keeps a negligible normal force.
  const double downSlope = weight * std::sin(inclineAngle);
  BlockOnIncline b{};
  b.normalForce = weight * std::cos(inclineAngle);
  b.slides = downSlope > staticCoefficient * b.normalForce;
  b.frictionForce = b.slides ? kineticCoefficient * b.normalForce : downSlope;
  b.acceleration = b.slides ? (downSlope - b.frictionForce) / mass : 0.0;
  return b;
}

std::span<const FrictionMaterial> frictionMaterials() noexcept { return materials; }

const FrictionMaterial& frictionMaterial(std::string_view name) {
  for (const FrictionMaterial& m : materials) {
    if (m.name == name) {
      return m;
    }
  }
  throw Error("material",
              "material = '" + std::string(name) + "': unknown pair (impetus calc friction-materials lists them)");
}

} // namespace impetus
