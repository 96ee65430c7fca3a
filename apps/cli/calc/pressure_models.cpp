// `impetus calc` entries for pressure sensors, buttons and load cells (ch. 23): depth and
// barometric pressure, analog buttons, strain gauges, load cells, the balance board and moving
// averages.
#include "calc/sensors_models.hpp"
#include "calc/values.hpp"

#include <impetus/error.hpp>
#include <impetus/sensors/sensors.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace impetus::cli::sensors_calc {
namespace {

using namespace impetus::sensors;

constexpr const char* pressureTopic = "pressure sensors and load cells (ch. 23)";

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

} // namespace

void registerPressureModels(Registry& registry) {
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
}

} // namespace impetus::cli::sensors_calc
