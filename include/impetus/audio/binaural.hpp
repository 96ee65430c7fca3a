// 3D hearing (ch. 26): how two ears locate a sound. A sound from the side reaches the far ear
// later (the interaural time difference, ITD, up to about 0.5-0.7 ms) and weaker (the
// interaural level difference, ILD: the head shadows high frequencies, low ones diffract
// round it). Spectral cues from the pinnae, head and torso (the HRTF) add elevation and
// front/back.
//
// Azimuth: radians from straight ahead in the horizontal plane, positive to the right (+pi/2:
// the right ear faces the source). ITD > 0 and ILD > 0 when the right ear leads / is louder.
#pragma once

#include <impetus/audio/waves.hpp>

namespace impetus::audio {

/// The spacing of the ears, m (the book's order of magnitude: 0.17 m gives ~0.5 ms).
inline constexpr double typicalEarSpacing = 0.17;
/// The radius of a spherical head, m (Woodworth's 8.75 cm).
inline constexpr double typicalHeadRadius = 0.0875;

/// ITD of two ears `earSpacing` (m, > 0) apart in free field, the path difference of a plane
/// wave: (d / c) sin(azimuth), s.
[[nodiscard]] double interauralTimeDifference(double azimuth, double earSpacing = typicalEarSpacing,
                                              double speedOfSound = openALSpeedOfSound);

/// Woodworth's ITD for a rigid spherical head of radius a (m, > 0), the far ear reached round
/// the head: (a / c)(theta + sin theta) with theta the lateral angle (azimuth folded into
/// [-pi/2, pi/2]: a source behind gives the same ITD as its mirror in front), s. 0.655 ms at
/// 90 degrees for a = 8.75 cm.
[[nodiscard]] double woodworthTimeDifference(double azimuth, double headRadius = typicalHeadRadius,
                                             double speedOfSound = openALSpeedOfSound);

/// The head-shadow gain of one ear (Brown and Duda's one-pole, one-zero model of a spherical
/// head, IEEE Trans. Speech Audio Proc. 6(5), 1998):
///   |H| = sqrt((1 + (alpha w / 2 w0)^2) / (1 + (w / 2 w0)^2)),  w0 = c / a,
///   alpha(theta) = (1 + alpha_min/2) + (1 - alpha_min/2) cos(pi theta / theta_min),
/// alpha_min = 0.1, theta_min = 150 degrees; theta (rad, 0..pi) is the angle between the ear's
/// outward axis and the source. Low frequencies pass (|H| -> 1); at high ones the facing ear
/// gains up to +6 dB (alpha = 2) and the shadowed one loses up to -20 dB at 150 degrees from its
/// axis (alpha = 0.1; the bright spot right behind the sphere brings it back to -11 dB at 180).
/// Returns |H| (linear).
[[nodiscard]] double headShadowGain(double angleFromEarAxis, double frequency, double headRadius = typicalHeadRadius,
                                    double speedOfSound = openALSpeedOfSound);

/// ILD = 20 log10(|H_right| / |H_left|), dB, from the head-shadow model at `frequency` (Hz, > 0).
[[nodiscard]] double interauralLevelDifference(double azimuth, double frequency, double headRadius = typicalHeadRadius,
                                               double speedOfSound = openALSpeedOfSound);

} // namespace impetus::audio
