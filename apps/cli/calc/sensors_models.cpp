// `impetus calc` entries for the sensors layer: touch screens (ch. 20), accelerometers (ch. 21),
// pressure sensors, buttons and load cells (ch. 23) and optical tracking (ch. 25).
#include "calc/calc.hpp"
#include "calc/values.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/sensors/sensors.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace impetus::cli {
namespace {

using namespace impetus::sensors;

constexpr const char* touchTopic = "touch screens (ch. 20)";
constexpr const char* accelTopic = "accelerometers (ch. 21)";
constexpr const char* pressureTopic = "pressure sensors and load cells (ch. 23)";
constexpr const char* trackingTopic = "optical tracking (ch. 25)";

/// Numbers separated by commas, spaces or semicolons.
std::vector<double> numberList(const Args& a, const std::string& name) {
  std::string text = a.text(name);
  std::replace(text.begin(), text.end(), ',', ' ');
  std::replace(text.begin(), text.end(), ';', ' ');
  std::istringstream in(text);
  std::vector<double> values;
  for (std::string token; in >> token;) {
    values.push_back(requireFinite(parseNumber(name, token), name));
  }
  return values;
}

/// Points "x,y x,y ...".
std::vector<Vec2d> pointList(const Args& a, const std::string& name) {
  std::istringstream in(a.text(name));
  std::vector<Vec2d> points;
  for (std::string token; in >> token;) {
    const std::size_t comma = token.find(',');
    if (comma == std::string::npos) {
      throw Error(name, "--" + name + ": '" + token + "' is not x,y");
    }
    points.push_back({requireFinite(parseNumber(name, token.substr(0, comma)), name),
                      requireFinite(parseNumber(name, token.substr(comma + 1)), name)});
  }
  return points;
}

// ---- Touch ---------------------------------------------------------------------------------------

Result fourWire(const Args& a) {
  FourWirePanel panel;
  const double vref = requirePositive(a.number("reference-volts"), "referenceVolts");
  panel.x = {requirePositive(a.number("width"), "width"), 0.0, vref};
  panel.y = {requirePositive(a.number("height"), "height"), 0.0, vref};
  panel.xPlateOhms = a.number("x-plate-ohms");
  panel.referenceVolts = vref;
  const TouchPoint p =
      readFourWire(panel, {requireFinite(a.number("voltage-x"), "voltageX"),
                           requireFinite(a.number("voltage-y"), "voltageY"), a.number("z1"), a.number("z2")});
  Result r;
  r.add("x", p.position.x, "m", "x = W V_x / V_ref, from the X- bar");
  r.add("y", p.position.y, "m", "y = H V_y / V_ref, from the Y- bar");
  r.add("touched", p.touchOhms.has_value(), "", "Z1 > 0: the sheets are in contact");
  if (p.touchOhms) {
    r.add("touch_resistance", *p.touchOhms, "ohm", "R_x-plate (x/W)(Z2/Z1 - 1): falls as the press hardens");
  }
  return r;
}

Result fiveWire(const Args& a) {
  FiveWirePanel panel;
  const double vref = requirePositive(a.number("reference-volts"), "referenceVolts");
  panel.x = {requirePositive(a.number("width"), "width"), 0.0, vref};
  panel.y = {requirePositive(a.number("height"), "height"), 0.0, vref};
  panel.pullupOhms = a.number("pullup-ohms");
  panel.referenceVolts = vref;
  const TouchPoint p = readFiveWire(panel, {requireFinite(a.number("voltage-x"), "voltageX"),
                                            requireFinite(a.number("voltage-y"), "voltageY"), a.number("wiper")});
  Result r;
  r.add("x", p.position.x, "m", "the wiper's voltage with the right corners driven");
  r.add("y", p.position.y, "m", "the wiper's voltage with the upper corners driven");
  r.add("touched", p.touchOhms.has_value(), "", "the wiper is pulled below V_ref");
  if (p.touchOhms) {
    r.add("contact_resistance", *p.touchOhms, "ohm", "R_pullup V_w / (V_ref - V_w)");
  }
  return r;
}

Result surfaceCapacitive(const Args& a) {
  const CornerCurrents c{a.number("upper-left"), a.number("upper-right"), a.number("lower-left"),
                         a.number("lower-right")};
  const auto p = surfaceCapacitivePosition(c, a.number("width"), a.number("height"));
  Result r;
  r.add("touched", p.has_value(), "", "any current drawn");
  if (p) {
    r.add("x", p->x, "m", "W (I_UR + I_LR) / I");
    r.add("y", p->y, "m", "H (I_UL + I_UR) / I");
  }
  r.add("total_current", c.upperLeft + c.upperRight + c.lowerLeft + c.lowerRight, "A");
  return r;
}

Result grid(const Args& a) {
  // Rows separated by ';', values within a row by spaces or commas.
  std::vector<double> deltas;
  int rows = 0;
  int columns = -1;
  std::istringstream rowsIn(a.text("deltas"));
  for (std::string row; std::getline(rowsIn, row, ';');) {
    std::replace(row.begin(), row.end(), ',', ' ');
    std::istringstream in(row);
    int n = 0;
    for (std::string token; in >> token; ++n) {
      deltas.push_back(parseNumber("deltas", token));
    }
    if (n == 0) {
      continue;
    }
    if (columns >= 0 && n != columns) {
      throwInvalid("deltas", n, "rows must all have the same number of values");
    }
    columns = n;
    ++rows;
  }
  if (rows == 0) {
    throwInvalid("deltas", 0.0, "needs at least one row");
  }
  GridGeometry g;
  g.rows = rows;
  g.columns = columns;
  g.pitchX = g.pitchY = requirePositive(a.number("pitch"), "pitch");
  const std::vector<GridTouch> touches = findGridTouches(deltas, g, a.number("threshold"));
  Result r;
  r.add("touches", static_cast<double>(touches.size()), "", "blobs above the threshold, split at dips");
  Matrix m;
  for (const GridTouch& t : touches) {
    m.push_back({t.position.x, t.position.y, t.signal, static_cast<double>(t.cells)});
  }
  r.add("positions", m, "m", "x, y (from the corner of cell 0,0), signal, cells: strongest first");
  r.notes.emplace_back("weights DeltaC - threshold (a cell entering the blob carries no weight: no jumps)");
  return r;
}

Result calibration(const Args& a) {
  const std::vector<Vec2d> raw = pointList(a, "raw");
  const std::vector<Vec2d> screen = pointList(a, "screen");
  const TouchCalibration c = TouchCalibration::fit(raw, screen);
  const auto k = c.coefficients();
  const std::vector<Vec2d> point = pointList(a, "point");
  if (point.size() != 1) {
    throwInvalid("point", static_cast<double>(point.size()), "must be one x,y");
  }
  Result r;
  r.add("x_row", Vector{k[0], k[1], k[2]}, "", "a, b, c: x_s = a x_r + b y_r + c");
  r.add("y_row", Vector{k[3], k[4], k[5]}, "", "d, e, f: y_s = d x_r + e y_r + f");
  const Vec2d mapped = c.apply(point[0]);
  r.add("mapped", Vector{mapped.x, mapped.y}, "px", "--point through the map");
  double worst = 0.0;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    worst = std::max(worst, distance(c.apply(raw[i]), screen[i]));
  }
  r.add("largest_residual", worst, "px", "0 for three touches; the finger's scatter for more");
  return r;
}

