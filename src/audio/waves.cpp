#include <impetus/audio/waves.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <cmath>

namespace impetus::audio {

double HarmonicWave::angularFrequency() const noexcept { return 2.0 * pi<double> * frequency; }

double HarmonicWave::wavenumber() const noexcept { return 2.0 * pi<double> * frequency / speedOfSound; }

double HarmonicWave::pressure(double x, double t) const noexcept {
  return amplitude * std::sin(wavenumber() * x - angularFrequency() * t + phase);
}

void requireValid(const HarmonicWave& wave) {
  requireNonNegative(wave.amplitude, "amplitude");
  requirePositive(wave.frequency, "frequency");
  requireFinite(wave.phase, "phase");
  requirePositive(wave.speedOfSound, "speedOfSound");
}

double wavelength(double frequency, double speedOfSound) {
  requirePositive(frequency, "frequency");
  requirePositive(speedOfSound, "speedOfSound");
  return speedOfSound / frequency;
}

double frequencyFromWavelength(double wavelength, double speedOfSound) {
  requirePositive(wavelength, "wavelength");
  requirePositive(speedOfSound, "speedOfSound");
  return speedOfSound / wavelength;
}

WaveSum::WaveSum(std::span<const HarmonicWave> components) {
  for (const HarmonicWave& w : components) {
    add(w);
  }
}

void WaveSum::add(const HarmonicWave& wave) {
  requireValid(wave);
  components_.push_back(wave);
}

double WaveSum::pressure(double x, double t) const noexcept {
  double p = 0.0;
  for (const HarmonicWave& w : components_) {
    p += w.pressure(x, t);
  }
  return p;
}

std::vector<double> WaveSum::sample(double x, double sampleRate, std::size_t count) const {
  requireFinite(x, "x");
  requirePositive(sampleRate, "sampleRate");
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    out[i] = pressure(x, static_cast<double>(i) / sampleRate);
  }
  return out;
}

double beatFrequency(double frequency1, double frequency2) {
  requirePositive(frequency1, "frequency1");
  requirePositive(frequency2, "frequency2");
  return std::abs(frequency1 - frequency2);
}

} // namespace impetus::audio
