// `impetus calc` entries for accelerometers (ch. 21): tilt, clipping, calibration, filters and
// the tilt-controlled sprite.
#include "calc/sensors_models.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/sensors/sensors.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace impetus::cli::sensors_calc {
namespace {

using namespace impetus::sensors;

constexpr const char* accelTopic = "accelerometers (ch. 21)";

AccelConvention convention(const Args& a) {
  const std::string& c = a.text("convention");
  if (c == "specific-force") {
    return AccelConvention::specificForce;
  }
  if (c == "gravity") {
    return AccelConvention::gravityDirection;
  }
  throw Error("convention", "--convention = '" + c + "': must be specific-force (Android) or gravity (iOS)");
}

Result tiltAngleModel(const Args& a) {
  const double ax = a.number("ax");
  const double ay = a.number("ay");
  Result r;
  r.add("tilt", tiltAngle(ax, ay), "deg", "atan2(a_x, a_y) in [0, 360): 0 upright, 90 turned left");
  r.add("angle_from_x", angle360(ax, ay), "deg", "atan2(a_y, a_x) in [0, 360): the book's order, mapped right");
  r.add("book_find2dAngle", bookFind2dAngle(ax, ay), "deg", "the book's listing (negative angles mirrored)");
  r.notes.emplace_back("the book maps a negative atan2 result alpha to -alpha + 180, which mirrors it: -10 deg "
                       "gives 190 where 350 is right");
  return r;
}

Result tiltModel(const Args& a) {
  const Vec3d reading{requireFinite(a.number("ax"), "ax"), requireFinite(a.number("ay"), "ay"),
                      requireFinite(a.number("az"), "az")};
  const AccelConvention c = convention(a);
  const Tilt t = tiltFromGravity(reading, c);
  Result r;
  r.add("roll", radToDeg(t.roll), "deg", "about the device's x axis, top edge up: atan2(f_y, f_z)");
  r.add("pitch", radToDeg(t.pitch), "deg", "about its y axis, right side down: atan2(-f_x, sqrt(f_y^2 + f_z^2))");
  r.add("orientation", std::string(toString(grossOrientation(reading, c))), "", "Table 21-2's gross orientation");
  r.add("magnitude", length(reading), "g", "1 when still: anything else is the user's acceleration");
  r.notes.emplace_back("yaw (heading) is not observable from gravity");
  return r;
}

Result clipModel(const Args& a) {
  const double range = a.number("range");
  const double v = clipReading(requireFinite(a.number("acceleration"), "acceleration"), range);
  Result r;
  r.add("reading", v, "g", "what the sensor reports");
  r.add("clipped", isClipped(v, range), "", "at the limit: the true value is at least this");
  r.add("reading_si", gToMetresPerSecond2(v), "m/s^2", "x 9.80665");
  return r;
}

Result accelCalibration(const Args& a) {
  const AxisCalibration c = AxisCalibration::fromFlip(a.number("reading-up"), a.number("reading-down"));
  Result r;
  r.add("offset", c.offset, "g", "(r_up + r_down) / 2");
  r.add("scale", c.scale, "", "(r_up - r_down) / 2");
  r.add("corrected", c.apply(requireFinite(a.number("raw"), "raw")), "g", "(raw - offset) / scale");
  return r;
}

Result filterModel(const Args& a) {
  const double fc = a.number("cutoff-hz");
  const double rate = a.number("sample-rate-hz");
  const LowPassFilter low(fc, rate);
  const HighPassFilter high(fc, rate);
  const double f = a.number("frequency");
  requireNonNegative(f, "frequency");
  const double dt = 1.0 / rate;
  const double alpha = low.alpha(dt);
  const double beta = high.beta(dt);
  // Exact discrete responses: H_low = alpha / (1 - (1 - alpha) z^-1), H_high = beta (1 - z^-1) / (1 - beta z^-1).
  const double w = 2.0 * pi<double> * f * dt;
  const double lowGain = alpha / std::sqrt(1.0 - 2.0 * (1.0 - alpha) * std::cos(w) + (1.0 - alpha) * (1.0 - alpha));
  const double highGain =
      beta * 2.0 * std::abs(std::sin(0.5 * w)) / std::sqrt(1.0 - 2.0 * beta * std::cos(w) + beta * beta);
  const double ratio = f / fc;
  Result r;
  r.add("rc", 1.0 / (2.0 * pi<double> * fc), "s", "RC = 1 / (2 pi f_c)");
  r.add("alpha", alpha, "", "low-pass: y += alpha (x - y), alpha = dt / (RC + dt)");
  r.add("beta", beta, "", "high-pass: y = beta (y + x - x_prev), beta = RC / (RC + dt)");
  r.add("low_pass_gain", lowGain, "", "at --frequency, exact for the sampled filter");
  r.add("high_pass_gain", highGain, "", "at --frequency, exact for the sampled filter");
  r.add("rc_low_pass_gain", 1.0 / std::sqrt(1.0 + ratio * ratio), "", "the continuous RC circuit's");
  r.add("rc_high_pass_gain", ratio / std::sqrt(1.0 + ratio * ratio), "", "the continuous RC circuit's");
  r.add("nyquist", 0.5 * rate, "Hz", "the cut-off must stay below it");
  return r;
}

Result spriteModel(const Args& a) {
  TiltSpriteSettings s;
  s.worldSize = {requirePositive(a.number("world-width"), "worldWidth"),
                 requirePositive(a.number("world-height"), "worldHeight")};
  s.spriteSize = {a.number("sprite-size"), a.number("sprite-size")};
  s.gravity = a.number("gravity");
  s.staticFriction = a.number("static-friction");
  s.kineticFriction = a.number("kinetic-friction");
  s.drag = a.number("drag");
  s.restitution = a.number("restitution");
  s.convention = convention(a);
  TiltSprite sprite(s);
  const double duration = requireNonNegative(a.number("duration"), "duration");
  const double dt = requirePositive(a.number("time-step"), "timeStep");
  const Vec3d reading{requireFinite(a.number("ax"), "ax"), requireFinite(a.number("ay"), "ay"),
                      requireFinite(a.number("az"), "az")};
  const Vec2d start = sprite.position();
  const auto steps = static_cast<long>(std::ceil(duration / dt - 1e-9));
  if (steps > 10'000'000) {
    throwInvalid("duration", duration, "needs more than 1e7 steps: use a longer --time-step");
  }
  for (long i = 0; i < steps; ++i) {
    sprite.step(reading, std::min(dt, duration - static_cast<double>(i) * dt));
  }
  Result r;
  r.add("start", Vector{start.x, start.y}, "m", "centred");
  r.add("position", Vector{sprite.position().x, sprite.position().y}, "m", "bottom-left corner, y up");
  r.add("velocity", Vector{sprite.velocity().x + 0.0, sprite.velocity().y + 0.0}, "m/s"); // no -0
  r.add("edge_hits", static_cast<double>(sprite.edgeHits()), "");
  r.add("screen_position", Vector{sprite.screenPosition({320.0, 480.0}).x, sprite.screenPosition({320.0, 480.0}).y},
        "px", "top-left corner in a 320 x 480 view (y down)");
  return r;
}

Result hourglassModel(const Args& a) {
  HourglassSettings s;
  const double grains = a.number("grain-count");
  if (!(grains >= 1.0 && grains <= 1e6 && grains == std::floor(grains))) {
    throwInvalid("grain-count", grains, "must be a whole number from 1 to 1000000");
  }
  s.grainCount = static_cast<int>(grains);
  s.neckWidth = a.number("neck-width");
  s.grainDiameter = a.number("grain-diameter");
  s.gravity = a.number("gravity");
  s.bulbWidth = a.number("bulb-width");
  s.bulbHeight = a.number("bulb-height");
  const double tilt = degToRad(requireFinite(a.number("tilt"), "tilt"));
  const double limit = a.number("max-time");
  if (!(limit > 0.0 && limit <= 600.0)) {
    throwInvalid("max-time", limit, "must be in (0, 600] s");
  }
  Hourglass hg(s, Bulb::top);
  // Upright with the sand settled in the top bulb, then held at the tilt, stepped at 1/60 s.
  const double frame = 1.0 / 60.0;
  const int n = hg.grainCount();
  double t20 = -1.0;
  double t80 = -1.0;
  double drained = -1.0;
  for (int i = 0; i < static_cast<int>(std::ceil(limit / frame)) && drained < 0.0; ++i) {
    hg.stepAtTilt(tilt, frame);
    const int moved = n - hg.grainsIn(Bulb::top);
    if (t20 < 0.0 && 5 * moved >= n) {
      t20 = hg.time();
    }
    if (t80 < 0.0 && 5 * moved >= 4 * n) {
      t80 = hg.time();
    }
    if (moved == n) {
      drained = hg.time();
    }
  }
  Result r;
  r.add("drained", drained >= 0.0, "", "the top bulb emptied within --max-time");
  if (drained >= 0.0) {
    r.add("drain_time", drained, "s", "until the last grain left the top bulb");
  }
  r.add("grains_left", static_cast<double>(hg.grainsIn(Bulb::top)), "", "in the top bulb at the end");
  if (t80 > t20 && t20 >= 0.0) {
    r.add("flow_rate", 0.6 * n / (t80 - t20), "grains/s", "from 20 % to 80 % drained: steady, unlike a liquid's");
  }
  const double beverloo = beverlooRate2d(s.neckWidth, s.grainDiameter, std::max(s.gravity, 1e-300), 1.0, 1.5);
  r.add("beverloo_rate", beverloo, "grains/s",
        "2D Beverloo, C = 1, k = 1.5, phi = 0.82: (phi/a) sqrt(g) (D - k d)^1.5");
  r.notes.emplace_back("The grains' contacts are soft (one pass per substep): the model drains about 4 to 7 times "
                       "faster than Beverloo's C = 1, and its rate grows about as D, not (D - k d)^1.5 "
                       "(docs/digital-physics.md).");
  return r;
}

} // namespace

