// Shared by the sensors layer's `impetus calc` entries, one file per topic: touch screens
// (touch_models.cpp), accelerometers (accelerometer_models.cpp), pressure sensors, buttons and
// load cells (pressure_models.cpp), optical tracking (tracking_models.cpp).
#pragma once

#include "calc/calc.hpp"

#include <impetus/math/vec2.hpp>

#include <string>
#include <vector>

namespace impetus::cli::sensors_calc {

/// Numbers separated by commas, spaces or semicolons.
[[nodiscard]] std::vector<double> numberList(const Args& a, const std::string& name);

/// Points "x,y x,y ...".
[[nodiscard]] std::vector<Vec2d> pointList(const Args& a, const std::string& name);

void registerTouchModels(Registry& registry);
void registerAccelerometerModels(Registry& registry);
void registerPressureModels(Registry& registry);
void registerTrackingModels(Registry& registry);

} // namespace impetus::cli::sensors_calc
