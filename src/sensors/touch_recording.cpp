#include <impetus/error.hpp>
#include <impetus/sensors/touch_recording.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>

namespace impetus::sensors {
namespace {

// Messages are appended piece by piece: GCC 12 warns falsely (-Wrestrict) on chains of
// std::string operator+ with literals.
[[noreturn]] void bad(std::size_t frame, std::initializer_list<std::string_view> why) {
  std::string message = "recording: frame ";
  message.append(std::to_string(frame + 1)).append(": ");
  for (const std::string_view piece : why) {
    message.append(piece);
  }
  throw Error("recording", message);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) {
    s.remove_prefix(1);
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
    s.remove_suffix(1);
  }
  return s;
}

double number(std::string_view s, std::size_t frame) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
  }
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || end != s.data() + s.size() || s.empty()) {
    bad(frame, {"'", s, "' is not a number"});
  }
  if (!std::isfinite(v)) {
    bad(frame, {"'", s, "' is not finite"});
  }
  return v;
}

} // namespace

std::vector<TouchFrame> parseTouchRecording(std::string_view text) {
  std::vector<TouchFrame> frames;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find_first_of(";\n", pos);
    if (end == std::string_view::npos) {
      end = text.size();
    }
    const std::string_view item = trim(text.substr(pos, end - pos));
    pos = end + 1;
    if (item.empty()) {
      continue;
    }
    const std::size_t k = frames.size();
    const std::size_t colon = item.find(':');
    if (colon == std::string_view::npos) {
      bad(k, {"'", item, "' has no 'TIME:'"});
    }
    TouchFrame f;
    f.time = number(item.substr(0, colon), k);
    if (!frames.empty() && f.time < frames.back().time) {
      const std::string t = formatValue(f.time);
      bad(k, {"time ", t, " goes back"});
    }
    std::string_view rest = trim(item.substr(colon + 1));
    while (!rest.empty()) {
      std::size_t space = rest.find_first_of(" \t");
      const std::string_view point = rest.substr(0, space);
      rest = space == std::string_view::npos ? std::string_view{} : trim(rest.substr(space));
      const std::size_t comma = point.find(',');
      if (comma == std::string_view::npos) {
        bad(k, {"point '", point, "' is not X,Y"});
      }
      f.points.push_back({number(point.substr(0, comma), k), number(point.substr(comma + 1), k)});
    }
    frames.push_back(std::move(f));
  }
  return frames;
}

std::string formatTouchRecording(const std::vector<TouchFrame>& frames) {
  std::string out;
  char buffer[64];
  for (const TouchFrame& f : frames) {
    std::snprintf(buffer, sizeof buffer, "%.17g:", f.time);
    out += buffer;
    for (const Vec2d& p : f.points) {
      std::snprintf(buffer, sizeof buffer, " %.17g,%.17g", p.x, p.y);
      out += buffer;
    }
    out += '\n';
  }
  return out;
}

} // namespace impetus::sensors
