// Recorded touch input: frames of contact points over time, to drive the touch models (tracker,
// gestures, the touch explosion) reproducibly from a file, a test or the command line.
//
// Text form, one frame per line or separated by ';':   TIME: X,Y X,Y ...
// TIME in s (non-decreasing), each point "X,Y" in the recording's unit (pixels on a screen with
// y down, as touch APIs report them); a frame with no points ("0.5:") means every finger is up.
// Example, a tap then a two-finger pinch:  "0:100,200; 0.1:; 0.5:50,50 150,50; 0.6:40,50 160,50; 0.7:"
#pragma once

#include <impetus/math/vec2.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace impetus::sensors {

struct TouchFrame {
  double time = 0.0;         ///< s
  std::vector<Vec2d> points; ///< the contacts down at `time`
};

/// Parses the text form. Throws impetus::Error (field "recording") naming the frame that does
/// not parse, has a non-finite number or goes back in time.
[[nodiscard]] std::vector<TouchFrame> parseTouchRecording(std::string_view text);

/// The text form of `frames` (parseTouchRecording reads it back exactly: 17 significant digits).
[[nodiscard]] std::string formatTouchRecording(const std::vector<TouchFrame>& frames);

} // namespace impetus::sensors