Result gestures(const Args& a) {
  const std::vector<TouchFrame> frames = parseTouchRecording(a.text("recording"));
  TouchTracker tracker(a.number("max-jump"));
  GestureRecognizer recognizer({a.number("tap-max-duration"), a.number("slop"), a.number("pinch-threshold"),
                                degToRad(a.number("rotate-threshold"))});
  int taps = 0, drags = 0, pinches = 0, rotations = 0;
  double scale = 1.0, rotation = 0.0;
  std::string log;
  for (const TouchFrame& f : frames) {
    for (const GestureEvent& e : recognizer.update(f.time, tracker.update(f.time, f.points))) {
      if (e.phase != GesturePhase::changed) {
        log += fmt::format("{}{} {} t={:g} at ({:g}, {:g})", log.empty() ? "" : "; ", gestureKindName(e.kind),
                           gesturePhaseName(e.phase), e.time, e.position.x, e.position.y);
        if (e.kind == GestureKind::pinch) {
          log += fmt::format(" scale {:.4g}", e.scale);
        } else if (e.kind == GestureKind::rotate) {
          log += fmt::format(" {:.4g} deg", radToDeg(e.rotation));
        } else if (e.kind == GestureKind::drag) {
          log += fmt::format(" moved ({:g}, {:g})", e.translation.x, e.translation.y);
        }
      }
      if (e.phase == GesturePhase::began || e.kind == GestureKind::tap) {
        taps += e.kind == GestureKind::tap ? 1 : 0;
        drags += e.kind == GestureKind::drag ? 1 : 0;
        pinches += e.kind == GestureKind::pinch ? 1 : 0;
        rotations += e.kind == GestureKind::rotate ? 1 : 0;
      }
      if (e.kind == GestureKind::pinch) {
        scale = e.scale;
      }
      if (e.kind == GestureKind::rotate) {
        rotation = e.rotation;
      }
    }
  }
  Result r;
  r.add("frames", static_cast<double>(frames.size()), "");
  r.add("taps", static_cast<double>(taps), "");
  r.add("drags", static_cast<double>(drags), "");
  r.add("pinches", static_cast<double>(pinches), "");
  r.add("rotations", static_cast<double>(rotations), "");
  r.add("last_scale", scale, "", "the last pinch's d / d0");
  r.add("last_rotation", radToDeg(rotation), "deg", "the last rotation, counter-clockwise in y-up axes");
  r.add("events", log.empty() ? std::string("none") : log, "", "began and ended events (changed left out)");
  return r;
}

