// The sensors layer (chapters 20, 21, 23, 25): touch screens, accelerometers, pressure sensors
// and load cells, optical tracking. Double precision, SI units, namespace impetus::sensors.
#pragma once

#include <impetus/sensors/accelerometer.hpp>
#include <impetus/sensors/analog_button.hpp>
#include <impetus/sensors/balance_board.hpp>
#include <impetus/sensors/barometer.hpp>
#include <impetus/sensors/depth_pressure.hpp>
#include <impetus/sensors/finite_difference.hpp>
#include <impetus/sensors/gestures.hpp>
#include <impetus/sensors/hourglass.hpp>
#include <impetus/sensors/load_cell.hpp>
#include <impetus/sensors/moving_average.hpp>
#include <impetus/sensors/optical_tracking.hpp>
#include <impetus/sensors/savitzky_golay.hpp>
#include <impetus/sensors/sensor_filters.hpp>
#include <impetus/sensors/tilt.hpp>
#include <impetus/sensors/tilt_sprite.hpp>
#include <impetus/sensors/touch_calibration.hpp>
#include <impetus/sensors/touch_capacitive.hpp>
#include <impetus/sensors/touch_explosion.hpp>
#include <impetus/sensors/touch_grid.hpp>
#include <impetus/sensors/touch_recording.hpp>
#include <impetus/sensors/touch_resistive.hpp>
#include <impetus/sensors/touch_tracker.hpp>
