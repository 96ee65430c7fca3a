// Sound as a wave (ch. 26): a longitudinal pressure wave; harmonic components and their
// superposition.
//
// A harmonic wave travelling toward +x: dP(x, t) = A sin(k x - w t + phi), the pressure about
// ambient (Pa) with amplitude A, wavenumber k = 2 pi / lambda (rad/m), angular frequency
// w = 2 pi f (rad/s), and c = f lambda: f = c / lambda (the book writes f = 1/lambda, which is
// 1/T in time, not in space). Waves superpose: the pressures of all components add at a point,
// constructively or destructively (noise cancellation). Two tones f1, f2 of equal amplitude sum
// to 2A cos(pi (f1 - f2) t) sin(pi (f1 + f2) t): a tone at the mean frequency whose loudness
// beats |f1 - f2| times a second.
#pragma once

#include <span>
#include <vector>

namespace impetus::audio {

/// OpenAL's default speed of sound, m/s ("air at 20 degrees C", the book's value; the
/// temperature formula of propagation.hpp gives 343.21).
inline constexpr double openALSpeedOfSound = 343.3;

struct HarmonicWave {
  double amplitude = 1.0;                   ///< A, Pa (pressure amplitude), >= 0
  double frequency = 440.0;                 ///< f, Hz, > 0
  double phase = 0.0;                       ///< phi, rad
  double speedOfSound = openALSpeedOfSound; ///< c, m/s, > 0

  [[nodiscard]] double wavelength() const noexcept { return speedOfSound / frequency; } ///< lambda = c/f, m
  [[nodiscard]] double period() const noexcept { return 1.0 / frequency; }              ///< T = 1/f, s
  [[nodiscard]] double angularFrequency() const noexcept;                               ///< w = 2 pi f, rad/s
  [[nodiscard]] double wavenumber() const noexcept;                                     ///< k = 2 pi / lambda, rad/m
  /// dP(x, t) = A sin(k x - w t + phi), Pa; x in m, t in s.
  [[nodiscard]] double pressure(double x, double t) const noexcept;
};

/// Throws impetus::Error naming "amplitude", "frequency", "phase" or "speedOfSound" unless the
/// wave is physical (finite, amplitude >= 0, frequency and speed > 0).
void requireValid(const HarmonicWave& wave);

/// lambda = c / f, m. frequency (Hz) and speedOfSound (m/s) > 0.
[[nodiscard]] double wavelength(double frequency, double speedOfSound = openALSpeedOfSound);

/// f = c / lambda, Hz (the book's f = 1/lambda drops c). wavelength (m) and speed > 0.
[[nodiscard]] double frequencyFromWavelength(double wavelength, double speedOfSound = openALSpeedOfSound);

/// The superposition of harmonic components: dP(x, t) = sum A_n sin(k_n x - w_n t + phi_n).
/// Every component is checked when it is added.
class WaveSum {
public:
  WaveSum() = default;
  explicit WaveSum(std::span<const HarmonicWave> components);

  void add(const HarmonicWave& wave);
  [[nodiscard]] std::span<const HarmonicWave> components() const noexcept { return components_; }
  /// Total pressure at x (m) and t (s), Pa.
  [[nodiscard]] double pressure(double x, double t) const noexcept;
  /// Samples of the pressure at x: count samples from t = 0 at sampleRate (Hz, > 0).
  [[nodiscard]] std::vector<double> sample(double x, double sampleRate, std::size_t count) const;

private:
  std::vector<HarmonicWave> components_;
};

/// The beat frequency |f1 - f2| (Hz) heard when two tones of nearly equal frequency sound
/// together; f1, f2 > 0.
[[nodiscard]] double beatFrequency(double frequency1, double frequency2);

} // namespace impetus::audio