Result touchExplosion(const Args& a) {
  const std::vector<TouchFrame> frames = parseTouchRecording(a.text("recording"));
  TouchExplosionSettings s;
  s.screen = {a.number("screen-height"), a.number("pixels-per-metre")};
  s.explosion.speed = a.number("speed");
  s.explosion.life = a.number("life");
  s.explosion.gravity = a.number("gravity");
  const double multitouch = a.number("multitouch");
  if (multitouch != 0.0 && multitouch != 1.0) {
    throwInvalid("multitouch", multitouch, "must be 0 or 1");
  }
  s.multitouch = multitouch == 1.0;
  TouchExplosions demo(s);
  Matrix origins;
  for (const TouchFrame& f : frames) {
    const std::size_t before = demo.burstCount();
    demo.update(f.time, f.points);
    for (std::size_t k = demo.bursts().size() - (demo.burstCount() - before); k < demo.bursts().size(); ++k) {
      const TouchBurst& b = demo.bursts()[k];
      origins.push_back({b.start, b.explosion.origin().x, b.explosion.origin().y, static_cast<double>(b.touchId)});
    }
  }
  const double end = frames.empty() ? 0.0 : frames.back().time;
  Result r;
  r.add("bursts", static_cast<double>(demo.burstCount()), "", "one per finger that touched down");
  if (!origins.empty()) {
    r.add("origins", origins, "s, m, m, id", "start time, world x, y (y up), touch id");
  }
  r.add("alive_at_end", static_cast<double>(demo.aliveParticles(end)), "", "particles alive at the last frame");
  return r;
}

// ---- Accelerometers ------------------------------------------------------------------------------

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

// ---- Pressure, buttons, load cells -----------------------------------------------------------------

