// Anaglyph stereo (ch. 24): one picture for red/cyan glasses from a left and a right image.
//
// The left eye looks through the red filter and the right eye through the cyan (green + blue)
// one, so the left image goes to the red channel and the right image to green and blue; the
// methods differ in how much colour survives and how much leaks to the wrong eye (ghosting) or
// makes the eyes disagree on brightness (retinal rivalry). Per pixel, with Y = 0.299 r + 0.587 g
// + 0.114 b (Rec. 601 luma):
//   true        (Y(L), 0, Y(R))        dark, no colour, least ghosting
//   gray        (Y(L), Y(R), Y(R))     no colour, brighter
//   color       (L.r, R.g, R.b)        full colour, but pure reds and cyans reach one eye only
//   half-color  (Y(L), R.g, R.b)       colour on the right, less rivalry on the red channel
//   optimized   (0.7 L.g + 0.3 L.b, R.g, R.b)  half-color without the left eye's red (less rivalry)
//   dubois      least-squares projection (E. Dubois, "A projection method to generate anaglyph
//               stereo images", ICASSP 2001) through the filters' measured spectra: out =
//               clip(M_L L + M_R R) in linear light, with his red-cyan matrices
//               M_L = [ 0.456  0.500  0.176; -0.040 -0.038 -0.016; -0.015 -0.021 -0.005]
//               M_R = [-0.043 -0.088 -0.002;  0.378  0.734 -0.018; -0.072 -0.113  1.226]
// Pixels are in [0, 1]. The first five mix the stored (gamma-encoded) values, as image tools do;
// dubois converts sRGB to linear light, projects, clips to [0, 1] and converts back, as Dubois'
// method requires (`AnaglyphEncoding::linear` skips the conversions for linear input).
#pragma once

#include <span>
#include <string_view>

namespace impetus::display {

struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;
  friend constexpr bool operator==(const Rgb&, const Rgb&) = default;
};

enum class AnaglyphMode { trueAnaglyph, gray, color, halfColor, optimized, dubois };
enum class AnaglyphEncoding { srgb, linear };

/// 0.299 r + 0.587 g + 0.114 b.
[[nodiscard]] constexpr double luma(const Rgb& c) noexcept { return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b; }

/// The sRGB transfer function (IEC 61966-2-1) and its inverse, per channel in [0, 1].
[[nodiscard]] double srgbToLinear(double encoded) noexcept;
[[nodiscard]] double linearToSrgb(double linear) noexcept;

/// One pixel. Throws impetus::Error (field "left" or "right") when a channel is outside [0, 1] or
/// not finite, "mode" or "encoding" for a value outside its enumeration.
[[nodiscard]] Rgb anaglyph(const Rgb& left, const Rgb& right, AnaglyphMode mode,
                           AnaglyphEncoding encoding = AnaglyphEncoding::srgb);

/// A whole image (the three spans of equal size, row by row). Throws impetus::Error naming
/// "right" or "out" when the sizes differ, or the bad pixel by its index ("left[3]").
void anaglyphImage(std::span<const Rgb> left, std::span<const Rgb> right, std::span<Rgb> out, AnaglyphMode mode,
                   AnaglyphEncoding encoding = AnaglyphEncoding::srgb);

[[nodiscard]] std::string_view toString(AnaglyphMode mode) noexcept;
/// The mode named "true", "gray", "color", "half-color", "optimized" or "dubois"; throws
/// impetus::Error (field "mode") for any other name.
[[nodiscard]] AnaglyphMode anaglyphModeFromString(std::string_view name);

} // namespace impetus::display
