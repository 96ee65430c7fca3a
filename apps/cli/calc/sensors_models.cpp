// `impetus calc` entries for the sensors layer: touch screens (ch. 20), accelerometers (ch. 21),
// pressure sensors, buttons and load cells (ch. 23) and optical tracking (ch. 25), one file per
// topic (sensors_models.hpp); here the list parsing they share and the registration in order.
#include "calc/sensors_models.hpp"

#include <impetus/error.hpp>

#include <algorithm>
#include <sstream>

namespace impetus::cli {
namespace sensors_calc {

std::vector<double> numberList(const Args& a, const std::string& name) {
  std::string text = a.text(name);
  std::replace(text.begin(), text.end(), ',', ' ');
  std::replace(text.begin(), text.end(), ';', ' ');
  std::istringstream in(text);
  std::vector<double> values;
  for (std::string token; in >> token;) {
    values.push_back(requireFinite(parseParameter(name, token), name));
  }
  return values;
}

std::vector<Vec2d> pointList(const Args& a, const std::string& name) {
  std::istringstream in(a.text(name));
  std::vector<Vec2d> points;
  for (std::string token; in >> token;) {
    const std::size_t comma = token.find(',');
    if (comma == std::string::npos) {
      throw Error(name, "--" + name + ": '" + token + "' is not x,y");
    }
    points.push_back({requireFinite(parseParameter(name, token.substr(0, comma)), name),
                      requireFinite(parseParameter(name, token.substr(comma + 1)), name)});
  }
  return points;
}

} // namespace sensors_calc

void registerSensorsModels(Registry& registry) {
  sensors_calc::registerTouchModels(registry);
  sensors_calc::registerAccelerometerModels(registry);
  sensors_calc::registerPressureModels(registry);
  sensors_calc::registerTrackingModels(registry);
}

} // namespace impetus::cli