void registerAccelerometerModels(Registry& registry) {
  registry.add({"tilt-angle",
                accelTopic,
                "single-axis tilt from a_x, a_y in [0, 360): the book's find2dAngle corrected",
                {{"ax", "g", "", std::string("-0.173648")}, {"ay", "g", "", std::string("0.984808")}},
                tiltAngleModel});
  registry.add({"tilt",
                accelTopic,
                "pitch and roll from a 3-axis reading, every quadrant; the gross orientation",
                {{"ax", "g", "", std::string("0.25")},
                 {"ay", "g", "", std::string("-0.4")},
                 {"az", "g", "", std::string("-0.88")},
                 {"convention", "", "specific-force (Android: face up z = +1) or gravity (iOS: face up z = -1)",
                  std::string("gravity"), ParamKind::text}},
                tiltModel});
  registry.add(
      {"accel-clip",
       accelTopic,
       "what a sensor with range +-R reports for a true acceleration (saturation)",
       {{"acceleration", "g", "true", std::string("3")}, {"range", "g", "sensor range (> 0)", std::string("2.3")}},
       clipModel});
  registry.add({"accel-calibration",
                accelTopic,
                "offset and scale of an axis from readings pointing up and down (+-1 g)",
                {{"reading-up", "g", "", std::string("1.08")},
                 {"reading-down", "g", "", std::string("-0.98")},
                 {"raw", "g", "a reading to correct", std::string("0.565")}},
                accelCalibration});
  registry.add({"sensor-filter",
                accelTopic,
                "first-order low-pass and high-pass filters: coefficients and gain at a frequency",
                {{"cutoff-hz", "Hz", "f_c, below Nyquist", std::string("5")},
                 {"sample-rate-hz", "Hz", "", std::string("100")},
                 {"frequency", "Hz", "where to evaluate the gain", std::string("5")}},
                filterModel});
  registry.add(
      {"tilt-sprite",
       accelTopic,
       "the book's tilt-controlled sprite under a constant tilt: friction, drag and screen edges",
       {{"ax", "g", "reading x", std::string("0.2")},
        {"ay", "g", "reading y", std::string("-0.1")},
        {"az", "g", "reading z", std::string("-0.97")},
        {"convention", "", "gravity (the book's iOS) or specific-force", std::string("gravity"), ParamKind::text},
        {"duration", "s", "", std::string("1")},
        {"time-step", "s", "the accelerometer interval (the book's 1/60)", std::string("0.0166666666667")},
        {"world-width", "m", "kWorldWidth", std::string("0.5")},
        {"world-height", "m", "kWorldHeight", std::string("0.75")},
        {"sprite-size", "m", "", std::string("0.05")},
        {"gravity", "m/s^2", "per g of reading (the book's 9.8)", std::string("9.8")},
        {"static-friction", "", "mu_s", std::string("0")},
        {"kinetic-friction", "", "mu_k", std::string("0")},
        {"drag", "1/s", "linear drag", std::string("0")},
        {"restitution", "", "at the edges (0: the book's stop)", std::string("0")}},
       spriteModel});
  registry.add(
      {"hourglass",
       accelTopic,
       "sand in an hourglass on the particle world: drain time and flow rate through the neck, tilted",
       {{"grain-count", "", "N sand grains, settled in the top bulb", std::string("300")},
        {"neck-width", "m", "D, the slot between the bulbs", std::string("0.008")},
        {"grain-diameter", "m", "d, the mean (sizes spread +-10 %)", std::string("0.002")},
        {"gravity", "m/s^2", "g", std::string("9.80665")},
        {"tilt", "deg", "the device turned counter-clockwise from upright (90: on its side)", std::string("0")},
        {"bulb-width", "m", "W", std::string("0.05")},
        {"bulb-height", "m", "H, neck to end (60-degree funnels)", std::string("0.06")},
        {"max-time", "s", "simulated at most", std::string("10")}},
       hourglassModel});
}

} // namespace impetus::cli::sensors_calc
