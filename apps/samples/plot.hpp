// Live plots in a sample's panel (Dear ImGui's PlotLines): a rolling history of one quantity per
// frame or step, drawn with its latest value and unit in the overlay.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace impetus::samples {

class History {
public:
  /// Keeps the last `capacity` values (600: ten seconds at one value per 1/60 s frame).
  explicit History(std::size_t capacity = 600);

  void push(float value);
  void clear();
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
  [[nodiscard]] float latest() const noexcept;
  [[nodiscard]] std::size_t size() const noexcept { return size_; }

  /// The plot, `heightPixels` tall and as wide as the panel; `valueFormat` prints the latest
  /// value with its unit (e.g. "%.2f J"). Scales to the data unless `min` < `max` are given.
  void plot(const char* label, const char* valueFormat, float heightPixels = 60.0f, float min = 0.0f,
            float max = 0.0f) const;

private:
  std::vector<float> values_;
  std::size_t next_ = 0;
  std::size_t size_ = 0;
};

/// A whole curve at once (e.g. range against the launch angle); `overlay` is printed on it.
void plotCurve(const char* label, std::span<const float> values, const char* overlay, float heightPixels = 80.0f,
               float min = 0.0f, float max = 0.0f);

} // namespace impetus::samples
