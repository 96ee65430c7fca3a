// Reflection and echoes (ch. 26): part of a sound wave hitting a surface is reflected, part
// absorbed or transmitted. Hard smooth surfaces reflect; soft, irregular ones absorb and
// scatter. A reflection off a plane wall is heard as if it came from the source's mirror image
// behind the wall (the image source): it travels the longer path |L - S'|, arrives later and
// weaker (amplitude ~ 1/path, times the wall's reflection coefficient). When the lag exceeds
// about 50-100 ms the ear hears it as a separate echo; shorter reflections blend into
// reverberation.
#pragma once

#include <impetus/audio/waves.hpp>
#include <impetus/math/vec3.hpp>

namespace impetus::audio {

/// The delay of the echo from a reflector `distance` away (m, >= 0) back to where the sound
/// started: 2 d / c, s.
[[nodiscard]] double echoDelay(double distance, double speedOfSound = openALSpeedOfSound);

/// The distance (m) of the reflector whose echo comes back after `delay` (s, >= 0): c t / 2.
[[nodiscard]] double reflectorDistance(double delay, double speedOfSound = openALSpeedOfSound);

/// The pressure reflection coefficient of a surface that absorbs the fraction `absorption`
/// (0..1) of the incident energy: R = sqrt(1 - alpha).
[[nodiscard]] double reflectionCoefficient(double absorption);

struct PlaneReflection {
  Vec3d imageSource{};         ///< S' = S - 2 ((S - Q) . n) n, m
  Vec3d reflectionPoint{};     ///< where the reflected ray meets the plane, m
  double directPath = 0.0;     ///< |L - S|, m
  double reflectedPath = 0.0;  ///< |L - S'|, m
  double directDelay = 0.0;    ///< directPath / c, s
  double reflectedDelay = 0.0; ///< reflectedPath / c, s
  double lag = 0.0;            ///< reflectedDelay - directDelay, s
  /// Reflected over direct pressure amplitude: R directPath / reflectedPath.
  double amplitudeRatio = 0.0;
  /// The same in dB: 20 log10(amplitudeRatio) (minus infinity for R = 0 is reported as the
  /// lowest double).
  double levelDifference = 0.0;
};

/// The reflection of a sound from `source` off the plane through `planePoint` with normal
/// `planeNormal` (any length > 0) heard at `listener`; `coefficient` is the pressure
/// reflection coefficient (0..1). Source and listener must be on the same side of the plane,
/// off it. Throws impetus::Error naming the argument at fault.
[[nodiscard]] PlaneReflection reflectOffPlane(const Vec3d& source, const Vec3d& listener, const Vec3d& planePoint,
                                              const Vec3d& planeNormal, double coefficient = 1.0,
                                              double speedOfSound = openALSpeedOfSound);

} // namespace impetus::audio
