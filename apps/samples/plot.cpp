#include "plot.hpp"

#include "ui.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace impetus::samples {
namespace {

/// 1, 2 or 5 times a power of ten, the least at or above `x` (> 0).
float niceStep(float x) {
  const float decade = std::pow(10.0f, std::floor(std::log10(x)));
  for (const float f : {1.0f, 2.0f, 5.0f}) {
    if (f * decade >= x * (1.0f - 1e-6f)) {
      return f * decade;
    }
  }
  return 10.0f * decade;
}

/// Draws `count` values, the first at `offset` in a ring of `count` (a History), in a frame as
/// wide as the panel with the axis's tick labels on the left and `overlay` at the top right.
/// What a plot's y range should cover: the data's extent or the caller's fixed range.
struct RangeRequest {
  float min = 0.0f;
  float max = 0.0f;
  float minSpan = 0.0f;
  bool fixed = false;
};

RangeRequest rangeFor(const float* values, std::size_t count, float min, float max, float minSpan) {
  if (min < max) {
    return {min, max, 0.0f, true};
  }
  RangeRequest request{0.0f, 0.0f, minSpan, false};
  bool any = false;
  for (std::size_t i = 0; i < count; ++i) {
    if (std::isfinite(values[i])) {
      request.min = any ? std::min(request.min, values[i]) : values[i];
      request.max = any ? std::max(request.max, values[i]) : values[i];
      any = true;
    }
  }
  return request;
}

void drawPlot(const char* label, const float* values, int count, int offset, const char* overlay, float heightPixels,
              const RangeRequest& range) {
  textWrappedUnformatted(label);
  const float em = ImGui::GetFontSize() / panelFontPixels;
  const float width = ImGui::GetContentRegionAvail().x;
  const float height = heightPixels * em;
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::PushID(label);
  ImGui::Dummy(ImVec2(width, height));
  ImGui::PopID();
  ImDrawList* list = ImGui::GetWindowDrawList();
  const ImGuiStyle& style = ImGui::GetStyle();
  const ImU32 frame = ImGui::GetColorU32(ImGuiCol_FrameBg);
  const ImU32 grid = ImGui::GetColorU32(ImGuiCol_TextDisabled, 0.35f);
  const ImU32 tickText = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  const ImU32 line = ImGui::GetColorU32(ImGuiCol_PlotLines);
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  list->AddRectFilled(p0, ImVec2(p0.x + width, p0.y + height), frame, style.FrameRounding);
  // As many ticks as fit with a line of text between their labels.
  const int tickRoom = static_cast<int>(std::floor(height / (2.0f * ImGui::GetFontSize()))) + 1;
  PlotAxis axis = plotAxis(range.min, range.max, range.minSpan, std::clamp(tickRoom, 2, maxTicks));
  if (range.fixed) { // the caller's range as it is, ticks inside it
    axis.lower = range.min;
    axis.upper = range.max;
  }

  // Tick labels at the multiples of the step inside the range: their widest sets the axis column.
  const double firstTick = std::ceil(axis.lower / axis.step - 1e-4f) * static_cast<double>(axis.step);
  const int ticks = static_cast<int>(std::floor((axis.upper - firstTick) / axis.step + 1e-4)) + 1;
  char tickLabels[maxTicks + 2][24];
  float labelWidth = 0.0f;
  for (int i = 0; i < ticks && i < maxTicks + 2; ++i) {
    const double v = firstTick + i * static_cast<double>(axis.step);
    std::snprintf(tickLabels[i], sizeof tickLabels[i], "%.*f", axis.decimals, std::abs(v) < 1e-12 ? 0.0 : v);
    labelWidth = std::max(labelWidth, ImGui::CalcTextSize(tickLabels[i]).x);
  }
  const float pad = 3.0f * em;
  const float fontHalf = 0.5f * ImGui::GetFontSize();
  const float left = p0.x + labelWidth + 2.0f * pad;
  const float right = p0.x + width - pad;
  const float top = p0.y + fontHalf;
  const float bottom = p0.y + height - fontHalf;
  const auto yOf = [&](float v) {
    return bottom - (bottom - top) * std::clamp((v - axis.lower) / (axis.upper - axis.lower), 0.0f, 1.0f);
  };
  for (int i = 0; i < ticks && i < maxTicks + 2; ++i) {
    const float y = yOf(static_cast<float>(firstTick + i * static_cast<double>(axis.step)));
    list->AddLine(ImVec2(left, y), ImVec2(right, y), grid);
    const float w = ImGui::CalcTextSize(tickLabels[i]).x;
    list->AddText(ImVec2(left - pad - w, y - fontHalf), tickText, tickLabels[i]);
  }
  if (count >= 2) {
    std::vector<ImVec2> points(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
      const float v = values[(offset + i) % count];
      const float x = left + (right - left) * static_cast<float>(i) / static_cast<float>(count - 1);
      points[static_cast<std::size_t>(i)] = ImVec2(x, yOf(v));
    }
    list->PushClipRect(ImVec2(left, p0.y), ImVec2(right, p0.y + height), true);
    list->AddPolyline(points.data(), count, line, 0, 1.5f * em);
    list->PopClipRect();
  }
  if (overlay != nullptr && overlay[0] != '\0') {
    const ImVec2 size = ImGui::CalcTextSize(overlay);
    const ImVec2 at(std::max(left, right - size.x - pad), p0.y + 1.0f);
    list->AddRectFilled(ImVec2(at.x - pad, at.y), ImVec2(at.x + size.x + pad, at.y + size.y), frame);
    list->AddText(at, text, overlay);
  }
}

} // namespace

