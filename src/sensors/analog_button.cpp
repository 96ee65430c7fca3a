#include <impetus/error.hpp>
#include <impetus/sensors/analog_button.hpp>

#include <algorithm>
#include <array>

namespace impetus::sensors {
namespace {

constexpr std::array<ButtonZone, 3> bookZones{{{"raise", 0, 127}, {"shoulder", 127, 250}, {"fire", 250, 256}}};

double requireFraction(double s, std::string_view field) {
  requireFinite(s, field);
  if (s < 0.0 || s > 1.0) {
    throwInvalid(field, s, "must be in [0, 1]");
  }
  return s;
}

} // namespace

double buttonDepression(int raw) {
  if (raw < 0 || raw > 255) {
    throwInvalid("raw", raw, "must be an 8-bit value, 0 to 255");
  }
  return raw / 255.0;
}

double depressionFromCurrent(double current, double maxCurrent) {
  requirePositive(maxCurrent, "maxCurrent");
  requireNonNegative(current, "current");
  if (current > maxCurrent) {
    throwInvalid("current", current, "must not exceed maxCurrent");
  }
  return current / maxCurrent;
}

std::span<const ButtonZone> bookButtonZones() noexcept { return bookZones; }

std::string_view buttonZone(int raw, std::span<const ButtonZone> zones) {
  if (raw < 0 || raw > 255) {
    throwInvalid("raw", raw, "must be an 8-bit value, 0 to 255");
  }
  for (const ButtonZone& z : zones) {
    if (raw >= z.lower && raw < z.upper) {
      return z.name;
    }
  }
  return {};
}

double ButtonDome::force(double depression) const {
  requireFraction(depression, "depression");
  requireNonNegative(stiffness, "stiffness");
  requireNonNegative(travel, "travel");
  return stiffness * depression * travel;
}

double ButtonDome::fingertipPressure(double depression) const {
  requirePositive(contactArea, "contactArea");
  return force(depression) / contactArea;
}

ButtonMash::ButtonMash(double window, double pressLevel, double releaseLevel)
    : window_(requirePositive(window, "window")), pressLevel_(requireFraction(pressLevel, "pressLevel")),
      releaseLevel_(requireFraction(releaseLevel, "releaseLevel")) {
  if (!(releaseLevel < pressLevel)) {
    throwInvalid("releaseLevel", releaseLevel, "must be below pressLevel (hysteresis)");
  }
}

bool ButtonMash::update(double time, double depression) {
  requireFinite(time, "time");
  requireFraction(depression, "depression");
  if (time < lastTime_) {
    throwInvalid("time", time, "must not go back");
  }
  lastTime_ = time;
  now_ = time;
  bool pressed = false;
  if (!down_ && depression >= pressLevel_) {
    down_ = true;
    pressed = true;
    ++total_;
    recent_.push_back({time, depression});
  } else if (down_ && depression <= releaseLevel_) {
    down_ = false;
  } else if (down_ && !recent_.empty()) {
    recent_.back().peak = std::max(recent_.back().peak, depression);
  }
  forget();
  return pressed;
}

void ButtonMash::forget() noexcept {
  while (!recent_.empty() && recent_.front().time <= now_ - window_) {
    recent_.pop_front();
  }
}

double ButtonMash::rate() const noexcept { return static_cast<double>(recent_.size()) / window_; }

double ButtonMash::meanPeakDepression() const noexcept {
  if (recent_.empty()) {
    return 0.0;
  }
  double sum = 0.0;
  for (const Press& p : recent_) {
    sum += p.peak;
  }
  return sum / static_cast<double>(recent_.size());
}

} // namespace impetus::sensors