Result depthModel(const Args& a) {
  const DepthPressure p = depthPressure(a.number("depth"), a.number("density"), a.number("gravity"),
                                        a.number("surface-pressure"), a.number("internal-pressure"));
  Result r;
  r.add("gauge", p.gauge, "Pa", "rho g h");
  r.add("absolute", p.absolute, "Pa", "P_surface + rho g h");
  r.add("differential", p.differential, "Pa", "absolute - internal: the net push on a sealed hull");
  r.add("atmospheres", p.gauge / 101'325.0, "atm", "gauge over 101,325 Pa");
  r.add("force_per_cm2", p.differential * 1e-4, "N", "on each square centimetre of the hull");
  return r;
}

Result altitudeModel(const Args& a) {
  const double p = a.number("pressure");
  const double p0 = a.number("sea-level-pressure");
  Result r;
  r.add("altitude", barometricAltitude(p, p0), "m", "ISA: (T0/L)(1 - (p/p0)^(R L/(g M))), isothermal above 11 km");
  r.add("android_altitude", androidAltitude(p0, p), "m", "44330 (1 - (p/p0)^(1/5.255))");
  r.add("standard_pressure_here", pressureAtAltitude(barometricAltitude(p, p0)), "Pa",
        "the standard atmosphere's pressure at that altitude (p0 = 101,325 Pa)");
  return r;
}

Result altitudeDifferenceModel(const Args& a) {
  const double p1 = a.number("pressure1");
  const double p2 = a.number("pressure2");
  const double p0 = a.number("sea-level-pressure");
  Result r;
  r.add("difference", altitudeDifference(p1, p2, p0), "m", "h(p2) - h(p1): up is positive");
  r.add("android_difference", androidAltitude(p0, p2) - androidAltitude(p0, p1), "m",
        "getAltitude(p0, p2) - getAltitude(p0, p1)");
  return r;
}

Result buttonModel(const Args& a) {
  const double raw = a.number("raw");
  if (!(raw == std::floor(raw) && raw >= 0.0 && raw <= 255.0)) {
    throwInvalid("raw", raw, "must be a whole number 0 to 255");
  }
  const int value = static_cast<int>(raw);
  const ButtonDome dome{a.number("stiffness"), a.number("travel"), a.number("contact-area")};
  const double s = buttonDepression(value);
  Result r;
  r.add("depression", s, "", "raw / 255");
  r.add("zone", std::string(buttonZone(value)), "", "the book's zones, half-open: [0,127) [127,250) [250,255]");
  r.add("force", dome.force(s), "N", "F = k s d");
  r.add("fingertip_pressure", dome.fingertipPressure(s), "Pa", "P = F / A");
  return r;
}

Result mashModel(const Args& a) {
  const std::vector<double> v = numberList(a, "samples");
  if (v.size() % 2 != 0 || v.empty()) {
    throwInvalid("samples", static_cast<double>(v.size()), "must be pairs time,depression");
  }
  ButtonMash mash(a.number("window"), a.number("press-level"), a.number("release-level"));
  const ButtonDome dome{a.number("stiffness"), a.number("travel"), a.number("contact-area")};
  for (std::size_t i = 0; i < v.size(); i += 2) {
    mash.update(v[i], v[i + 1]);
  }
  Result r;
  r.add("presses", static_cast<double>(mash.presses()), "", "rising through the press level after a release");
  r.add("rate", mash.rate(), "Hz", "presses in the last window / window");
  r.add("mean_peak_depression", mash.meanPeakDepression(), "", "how hard, on average, in the window");
  r.add("mean_peak_force", dome.force(mash.meanPeakDepression()), "N", "k s d");
  r.add("mean_peak_pressure", dome.fingertipPressure(mash.meanPeakDepression()), "Pa", "F / A on the fingertip");
  return r;
}

BridgeKind bridgeKind(const Args& a) {
  const std::string& k = a.text("bridge");
  if (k == "quarter") {
    return BridgeKind::quarter;
  }
  if (k == "half") {
    return BridgeKind::half;
  }
  if (k == "full") {
    return BridgeKind::full;
  }
  throw Error("bridge", "--bridge = '" + k + "': must be quarter, half or full");
}

Result bridgeModel(const Args& a) {
  const double strain = a.number("strain");
  const double gf = a.number("gauge-factor");
  const double vex = requirePositive(a.number("excitation"), "excitation");
  const double ratio = bridgeOutputRatio(strain, gf, bridgeKind(a));
  Result r;
  r.add("output_ratio", ratio, "V/V", "quarter GF e/(4 + 2 GF e), half GF e/2, full GF e");
  r.add("output", ratio * vex, "V");
  r.add("resistance_change", gf * strain, "", "dR / R = GF e");
  r.add("stress", requirePositive(a.number("youngs-modulus"), "youngsModulus") * strain, "Pa",
        "sigma = E e (linear region)");
  return r;
}

Result loadCellModel(const Args& a) {
  LoadCell cell;
  cell.capacity = a.number("capacity");
  cell.ratedOutput = a.number("rated-output") * 1e-3;
  cell.excitation = a.number("excitation");
  cell.zeroBalance = a.number("zero-balance") * 1e-3;
  const double f = cell.force(a.number("output-volts"));
  Result r;
  r.add("force", f, "N", "capacity (V_out/V_ex - zero) / rated output");
  r.add("mass", f / requirePositive(a.number("gravity"), "gravity"), "kg", "F / g");
  r.add("overloaded", cell.overloaded(f), "", "beyond the rated capacity");
  r.add("full_scale_output", cell.outputVolts(cell.capacity), "V");
  return r;
}

Result boardModel(const Args& a) {
  const std::vector<double> loads = numberList(a, "loads");
  if (loads.size() != 4) {
    throwInvalid("loads", static_cast<double>(loads.size()),
                 "must be four: top right, top left, bottom left, bottom right");
  }
  const auto cog = boardCentreOfGravity({loads[0], loads[1], loads[2], loads[3]});
  Result r;
  const double total = loads[0] + loads[1] + loads[2] + loads[3];
  r.add("total", total, "", "in the loads' unit");
  r.add("on_board", cog.has_value(), "", "total > 0");
  if (cog) {
    r.add("cog_x", cog->x, "", "sum W x / sum W, cells at x = +-1");
    r.add("cog_y", cog->y, "", "sum W y / sum W, cells at y = +-1");
  }
  if (const std::optional<double> weight = optionalNumber(a, "body-weight")) {
    requirePositive(*weight, "bodyWeight");
    const std::string_view motion = classifyMotion(total / *weight, cog ? cog->x : 0.0);
    r.add("load_ratio", total / *weight, "", "total / body weight");
    r.add("motion", motion.empty() ? std::string("none") : std::string(motion), "", "Table 23-3, first match");
  }
  return r;
}

Result averageModel(const Args& a) {
  const std::vector<double> values = numberList(a, "values");
  if (values.empty()) {
    throwInvalid("values", 0.0, "needs at least one value");
  }
  const double n = a.number("length");
  if (!(n >= 1.0 && n <= 100000.0 && n == std::floor(n))) {
    throwInvalid("length", n, "must be a whole number 1 to 100000");
  }
  const std::string& kind = a.text("weights");
  const auto length = static_cast<std::size_t>(n);
  WeightedMovingAverage wma = kind == "linear" ? WeightedMovingAverage::linear(length)
                              : kind == "simple"
                                  ? WeightedMovingAverage::simple(length)
                                  : throw Error("weights", "--weights = '" + kind + "': must be linear or simple");
  Vector out;
  for (const double v : values) {
    out.push_back(wma.update(v));
  }
  Result r;
  r.add("averages", out, "", "after each value");
  r.add("last", out.back(), "");
  r.add("ramp_lag", wma.rampLag(), "samples", "linear (N-1)/3, simple (N-1)/2");
  return r;
}

// ---- Optical tracking ----------------------------------------------------------------------------

Result differenceModel(const Args& a) {
  const std::vector<double> x = numberList(a, "samples");
  if (x.size() != 3) {
    throwInvalid("samples", static_cast<double>(x.size()), "must be three: x(t - h), x(t), x(t + h)");
  }
  const double h = a.number("step");
  requirePositive(h, "step");
  Result r;
  r.add("backward", backwardDifference(x[0], x[1], h), "/s", "(x_i - x_{i-1}) / h, O(h)");
  r.add("forward", forwardDifference(x[1], x[2], h), "/s", "(x_{i+1} - x_i) / h, O(h)");
  r.add("central", centralDifference(x[0], x[2], h), "/s", "(x_{i+1} - x_{i-1}) / 2h, O(h^2)");
  r.add("second", secondDifference(x[0], x[1], x[2], h), "/s^2", "(x_{i+1} - 2x_i + x_{i-1}) / h^2, O(h^2)");
  r.add("book_findAcceleration", bookFindAcceleration(x[0], x[1], x[2], h), "/s",
        "the book's: the same over h, not h^2");
  return r;
}

Result sgModel(const Args& a) {
  const auto whole = [&](const char* name) {
    const double v = a.number(name);
    if (!(v == std::floor(v) && std::abs(v) < 1e6)) {
      throwInvalid(name, v, "must be a whole number");
    }
    return static_cast<int>(v);
  };
  const SavitzkyGolay sg(whole("half-width"), whole("order"), whole("derivative"));
  const auto c = sg.coefficients();
  double norm2 = 0.0;
  for (const double v : c) {
    norm2 += v * v;
  }
  Result r;
  r.add("coefficients", Vector(c.begin(), c.end()), "", "c_k, k = -m..m: sum c_k x_{i+k} / h^d");
  const std::vector<double> last = sg.atOffset(sg.halfWidth());
  r.add("newest_coefficients", Vector(last.begin(), last.end()), "", "the same fit at the newest sample (real time)");
  r.add("noise_gain", std::sqrt(norm2), "", "output noise / (input noise / h^d)");
  return r;
}

Result disparityModel(const Args& a) {
  Result r;
  r.add("depth", depthFromDisparity(a.number("focal-pixels"), a.number("baseline"), a.number("disparity")), "m",
        "Z = f B / d");
  return r;
}

} // namespace

