// `impetus calc` entries for touch screens (ch. 20): resistive and capacitive panels, the
// projected-capacitive grid, calibration, gestures and the touch explosion.
#include "calc/sensors_models.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/sensors/sensors.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace impetus::cli::sensors_calc {
namespace {

using namespace impetus::sensors;

constexpr const char* touchTopic = "touch screens (ch. 20)";

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
      deltas.push_back(parseParameter("deltas", token));
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

} // namespace

void registerTouchModels(Registry& registry) {
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
}

} // namespace impetus::cli::sensors_calc
