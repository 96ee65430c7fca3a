// How sound travels and weakens (ch. 26): the speed of sound in air against temperature,
// intensity and decibels, the inverse-square law, OpenAL's distance models, flash-to-bang.
//
// A point source radiating a constant acoustic power P (W) spreads it over spheres:
// intensity I = P / (4 pi r^2) (W/m^2) falls as 1/r^2, so the pressure *amplitude* (I ~ p^2)
// falls as 1/r: -6.02 dB per doubling of distance, -20 dB per factor 10. (The book says the
// amplitude falls as 1/r^2: that is the intensity.) Levels: L = 10 log10(I / I0) dB with
// I0 = 1e-12 W/m^2 (the threshold of hearing), or 20 log10(p / p0) with p0 = 20 uPa rms.
// Perceived loudness roughly doubles per +10 dB.
#pragma once

#include <impetus/audio/waves.hpp>

#include <limits>

namespace impetus::audio {

/// I0, W/m^2: 0 dB intensity level.
inline constexpr double referenceIntensity = 1e-12;
/// p0, Pa (rms): 0 dB sound pressure level in air.
inline constexpr double referencePressure = 20e-6;

/// c(T) = 331.3 sqrt(1 + T / 273.15) m/s for dry air at temperature T (degrees C, > -273.15):
/// the ideal-gas c = sqrt(gamma R T / M) scaled from 331.3 m/s at 0 C. 343.21 m/s at 20 C.
[[nodiscard]] double speedOfSoundInAir(double celsius);

/// I = P / (4 pi r^2), W/m^2: a point source of power P (W, >= 0) at distance r (m, > 0).
[[nodiscard]] double intensityAtDistance(double power, double distance);

/// L = 10 log10(I / I0), dB; intensity (W/m^2) > 0.
[[nodiscard]] double intensityLevel(double intensity);
/// I = I0 10^(L/10), W/m^2; level finite.
[[nodiscard]] double intensityFromLevel(double level);
/// L = 20 log10(p / p0), dB; rms pressure p (Pa) > 0.
[[nodiscard]] double pressureLevel(double pressure);
/// p = p0 10^(L/20), Pa rms.
[[nodiscard]] double pressureFromLevel(double level);

/// The level at distance r2 of a point source whose level is `level` (dB) at r1 (m, > 0):
/// L2 = L1 - 20 log10(r2 / r1) (inverse square: intensity ~ 1/r^2).
[[nodiscard]] double levelAtDistance(double level, double distance1, double distance2);
/// Pressure-amplitude ratio p2/p1 = r1/r2 (1/r).
[[nodiscard]] double amplitudeRatio(double distance1, double distance2);
/// Intensity ratio I2/I1 = (r1/r2)^2 (1/r^2).
[[nodiscard]] double intensityRatio(double distance1, double distance2);

/// How many times louder a sound is perceived for a level difference dL (dB): 2^(dL/10)
/// (+10 dB ~ twice as loud; 130 dB against 60 dB: 128 times).
[[nodiscard]] double loudnessRatio(double levelDifference);

/// Flash-to-bang: the delay between seeing and hearing an event at `distance` (m, >= 0),
/// d/c_sound - d/c_light, s (2.91 s per km at 343.3 m/s).
[[nodiscard]] double flashToBangDelay(double distance, double speedOfSound = openALSpeedOfSound);
/// The distance (m) of an event heard `delay` (s, >= 0) after it was seen.
[[nodiscard]] double distanceFromFlashToBang(double delay, double speedOfSound = openALSpeedOfSound);

/// OpenAL 1.1's distance models (alDistanceModel).
enum class DistanceModel {
  none,            ///< gain 1
  inverse,         ///< ref / (ref + rolloff (d - ref))
  inverseClamped,  ///< the same with d clamped to [ref, max] (OpenAL's default)
  linear,          ///< 1 - rolloff (d - ref) / (max - ref), d <= max
  linearClamped,   ///< the same with d clamped to [ref, max]
  exponent,        ///< (d / ref)^-rolloff
  exponentClamped, ///< the same with d clamped to [ref, max]
};

/// A source's distance attenuation. With inverseClamped and rolloff 1 the gain is ref/d for
/// d >= ref: the physical 1/r fall of the pressure amplitude (intensity 1/r^2), the level at
/// referenceDistance being the source's own.
struct DistanceAttenuation {
  DistanceModel model = DistanceModel::inverseClamped;
  double referenceDistance = 1.0;                         ///< m, > 0 (AL_REFERENCE_DISTANCE)
  double maxDistance = std::numeric_limits<float>::max(); ///< m, > 0 (AL_MAX_DISTANCE)
  double rolloff = 1.0;                                   ///< >= 0 (AL_ROLLOFF_FACTOR)
};

/// The amplitude gain (0..1 for d >= ref) the model gives at `distance` (m, >= 0), as OpenAL
/// computes it. Throws impetus::Error naming the parameter at fault.
[[nodiscard]] double distanceGain(const DistanceAttenuation& attenuation, double distance);

} // namespace impetus::audio
