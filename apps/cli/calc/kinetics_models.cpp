// `impetus calc` entries for chapter 4 (kinetics): the ship under thrust with linear
// resistance, and a box pushed on a floor (tipping versus sliding).
#include "calc/calc.hpp"

#include <impetus/mechanics/kinetics.hpp>

#include <cmath>
#include <string>

namespace impetus::cli {
namespace {

constexpr const char* topic = "kinetics (ch. 4)";

Result ship(const Args& a) {
  const double thrust = a.number("thrust");
  const double mass = a.number("mass");
  const double c = a.number("resistance-coefficient");
  const ShipState s = shipMotion(thrust, mass, c, a.number("time"), a.number("initial-speed"));
  Result r;
  r.add("speed", s.speed, "m/s", "v(t)");
  r.add("distance", s.distance, "m", "s(t)");
  r.add("acceleration", s.acceleration, "m/s^2", "a(t)");
  if (c > 0.0) {
    r.add("terminal_speed", shipTerminalSpeed(thrust, c), "m/s", "T / C");
    r.add("time_constant", shipTimeConstant(mass, c), "s", "m / C");
  }
  return r;
}

std::string motionName(BoxMotion m) {
  switch (m) {
  case BoxMotion::rests:
    return "rests";
  case BoxMotion::slides:
    return "slides";
  case BoxMotion::tipsForward:
    return "tips-forward";
  case BoxMotion::tipsBackward:
    return "tips-backward";
  }
  return "?";
}

Result box(const Args& a) {
  PushedBox b{};
  b.mass = a.number("mass");
  b.width = a.number("width");
  b.height = a.number("height");
  b.pushHeight = a.number("push-height");
  b.staticCoefficient = a.number("static-coefficient");
  b.kineticCoefficient = a.number("kinetic-coefficient");
  b.gravity = a.number("gravity");
  const BoxTipping t = boxTipping(b);
  Result r;
  r.add("sliding_force", t.slidingForce, "N", "mu_s m g: the push that starts it sliding");
  r.add("tipping_force_at_rest", t.tippingForceAtRest, "N", "m g w / (2 h_p): the push that tips a held box");
  if (std::isfinite(t.criticalPushHeight)) {
    r.add("critical_push_height", t.criticalPushHeight, "m", "w / (2 mu_s): at or above it, it tips before sliding");
  } else {
    r.notes.emplace_back("mu_s = 0: the box slides under any push before it can tip");
  }
  r.add("first_motion", std::string(t.tipsFirst ? "tips" : "slides"), "", "as the push grows from zero");
  if (t.tippingForceWhileSliding) {
    r.add("tipping_force_while_sliding", *t.tippingForceWhileSliding, "N",
          "m g (w - mu_k h) / (2 h_p - h): the push that tips a sliding box forward");
  }
  if (t.backwardTippingForceWhileSliding) {
    r.add("backward_tipping_force_while_sliding", *t.backwardTippingForceWhileSliding, "N",
          "m g (w + mu_k h) / (h - 2 h_p): the push that tips a sliding box backward");
  }
  const BoxResponse response = pushBoxAtRest(b, a.number("push-force"));
  r.add("motion", motionName(response.motion), "", "at the onset of --push-force on the box at rest");
  r.add("leading_reaction", response.reactions.leadingReaction, "N", "R1, under the leading edge");
  r.add("trailing_reaction", response.reactions.trailingReaction, "N", "R2, under the pushed edge");
  r.add("friction_force", response.reactions.frictionForce, "N", "against the push");
  r.add("acceleration", response.reactions.acceleration, "m/s^2");
  return r;
}

} // namespace

void registerKineticsModels(Registry& registry) {
  registry.add({"ship",
                topic,
                "thrust T, linear resistance C: v = T/C (1 - e^{-Ct/m}), s = (T/C) t - (T m/C^2)(1 - e^{-Ct/m})",
                {{"thrust", "N", "propeller thrust T", std::nullopt},
                 {"mass", "kg", "mass m", std::nullopt},
                 {"resistance-coefficient", "N s/m", "C in R = C v (>= 0)", std::nullopt},
                 {"time", "s", "time since the start, >= 0", std::nullopt},
                 {"initial-speed", "m/s", "speed at t = 0", "0"}},
                ship});
  registry.add({"box-tipping",
                topic,
                "box pushed at height h_p: tips at F = m g w/(2 h_p) (held) or m g (w - mu_k h)/(2 h_p - h) "
                "(sliding)",
                {{"mass", "kg", "mass m", std::nullopt},
                 {"width", "m", "w, along the push", std::nullopt},
                 {"height", "m", "h", std::nullopt},
                 {"push-height", "m", "h_p, height of the horizontal push, 0 < h_p <= h", std::nullopt},
                 {"static-coefficient", "", "mu_s", std::nullopt},
                 {"kinetic-coefficient", "", "mu_k <= mu_s", std::nullopt},
                 {"gravity", "m/s^2", "g", "9.80665"},
                 {"push-force", "N", "a push to evaluate on the box at rest", "0"}},
                box});
}

} // namespace impetus::cli