PlotAxis plotAxis(float dataMin, float dataMax, float minSpan, int ticks) {
  const float magnitude = std::max(std::abs(dataMin), std::abs(dataMax));
  float span = std::max({dataMax - dataMin, minSpan, minimumSpanShare * magnitude});
  if (!(span > 0.0f)) {
    span = 1.0f; // all zero and nothing asked: a unit span around it
  }
  const float centre = 0.5f * (dataMin + dataMax);
  float lo = centre - 0.5f * span;
  float hi = centre + 0.5f * span;
  // Keep a sign the data never leave: a positive quantity's axis does not dip below zero.
  if (dataMin >= 0.0f && lo < 0.0f) {
    hi -= lo;
    lo = 0.0f;
  } else if (dataMax <= 0.0f && hi > 0.0f) {
    lo -= hi;
    hi = 0.0f;
  }
  // The finest round step whose ticks, from below the data to above it, number at most ticks + 1.
  const int most = std::max(ticks, 2) + 1;
  PlotAxis axis;
  axis.step = niceStep((hi - lo) / static_cast<float>(most - 1));
  for (;;) {
    axis.lower = std::floor(lo / axis.step) * axis.step;
    axis.upper = std::ceil(hi / axis.step) * axis.step;
    if (std::lround((axis.upper - axis.lower) / axis.step) + 1 <= most) {
      break;
    }
    axis.step = niceStep(axis.step * 1.5f); // the next of 1, 2, 5 x 10^k
  }
  if (axis.upper <= axis.lower) {
    axis.upper = axis.lower + axis.step;
  }
  axis.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(axis.step) + 1e-4f)));
  return axis;
}

float readoutResolution(const char* valueFormat) {
  const char* p = std::strchr(valueFormat, '%');
  while (p != nullptr && p[1] == '%') {
    p = std::strchr(p + 2, '%');
  }
  if (p == nullptr) {
    return 0.0f;
  }
  const char* dot = std::strchr(p, '.');
  const char* conversion = p + std::strcspn(p + 1, "fFeEgGdi") + 1;
  if (*conversion == 'd' || *conversion == 'i') {
    return 10.0f;
  }
  if (*conversion != 'f' && *conversion != 'F') {
    return 0.0f;
  }
  const int decimals = dot != nullptr && dot < conversion ? std::atoi(dot + 1) : 6;
  return 10.0f * std::pow(10.0f, -static_cast<float>(decimals));
}

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
  // Until the buffer is full the oldest value sits at index 0; afterwards at next_.
  const int offset = size_ < values_.size() ? 0 : static_cast<int>(next_);
  drawPlot(label, values_.data(), static_cast<int>(size_), offset, overlay, heightPixels,
           rangeFor(values_.data(), size_, min, max, readoutResolution(valueFormat)));
}

void plotCurve(const char* label, std::span<const float> values, const char* overlay, float heightPixels, float min,
               float max, float minSpan) {
  drawPlot(label, values.data(), static_cast<int>(values.size()), 0, overlay, heightPixels,
           rangeFor(values.data(), values.size(), min, max, minSpan));
}

} // namespace impetus::samples
