#include <impetus/error.hpp>
#include <impetus/geo/gps_clock.hpp>

namespace impetus::geo {

double rangeFromTimeOfFlight(double transmitTime, double receiveTime, double speedOfLight) {
  requireFinite(transmitTime, "transmitTime");
  requireFinite(receiveTime, "receiveTime");
  requirePositive(speedOfLight, "speedOfLight");
  if (receiveTime < transmitTime) {
    throwInvalid("receiveTime", receiveTime, "must not be before transmitTime (a signal cannot arrive before it left)");
  }
  return speedOfLight * (receiveTime - transmitTime);
}

double rangeErrorFromClockError(double clockError, double speedOfLight) {
  requireFinite(clockError, "clockError");
  requirePositive(speedOfLight, "speedOfLight");
  return speedOfLight * clockError;
}

double clockErrorFromRangeError(double rangeError, double speedOfLight) {
  requireFinite(rangeError, "rangeError");
  requirePositive(speedOfLight, "speedOfLight");
  return rangeError / speedOfLight;
}

double accumulatedRangeError(double rate, double duration, double speedOfLight) {
  requireFinite(rate, "rate");
  requireNonNegative(duration, "duration");
  requirePositive(speedOfLight, "speedOfLight");
  return speedOfLight * rate * duration;
}

} // namespace impetus::geo
