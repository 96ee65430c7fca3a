#include "plot.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>

namespace impetus::samples {

History::History(std::size_t capacity) : values_(std::max<std::size_t>(capacity, 2), 0.0f) {}

void History::push(float value) {
  values_[next_] = value;
  next_ = (next_ + 1) % values_.size();
  size_ = std::min(size_ + 1, values_.size());
}

void History::clear() {
  next_ = 0;
  size_ = 0;
}

float History::latest() const noexcept {
  if (size_ == 0) {
    return 0.0f;
  }
  return values_[(next_ + values_.size() - 1) % values_.size()];
}

void History::plot(const char* label, const char* valueFormat, float heightPixels, float min, float max) const {
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, valueFormat, static_cast<double>(latest()));
  const bool fixed = min < max;
  // Until the buffer is full the oldest value sits at index 0; afterwards at next_.
  const int offset = size_ < values_.size() ? 0 : static_cast<int>(next_);
  ImGui::TextUnformatted(label);
  ImGui::PushID(label);
  ImGui::PlotLines("##plot", values_.data(), static_cast<int>(size_), offset, overlay, fixed ? min : FLT_MAX,
                   fixed ? max : FLT_MAX, ImVec2(ImGui::GetContentRegionAvail().x, heightPixels));
  ImGui::PopID();
}

void plotCurve(const char* label, std::span<const float> values, const char* overlay, float heightPixels, float min,
               float max) {
  const bool fixed = min < max;
  ImGui::TextUnformatted(label);
  ImGui::PushID(label);
  ImGui::PlotLines("##curve", values.data(), static_cast<int>(values.size()), 0, overlay, fixed ? min : FLT_MAX,
                   fixed ? max : FLT_MAX, ImVec2(ImGui::GetContentRegionAvail().x, heightPixels));
  ImGui::PopID();
}

} // namespace impetus::samples
