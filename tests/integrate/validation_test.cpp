// The input validation audit of the integrators (docs/reliability.md, "Input validation"): the
// adaptive drivers refuse bad tolerances, step limits, spans and states with an impetus::Error
// naming the field and showing the value. (The fixed-step steppers do not validate by design:
// they run inside step loops that never throw; steppers.hpp says so.)
#include "support/validation_table.hpp"

#include <impetus/integrate/integrate.hpp>

#include <gtest/gtest.h>

namespace impetus {
namespace {

using impetus::testing::expectAccepted;
using impetus::testing::expectRejected;
using impetus::testing::infd;
using impetus::testing::nand;

double decay(double, double y) { return -y; }

TEST(IntegrateValidation, adaptive_settings_spans_and_states) {
  const auto settings = [](auto change) {
    return [change] {
      AdaptiveSettings s;
      change(s);
      (void)integrateDormandPrince(decay, 0.0, 1.0, 1.0, s);
    };
  };
  expectRejected({
      {"absoluteTolerance", "-1", settings([](AdaptiveSettings& s) { s.absoluteTolerance = -1; })},
      {"absoluteTolerance", "nan", settings([](AdaptiveSettings& s) { s.absoluteTolerance = nand; })},
      {"relativeTolerance", "inf", settings([](AdaptiveSettings& s) { s.relativeTolerance = infd; })},
      {"absoluteTolerance", "0", settings([](AdaptiveSettings& s) { s.absoluteTolerance = s.relativeTolerance = 0; })},
      {"initialStep", "-1", settings([](AdaptiveSettings& s) { s.initialStep = -1; })},
      {"minStep", "0", settings([](AdaptiveSettings& s) { s.minStep = 0; })},
      {"minStep", "nan", settings([](AdaptiveSettings& s) { s.minStep = nand; })},
      {"maxStep", "1e-13", settings([](AdaptiveSettings& s) { s.maxStep = 1e-13; })},
      {"maxStep", "nan", settings([](AdaptiveSettings& s) { s.maxStep = nand; })},
      {"safety", "0", settings([](AdaptiveSettings& s) { s.safety = 0; })},
      {"safety", "1.5", settings([](AdaptiveSettings& s) { s.safety = 1.5; })},
      {"minScale", "1", settings([](AdaptiveSettings& s) { s.minScale = 1; })},
      {"maxScale", "1", settings([](AdaptiveSettings& s) { s.maxScale = 1; })},
      {"maxScale", "inf", settings([](AdaptiveSettings& s) { s.maxScale = infd; })},
      {"maxSteps", "0", settings([](AdaptiveSettings& s) { s.maxSteps = 0; })},
      {"startTime", "nan", [] { (void)integrateDormandPrince(decay, nand, 1.0, 1.0); }},
      {"endTime", "inf", [] { (void)integrateStepDoubling(RungeKutta4{}, decay, 0.0, 1.0, infd); }},
      {"endTime", "-1", [] { (void)integrateDormandPrince(decay, 0.0, 1.0, -1.0); }},
      {"initialState", "nan", [] { (void)integrateDormandPrince(decay, 0.0, nand, 1.0); }},
      {"derivative", "inf", [] { (void)integrateDormandPrince([](double, double) { return infd; }, 0.0, 1.0, 1.0); }},
      {"time", "nan", [] { (void)stepDoublingTrial(Heun{}, decay, nand, 1.0, 0.1); }},
      {"step", "0", [] { (void)stepDoublingTrial(Heun{}, decay, 0.0, 1.0, 0.0); }},
      {"step", "-0.1", [] { (void)stepDoublingTrial(ExplicitEuler{}, decay, 0.0, 1.0, -0.1); }},
      {"step", "inf", [] { (void)stepDoublingTrial(Midpoint{}, decay, 0.0, 1.0, infd); }},
  });
  expectAccepted({
      {"a zero span, an absolute-only or relative-only tolerance, safety 1",
       [] {
         (void)integrateDormandPrince(decay, 1.0, 1.0, 1.0);
         AdaptiveSettings s;
         s.relativeTolerance = 0;
         s.safety = 1;
         (void)integrateStepDoubling(RungeKutta4{}, decay, 0.0, 1.0, 1.0, s);
         s.relativeTolerance = 1e-6;
         s.absoluteTolerance = 0;
         (void)integrateDormandPrince(decay, 0.0, 1.0, 1.0, s);
       }},
  });
}

} // namespace
} // namespace impetus
