// Book/Doppler (ch. 26): a sound source passing a listener in a straight line (audio/doppler.hpp).
// The view shows the road, the listener and the wavefronts: circles of radius c (t - tau)
// around where the source was when it emitted them, bunched ahead of it and spread behind (the
// Doppler effect seen). The sample synthesizes the pressure the listener receives, sampled at
// 44.1 kHz (audio: passByPressure, each sample the sound emitted at the retarded time, its
// amplitude falling as 1/r), measures its pitch by zero crossings over the last 0.1 s, and
// plots the measured frequency against the formula f c / (c - v cos theta) at emission. There
// is no audio output: `impetus demo doppler` renders the same pass to a WAV file through
// OpenAL Soft.
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/audio/audio.hpp>
#include <impetus/error.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <vector>

namespace impetus::samples {
namespace {

constexpr double sampleRate = 44100.0;
constexpr double pitchWindow = 0.1;    // s of received sound the pitch is measured over
constexpr double wavefrontEvery = 0.1; // s between the wavefronts drawn (not the sound's period)

class Doppler final : public Sample {
public:
  void setup() override {
    pass_.speedOfSound = audio::speedOfSoundInAir(static_cast<double>(temperature_));
    pass_.speed = std::min(static_cast<double>(speed_), 0.95 * pass_.speedOfSound);
    pass_.frequency = frequency_;
    pass_.closestApproach = closest_;
    duration_ = std::min(2.0 * std::clamp(150.0 / std::max(pass_.speed, 1e-3), 1.0, 6.0), 12.0);
    pass_.closestTime = 0.5 * duration_;
    t_ = 0.0;
    samplesDone_ = 0;
    received_.clear();
    measured_.clear();
    formula_.clear();
    difference_.clear();
    lastMeasured_ = 0.0;
  }

  void step(float dt) override {
    t_ += static_cast<double>(dt);
    if (t_ >= duration_) {
      setup(); // the next pass
      return;
    }
    // Synthesize the listener's pressure up to t, keep the last pitchWindow seconds.
    const auto target = static_cast<long>(t_ * sampleRate);
    for (; samplesDone_ < target; ++samplesDone_) {
      received_.push_back(static_cast<float>(
          audio::passByPressure(pass_, static_cast<double>(samplesDone_) / sampleRate, pass_.closestApproach)));
    }
    const auto keep = static_cast<std::size_t>(pitchWindow * sampleRate);
    while (received_.size() > keep) {
      received_.pop_front();
    }
    if (received_.size() == keep) {
      const std::vector<float> window(received_.begin(), received_.end());
      try {
        lastMeasured_ = audio::zeroCrossingPitch(window, sampleRate).frequency;
      } catch (const Error&) {
        return; // before the first sound arrives: silence, nothing to measure
      }
      // The formula at the window's centre (the measurement averages over the window).
      const double expected = audio::passByHeardFrequency(pass_, t_ - 0.5 * pitchWindow);
      measured_.push(static_cast<float>(lastMeasured_));
      formula_.push(static_cast<float>(expected));
      difference_.push(static_cast<float>(100.0 * (lastMeasured_ / expected - 1.0)));
    }
  }