void registerSensorsModels(Registry& registry) {
  registry.add({"touch-4wire",
                touchTopic,
                "4-wire resistive panel: position from V_x, V_y and the contact resistance from Z1, Z2",
                {{"voltage-x", "V", "probe voltage with the X sheet driven", std::string("0.825")},
                 {"voltage-y", "V", "probe voltage with the Y sheet driven", std::string("2.64")},
                 {"z1", "V", "X+ with Y+ driven and X- grounded (0: no pressure reading)", std::string("0.853448")},
                 {"z2", "V", "Y- in the same state", std::string("2.844828")},
                 {"width", "m", "active width", std::string("0.2")},
                 {"height", "m", "active height", std::string("0.15")},
                 {"x-plate-ohms", "ohm", "X sheet, end to end", std::string("600")},
                 {"reference-volts", "V", "V_ref", std::string("3.3")}},
                fourWire});
  registry.add({"touch-5wire",
                touchTopic,
                "5-wire resistive panel: position from the wiper, contact resistance from the pull-up divider",
                {{"voltage-x", "V", "wiper voltage, right corners at V_ref", std::string("1.5")},
                 {"voltage-y", "V", "wiper voltage, upper corners at V_ref", std::string("3.75")},
                 {"wiper", "V", "wiper with the corners grounded and the pull-up on", std::string("0.1220")},
                 {"pullup-ohms", "ohm", "R_pullup", std::string("47000")},
                 {"width", "m", "active width", std::string("0.3")},
                 {"height", "m", "active height", std::string("0.2")},
                 {"reference-volts", "V", "V_ref", std::string("5")}},
                fiveWire});
  registry.add({"touch-capacitive",
                touchTopic,
                "surface-capacitive panel: position from the four corner currents, x = W (I_UR + I_LR)/I",
                {{"upper-left", "A", "", std::string("1e-6")},
                 {"upper-right", "A", "", std::string("3e-6")},
                 {"lower-left", "A", "", std::string("1e-6")},
                 {"lower-right", "A", "", std::string("3e-6")},
                 {"width", "m", "", std::string("0.3")},
                 {"height", "m", "", std::string("0.2")}},
                surfaceCapacitive});
  registry.add({"touch-grid",
                touchTopic,
                "projected-capacitive scan to touches: weighted centroids between the electrodes",
                {{"deltas", "", "DeltaC per cell: rows separated by ';'",
                  std::string("0 1 2 1 0; 1 6 12 5 0; 2 12 20 9 1; 1 5 9 4 0; 0 0 1 0 0"), ParamKind::text},
                 {"pitch", "m", "electrode spacing", std::string("0.005")},
                 {"threshold", "", "DeltaC that counts as touched", std::string("1.5")}},
                grid});
  registry.add(
      {"touch-calibration",
       touchTopic,
       "affine calibration from reference touches (3 exact, more by least squares)",
       {{"raw", "", "raw points x,y x,y x,y ...", std::string("400,350 3700,2000 1900,3800"), ParamKind::text},
        {"screen", "px", "where they should land", std::string("92,34.5 752,232.5 392,448.5"), ParamKind::text},
        {"point", "", "a raw point to map", std::string("2048,2048"), ParamKind::text}},
       calibration});
  registry.add({"touch-gestures",
                touchTopic,
                "recorded touches (TIME: X,Y X,Y; ...) to tap, drag, pinch and rotate gestures",
                {{"recording", "px", "frames 'TIME: X,Y X,Y ...' separated by ';' (TIME in s)",
                  std::string("0: 100,200; 0.1: 101,200; 0.15:; 0.5: 200,300 300,300; 0.6: 190,300 310,300; "
                              "0.7: 180,300 320,300; 0.8:"),
                  ParamKind::text},
                 {"max-jump", "px", "farthest a finger moves between frames", std::string("60")},
                 {"tap-max-duration", "s", "longest tap", std::string("0.3")},
                 {"slop", "px", "wander still allowed for a tap", std::string("10")},
                 {"pinch-threshold", "", "relative change of distance that starts a pinch", std::string("0.05")},
                 {"rotate-threshold", "deg", "turn that starts a rotation", std::string("5")}},
                gestures});
  registry.add({"touch-explosion",
                touchTopic,
                "the book's touch explosion: each finger that touches sets off a particle explosion there",
                {{"recording", "px", "frames 'TIME: X,Y X,Y ...' separated by ';' (screen pixels, y down)",
                  std::string("0: 160,240; 0.1:; 0.5: 60,400 260,80; 0.6:"), ParamKind::text},
                 {"screen-height", "px", "", std::string("480")},
                 {"pixels-per-metre", "px/m", "", std::string("20")},
                 {"speed", "m/s", "strength: particles leave at [v/2, v]", std::string("10")},
                 {"life", "s", "particles live [0.8, 1] x life", std::string("2")},
                 {"gravity", "m/s^2", "vertical acceleration (negative pulls down)", std::string("-9.81")},
                 {"multitouch", "", "1: one burst per finger; 0: the book's single-touch version", std::string("1")}},
                touchExplosion});

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

  registry.add({"depth-pressure",
                pressureTopic,
                "pressure at depth and on a sealed hull: the book's steel ball in the Mariana trench",
                {{"depth", "m", "", std::string("10900")},
                 {"density", "kg/m^3", "sea water", std::string("1025")},
                 {"gravity", "m/s^2", "", std::string("9.81")},
                 {"surface-pressure", "Pa", "", std::string("101000")},
                 {"internal-pressure", "Pa", "what the hull was sealed at", std::string("101000")}},
                depthModel});
  registry.add({"barometric-altitude",
                pressureTopic,
                "altitude from air pressure, standard atmosphere (and Android's getAltitude)",
                {{"pressure", "Pa", "", std::string("100000")},
                 {"sea-level-pressure", "Pa", "p0 (a weather station's, or 101325)", std::string("101325")}},
                altitudeModel});
  registry.add({"altitude-difference",
                pressureTopic,
                "height between two barometer readings with the same p0",
                {{"pressure1", "Pa", "", std::string("100000")},
                 {"pressure2", "Pa", "", std::string("99000")},
                 {"sea-level-pressure", "Pa", "", std::string("101325")}},
                altitudeDifferenceModel});
  registry.add({"analog-button",
                pressureTopic,
                "pressure-sensitive button: depression, the book's zones, force and fingertip pressure",
                {{"raw", "", "8-bit reading 0-255", std::string("200")},
                 {"stiffness", "N/m", "dome", std::string("2000")},
                 {"travel", "m", "full travel", std::string("0.001")},
                 {"contact-area", "m^2", "fingertip", std::string("1e-4")}},
                buttonModel});
  registry.add(
      {"button-mash",
       pressureTopic,
       "button mashing: presses per second and how hard, from depression samples",
       {{"samples", "", "pairs time,depression (s, 0-1)",
         std::string("0,0 0.05,0.9 0.1,0.1 0.15,0.95 0.2,0.05 0.25,0.8 0.3,0.2 0.35,0.9 0.4,0"), ParamKind::text},
        {"window", "s", "rate window", std::string("0.5")},
        {"press-level", "", "depression that counts as pressed", std::string("0.6")},
        {"release-level", "", "depression that counts as released", std::string("0.4")},
        {"stiffness", "N/m", "dome", std::string("2000")},
        {"travel", "m", "full travel", std::string("0.001")},
        {"contact-area", "m^2", "fingertip", std::string("1e-4")}},
       mashModel});
  registry.add({"strain-bridge",
                pressureTopic,
                "strain gauge in a Wheatstone bridge: output voltage for a strain",
                {{"strain", "", "engineering strain dL/L", std::string("1e-3")},
                 {"gauge-factor", "", "GF", std::string("2.1")},
                 {"bridge", "", "quarter, half or full", std::string("full"), ParamKind::text},
                 {"excitation", "V", "", std::string("5")},
                 {"youngs-modulus", "Pa", "E of the beam (steel 200e9)", std::string("200e9")}},
                bridgeModel});
  registry.add({"load-cell",
                pressureTopic,
                "load cell: force from the bridge voltage, F = capacity (V/V_ex - zero)/rated output",
                {{"output-volts", "V", "", std::string("0.005")},
                 {"capacity", "N", "rated capacity", std::string("500")},
                 {"rated-output", "mV/V", "at capacity", std::string("2")},
                 {"excitation", "V", "", std::string("5")},
                 {"zero-balance", "mV/V", "tare", std::string("0")},
                 {"gravity", "m/s^2", "to show the mass", std::string("9.80665")}},
                loadCellModel});
  registry.add(
      {"balance-board",
       pressureTopic,
       "four-cell balance board: centre of gravity (the book's 0.30, -0.10) and Table 23-3's motion",
       {{"loads", "", "top right, top left, bottom left, bottom right", std::string("30,15,20,35"), ParamKind::text},
        optionalParam("body-weight", "", "the player's weight, same unit: classifies the motion")},
       boardModel});
  registry.add({"moving-average",
                pressureTopic,
                "weighted moving average of a sequence (linear: newest heaviest, or simple)",
                {{"values", "", "the samples", std::string("1 2 3 4 5 6 7 8"), ParamKind::text},
                 {"length", "", "N samples in the window", std::string("4")},
                 {"weights", "", "linear or simple", std::string("linear"), ParamKind::text}},
                averageModel});

  registry.add({"finite-difference",
                trackingTopic,
                "velocity and acceleration from three samples: backward, forward, central, second difference",
                {{"samples", "", "x(t - h), x(t), x(t + h)", std::string("4.578777777777778,4.9,5.232111111111111"),
                  ParamKind::text},
                 {"step", "s", "h", std::string("0.0333333333333333")}},
                differenceModel});
  registry.add({"savitzky-golay",
                trackingTopic,
                "Savitzky-Golay smoothing differentiator coefficients (window 2m+1, degree p, derivative d)",
                {{"half-width", "", "m", std::string("2")},
                 {"order", "", "p", std::string("2")},
                 {"derivative", "", "d", std::string("1")}},
                sgModel});
  registry.add({"depth-from-disparity",
                trackingTopic,
                "depth of a point seen by two rectified cameras: Z = f B / d",
                {{"focal-pixels", "px", "f", std::string("525")},
                 {"baseline", "m", "B", std::string("0.075")},
                 {"disparity", "px", "d", std::string("10")}},
                disparityModel});
}

} // namespace impetus::cli
