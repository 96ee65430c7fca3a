// `impetus calc` entries for optical tracking (ch. 25): finite differences, Savitzky-Golay
// coefficients and depth from disparity.
#include "calc/sensors_models.hpp"

#include <impetus/sensors/sensors.hpp>

#include <string>
#include <vector>

namespace impetus::cli::sensors_calc {
namespace {

using namespace impetus::sensors;

constexpr const char* trackingTopic = "optical tracking (ch. 25)";

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

void registerTrackingModels(Registry& registry) {
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

} // namespace impetus::cli::sensors_calc
