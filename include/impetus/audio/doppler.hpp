// The Doppler effect (ch. 26): a source approaching a listener is heard higher, a receding one
// lower. In still air, with the speeds along the line between them,
//   f_L = f_S (c + v_L) / (c - v_S),
// v_L the listener's speed toward the source, v_S the source's speed toward the listener (m/s;
// negative when moving away). A source at or above the speed of sound outruns its own sound
// (the formula's pole: a sonic boom, not a pitch): an impetus::Error here, never infinity.
//
// OpenAL 1.1 computes the same from the projections of the velocities on the source-to-
// listener direction, scaled by alDopplerFactor DF and clamped to SS/DF:
//   f' = f (SS - DF v_ls) / (SS - DF v_ss).
// It uses the positions *now*; physically the sound heard now left the source earlier (the
// retarded time), which the pass-by functions below account for. The book's demo sets a
// velocity of one tenth of the real speed and hides it behind a Doppler factor of 10.
#pragma once

#include <impetus/audio/waves.hpp>
#include <impetus/math/vec3.hpp>

namespace impetus::audio {

/// f (c + v_L) / (c - v_S), Hz. frequency > 0; sourceSpeedTowardListener < c (else an
/// impetus::Error naming "sourceSpeed"); listenerSpeedTowardSource > -c (a listener receding
/// at c or faster hears nothing: "listenerSpeed").
[[nodiscard]] double dopplerFrequency(double frequency, double sourceSpeedTowardListener,
                                      double listenerSpeedTowardSource, double speedOfSound = openALSpeedOfSound);

/// The same from positions (m) and velocities (m/s) in space, the speeds being the velocities'
/// components along the line between source and listener (which must not coincide).
[[nodiscard]] double dopplerFrequency(double frequency, const Vec3d& sourcePosition, const Vec3d& sourceVelocity,
                                      const Vec3d& listenerPosition, const Vec3d& listenerVelocity,
                                      double speedOfSound = openALSpeedOfSound);

/// OpenAL 1.1's form: v_ls, v_ss the listener's and source's velocity components along the
/// source-to-listener direction, each clamped to at most SS/DF; f (SS - DF v_ls)/(SS - DF v_ss).
/// dopplerFactor >= 0 (0 turns the shift off). Coincident positions give f unchanged.
[[nodiscard]] double openALDopplerFrequency(double frequency, const Vec3d& sourcePosition, const Vec3d& sourceVelocity,
                                            const Vec3d& listenerPosition, const Vec3d& listenerVelocity,
                                            double dopplerFactor = 1.0, double speedOfSound = openALSpeedOfSound);

/// A source of frequency f moving at `speed` along a straight line past a listener at rest at
/// the origin: S(t) = (speed (t - closestTime), closestApproach, 0).
struct PassBy {
  double frequency = 440.0;                 ///< f, Hz, > 0
  double speed = 30.0;                      ///< v, m/s, 0 <= v < c
  double closestApproach = 10.0;            ///< d, m, > 0
  double closestTime = 0.0;                 ///< when the source is nearest, s
  double speedOfSound = openALSpeedOfSound; ///< c, m/s, > 0
};

/// Throws impetus::Error naming the field unless the pass is physical (speed below c).
void requireValid(const PassBy& pass);

/// The source's position at time t, m.
[[nodiscard]] Vec3d passBySourcePosition(const PassBy& pass, double time);

/// The retarded time: when the sound heard at `time` left the source, s. With u = tau - t0,
/// T = t - t0, it solves |S(tau)| = c (t - tau):
///   u = (c^2 T - c sqrt(v^2 T^2 + (1 - v^2/c^2) d^2)) / (c^2 - v^2).
[[nodiscard]] double passByEmissionTime(const PassBy& pass, double time);

/// The frequency heard at `time`: f c / (c - v cos theta) with theta between the velocity and
/// the line from the source *at emission* to the listener, Hz. Far before the pass it tends to
/// f c/(c - v), far after to f c/(c + v); at the closest point of emission it is f.
[[nodiscard]] double passByHeardFrequency(const PassBy& pass, double time);

/// The frequency OpenAL computes at `time` from the positions now (no propagation delay), Hz.
[[nodiscard]] double passByInstantaneousFrequency(const PassBy& pass, double time);

/// The pressure heard at `time` from a source of pressure amplitude `amplitudeAt1m` (Pa at
/// 1 m): amplitudeAt1m sin(2 pi f tau) / r(tau), tau the emission time and r(tau) the distance
/// the sound travelled. Sampled, it is a physical rendering of the pass (no OpenAL).
[[nodiscard]] double passByPressure(const PassBy& pass, double time, double amplitudeAt1m = 1.0);

} // namespace impetus::audio