  [[nodiscard]] bool finite() const override {
    return std::isfinite(t_) && std::isfinite(lastMeasured_) &&
           std::all_of(received_.begin(), received_.end(), [](float s) { return std::isfinite(s); });
  }

  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 20.0f}, 70.0f, 170.0f}; }

  [[nodiscard]] std::string summary() const override {
    char text[200];
    std::snprintf(text, sizeof text,
                  "t = %.2f s, source at x = %.1f m, heard %.2f Hz measured, %.2f Hz by the formula "
                  "(approach %.2f, recede %.2f Hz)",
                  t_, sourceX(t_), lastMeasured_, audio::passByHeardFrequency(pass_, t_ - 0.5 * pitchWindow),
                  approaching(), receding());
    return text;
  }

  void draw(DebugDraw& draw) override {
    const float d = static_cast<float>(pass_.closestApproach);
    draw.segment({-400.0f, d}, {400.0f, d}, palette::staticBody);
    draw.text({-160.0f, d + 3.0f}, "road", palette::text);
    // Wavefronts: one every wavefrontEvery seconds of emission, radius c (t - tau).
    const double c = pass_.speedOfSound;
    const double first = std::floor(std::max(0.0, t_ - 1.5) / wavefrontEvery) * wavefrontEvery;
    for (double tau = first; tau <= t_; tau += wavefrontEvery) {
      const float radius = static_cast<float>(c * (t_ - tau));
      if (radius > 450.0f) {
        continue;
      }
      const Vec2f centre{static_cast<float>(sourceX(tau)), d};
      draw.circle(centre, radius, palette::trajectory.withAlpha(0.55f));
    }
    const Vec2f source{static_cast<float>(sourceX(t_)), d};
    draw.solidCircle(source, 2.0f, 0.0f, palette::bullet, palette::bullet);
    draw.arrow(source, source + Vec2f{static_cast<float>(0.3 * pass_.speed), 0.0f}, palette::awake);
    draw.solidCircle({0.0f, 0.0f}, 1.5f, 0.0f, palette::reference, palette::reference);
    draw.text({2.5f, -4.0f}, "listener", palette::text);
    // The ray the sound heard now travelled: from where the source was at emission.
    const double tau = audio::passByEmissionTime(pass_, t_);
    draw.segment({static_cast<float>(sourceX(tau)), d}, {0.0f, 0.0f}, palette::reference.withAlpha(0.6f));
    char label[96];
    std::snprintf(label, sizeof label, "heard %.1f Hz (emitted %.0f Hz)", lastMeasured_, pass_.frequency);
    draw.text({2.5f, -10.0f}, label, palette::reference);
  }

  void ui() override {
    bool changed = false;
    changed |= slider("source speed v", &speed_, 0.0f, 300.0f, "%.0f m/s");
    changed |= slider("frequency f", &frequency_, 100.0f, 2000.0f, "%.0f Hz");
    changed |= slider("closest approach d", &closest_, 1.0f, 60.0f, "%.0f m");
    changed |= slider("air temperature", &temperature_, -30.0f, 40.0f, "%.0f C");
    if (changed) {
      setup();
    }
    textWrapped("speed of sound c = %.1f m/s", pass_.speedOfSound);
    textWrapped("approaching f c/(c - v) = %.1f Hz", approaching());
    textWrapped("receding    f c/(c + v) = %.1f Hz", receding());
    measured_.plot("heard frequency, measured from the sound (Hz)", "%.1f Hz", 70.0f,
                   static_cast<float>(receding() * 0.97), static_cast<float>(approaching() * 1.03));
    formula_.plot("the formula f c / (c - v cos theta) (Hz)", "%.1f Hz", 70.0f, static_cast<float>(receding() * 0.97),
                  static_cast<float>(approaching() * 1.03));
    difference_.plot("measured minus formula (%)", "%.3f %%", 50.0f);
  }

private:
  [[nodiscard]] double sourceX(double t) const { return pass_.speed * (t - pass_.closestTime); }
  [[nodiscard]] double approaching() const {
    return pass_.frequency * pass_.speedOfSound / (pass_.speedOfSound - pass_.speed);
  }
  [[nodiscard]] double receding() const {
    return pass_.frequency * pass_.speedOfSound / (pass_.speedOfSound + pass_.speed);
  }

  float speed_ = 60.0f;
  float frequency_ = 440.0f;
  float closest_ = 10.0f;
  float temperature_ = 20.0f;
  audio::PassBy pass_;
  double duration_ = 0.0;
  double t_ = 0.0;
  long samplesDone_ = 0;
  std::deque<float> received_;
  double lastMeasured_ = 0.0;
  History measured_;
  History formula_;
  History difference_;
};

const SampleRegistrar registrar{"Book", "Doppler",
                                "Sound (ch. 26): a source passing a listener, its wavefronts, and the frequency "
                                "heard, measured from the synthesized sound, against the Doppler formula.",
                                [] { return std::make_unique<Doppler>(); }};

} // namespace
} // namespace impetus::samples
