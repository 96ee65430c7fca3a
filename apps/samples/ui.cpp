#include "ui.hpp"

#include <imgui.h>

#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>

namespace impetus::samples {
namespace {

/// Share of the panel's width given to a control's label; the control takes the rest.
constexpr float labelColumnShare = 0.42f;

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

/// Whether the word after a number reads as its unit or count: a letter, a symbol of a unit
/// ('%', '/', '^') or a non-ASCII sign (degrees, micro).
bool startsLikeAUnit(std::string_view word) {
  const auto c = static_cast<unsigned char>(word.front());
  return std::isalpha(c) != 0 || c == '%' || c == '/' || c == '^' || c >= 0x80;
}

/// Whether the space between two words must not break.
bool binds(std::string_view before, std::string_view after) {
  if (before.back() == '=' || after.front() == '=') {
    return true;
  }
  return isDigit(before.back()) && startsLikeAUnit(after);
}

std::vector<std::string_view> splitWords(std::string_view paragraph) {
  std::vector<std::string_view> words;
  std::size_t start = 0;
  while (start < paragraph.size()) {
    const std::size_t end = paragraph.find(' ', start);
    const std::size_t stop = end == std::string_view::npos ? paragraph.size() : end;
    if (stop > start) {
      words.push_back(paragraph.substr(start, stop - start));
    }
    start = stop + 1;
  }
  return words;
}

/// Fills lines greedily with `pieces` (each already free of breaks inside).
void fill(const std::vector<std::string>& pieces, float width, const std::function<float(std::string_view)>& measure,
          std::vector<std::string>& lines) {
  std::string line;
  for (const std::string& piece : pieces) {
    std::string candidate = line;
    if (!candidate.empty()) {
      candidate += ' ';
    }
    candidate += piece;
    if (line.empty() || measure(candidate) <= width) {
      line = std::move(candidate);
    } else {
      lines.push_back(std::move(line));
      line = piece;
    }
  }
  if (!line.empty()) {
    lines.push_back(std::move(line));
  }
}

} // namespace

void labelColumn(const char* label) {
  const float width = ImGui::GetContentRegionAvail().x * labelColumnShare;
  const float x = ImGui::GetCursorPosX();
  ImGui::AlignTextToFramePadding();
  ImGui::BeginGroup();
  for (const std::string& line : wrapLines(
           label, width, [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; })) {
    ImGui::TextUnformatted(line.c_str());
  }
  ImGui::EndGroup();
  ImGui::SameLine(x + width + ImGui::GetStyle().ItemSpacing.x);
  ImGui::SetNextItemWidth(-FLT_MIN);
}

namespace {

/// `control` (an ImGui widget labelled "##...") with `label` in the column beside it.
template <typename Control> bool labelled(const char* label, const Control& control) {
  ImGui::PushID(label);
  labelColumn(label);
  const bool changed = control();
  ImGui::PopID();
  return changed;
}

/// Where Debian's fonts-dejavu-core installs the font.
constexpr const char* fontCandidates[] = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/local/share/fonts/truetype/dejavu/DejaVuSans.ttf",
};

} // namespace

std::string loadFont(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  ImGui::GetStyle().ScaleAllSizes(scale);
  std::error_code error;
  for (const char* path : fontCandidates) {
    if (std::filesystem::is_regular_file(path, error) &&
        io.Fonts->AddFontFromFileTTF(path, std::round(panelFontPixels * scale)) != nullptr) {
      return path;
    }
  }
  ImFontConfig config;
  config.SizePixels = std::round(13.0f * scale); // ProggyClean is drawn for 13 px
  io.Fonts->AddFontDefault(&config);
  return {};
}

std::vector<std::string> wrapLines(std::string_view text, float width,
                                   const std::function<float(std::string_view)>& measure) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::size_t stop = end == std::string_view::npos ? text.size() : end;
    const std::vector<std::string_view> words = splitWords(text.substr(start, stop - start));
    // Groups of words joined by binding spaces.
    std::vector<std::vector<std::string_view>> groups;
    for (std::size_t i = 0; i < words.size(); ++i) {
      if (i > 0 && binds(words[i - 1], words[i])) {
        groups.back().push_back(words[i]);
      } else {
        groups.push_back({words[i]});
      }
    }
    std::vector<std::string> pieces;
    for (const auto& group : groups) {
      std::string joined;
      for (const std::string_view word : group) {
        joined += joined.empty() ? std::string(word) : ' ' + std::string(word);
      }
      if (measure(joined) <= width || group.size() == 1) {
        pieces.push_back(std::move(joined));
      } else { // wider than a line: its words are pieces of their own
        for (const std::string_view word : group) {
          pieces.emplace_back(word);
        }
      }
    }
    const std::size_t before = lines.size();
    fill(pieces, width, measure, lines);
    if (lines.size() == before && end != std::string_view::npos) {
      lines.emplace_back(); // an empty line between two '\n'
    }
    if (end == std::string_view::npos) {
      break;
    }
    start = end + 1;
  }
  return lines;
}

void textWrappedUnformatted(std::string_view text) {
  const float width = ImGui::GetContentRegionAvail().x;
  for (const std::string& line : wrapLines(
           text, width, [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; })) {
    ImGui::TextUnformatted(line.c_str());
  }
}

void textWrapped(const char* format, ...) {
  char text[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args); // NOLINT(clang-analyzer-valist.Uninitialized): va_start is above
  va_end(args);
  textWrappedUnformatted(text);
}

bool slider(const char* label, float* value, float min, float max, const char* valueFormat, ImGuiSliderFlags flags) {
  return labelled(label, [&] { return ImGui::SliderFloat("##slider", value, min, max, valueFormat, flags); });
}

bool slider(const char* label, int* value, int min, int max, const char* valueFormat, ImGuiSliderFlags flags) {
  return labelled(label, [&] { return ImGui::SliderInt("##slider", value, min, max, valueFormat, flags); });
}

bool checkbox(const char* label, bool* value) {
  ImGui::PushID(label);
  const bool changed = ImGui::Checkbox("##checkbox", value);
  ImGui::PopID();
  ImGui::SameLine();
  ImGui::BeginGroup();
  textWrappedUnformatted(label);
  ImGui::EndGroup();
  return changed;
}

} // namespace impetus::samples
