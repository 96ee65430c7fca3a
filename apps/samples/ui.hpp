// The samples' panel widgets: a label column beside each control, and text that wraps only
// between words, never inside a number or between a number and its unit.
//
// A slider's label sits in a column left of it (it wraps there when long) instead of inside the
// slider, where the grab would cover it; the slider shows only the value and unit ("%.1f m/s").
// The last item is the control, so ImGui::IsItemDeactivatedAfterEdit() after a call works as for
// ImGui's own widgets.
#pragma once

#include <imgui.h>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace impetus::samples {

/// Text height of the panels at a 96-dpi screen, pixels: DejaVu Sans reads well at 15 px, the
/// size of a browser's small text.
constexpr float panelFontPixels = 15.0f;

/// Loads the panels' font at `scale` times panelFontPixels and scales ImGui's spacing with it:
/// DejaVu Sans from Debian's fonts-dejavu-core when it is installed, otherwise ImGui's built-in
/// font. Returns the font file used ("" for the built-in one). Call before the first frame.
std::string loadFont(float scale);

/// A slider with its label beside it; `valueFormat` prints the value and its unit.
bool slider(const char* label, float* value, float min, float max, const char* valueFormat, ImGuiSliderFlags flags = 0);
bool slider(const char* label, int* value, int min, int max, const char* valueFormat = "%d",
            ImGuiSliderFlags flags = 0);
/// The label column for any other control (a combo box): the label wrapped in the column, the
/// cursor left beside it and the next item's width set to the rest of the line.
void labelColumn(const char* label);
/// A checkbox whose label wraps at the panel's edge instead of running past it.
bool checkbox(const char* label, bool* value);

/// printf-style text wrapped at the panel's width by wrapLines().
void textWrapped(const char* format, ...) IM_FMTARGS(1);
/// Text wrapped at the panel's width by wrapLines().
void textWrappedUnformatted(std::string_view text);

/// Splits `text` into lines no wider than `width` (as `measure` says) at spaces only, and never
/// at a space that joins a number to the word after it ("12.5 m/s", "3 boxes") or either side of
/// an '=' ("x = 4.0 m"): such groups move to the next line whole. A group wider than a line is
/// split at its spaces; a single word wider than a line gets a line of its own. '\n' breaks.
std::vector<std::string> wrapLines(std::string_view text, float width,
                                   const std::function<float(std::string_view)>& measure);

} // namespace impetus::samples
