// Live plots in a sample's panel: a rolling history of one quantity per frame or step, or a whole
// curve, drawn with a y axis (tick labels in the title's unit) and the latest value.
//
// The y range is the data's, widened to a minimum span so that round-off is never magnified into
// a curve: at least minimumSpanShare of the values' magnitude, and at least ten units of the last
// digit the readout prints ("%.2f m/s": 0.1 m/s). A conserved quantity with float noise on it
// plots flat.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace impetus::samples {

/// Least y span of a plot as a share of its largest |value|: changes smaller than 2% of the
/// quantity itself are not what a plot in a panel is for.
constexpr float minimumSpanShare = 0.02f;

/// A plot's y axis: from `lower` to `upper` with a tick every `step`, labels with `decimals` digits.
struct PlotAxis {
  float lower = 0.0f;
  float upper = 1.0f;
  float step = 0.5f;
  int decimals = 1;
};

/// Tick labels on a plot's y axis, at most.
constexpr int maxTicks = 5;

/// The axis for data spanning [dataMin, dataMax]: at least `minSpan` wide and minimumSpanShare of
/// the magnitude, centred on the data (a sign the data keep, the axis keeps), its ends on ticks
/// of 1, 2 or 5 times a power of ten, with about `ticks` ticks.
[[nodiscard]] PlotAxis plotAxis(float dataMin, float dataMax, float minSpan, int ticks = maxTicks);

/// Ten units of the last digit a printf format prints ("%.2f" -> 0.1, "%.0f" -> 10; 0 when the
/// format has no fixed precision, e.g. "%g").
[[nodiscard]] float readoutResolution(const char* valueFormat);

class History {
public:
  /// Keeps the last `capacity` values (600: ten seconds at one value per 1/60 s frame).
  explicit History(std::size_t capacity = 600);

  void push(float value);
  void clear();
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] float latest() const noexcept;
  [[nodiscard]] std::size_t size() const noexcept { return size_; }

  /// The plot, `heightPixels` tall (at a 15 px font) and as wide as the panel; `valueFormat`
  /// prints the latest value with its unit (e.g. "%.2f J") and sets the least span. Scales to the
  /// data unless `min` < `max` are given.
  void plot(const char* label, const char* valueFormat, float heightPixels = 60.0f, float min = 0.0f,
            float max = 0.0f) const;

private:
  std::vector<float> values_;
  std::size_t next_ = 0;
  std::size_t size_ = 0;
};

/// A whole curve at once (e.g. range against the launch angle); `overlay` is printed on it. The
/// range is the data's, at least `minSpan` wide, unless `min` < `max` are given.
void plotCurve(const char* label, std::span<const float> values, const char* overlay, float heightPixels = 80.0f,
               float min = 0.0f, float max = 0.0f, float minSpan = 0.0f);

} // namespace impetus::samples
