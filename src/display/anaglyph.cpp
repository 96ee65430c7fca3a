#include <impetus/display/anaglyph.hpp>
#include <impetus/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace impetus::display {
namespace {

void requirePixel(const Rgb& c, std::string_view field) {
  for (const double v : {c.r, c.g, c.b}) {
    if (!(std::isfinite(v) && v >= 0.0 && v <= 1.0)) {
      throwInvalid(field, v, "channels must be in [0, 1]");
    }
  }
}

using Matrix3 = std::array<std::array<double, 3>, 3>;

// Dubois' red-cyan least-squares matrices (linear RGB), rows = output r, g, b.
constexpr Matrix3 duboisLeft{{{0.456, 0.500, 0.176}, {-0.040, -0.038, -0.016}, {-0.015, -0.021, -0.005}}};
constexpr Matrix3 duboisRight{{{-0.043, -0.088, -0.002}, {0.378, 0.734, -0.018}, {-0.072, -0.113, 1.226}}};

Rgb times(const Matrix3& m, const Rgb& c) {
  return {m[0][0] * c.r + m[0][1] * c.g + m[0][2] * c.b, m[1][0] * c.r + m[1][1] * c.g + m[1][2] * c.b,
          m[2][0] * c.r + m[2][1] * c.g + m[2][2] * c.b};
}

Rgb map(const Rgb& c, double (*f)(double)) { return {f(c.r), f(c.g), f(c.b)}; }
double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

} // namespace

double srgbToLinear(double encoded) noexcept {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double linear) noexcept {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

Rgb anaglyph(const Rgb& left, const Rgb& right, AnaglyphMode mode, AnaglyphEncoding encoding) {
  requirePixel(left, "left");
  requirePixel(right, "right");
  // An enum value cast from an out-of-range integer would otherwise give black or skip the
  // sRGB conversion silently.
  if (static_cast<int>(mode) < static_cast<int>(AnaglyphMode::trueAnaglyph) ||
      static_cast<int>(mode) > static_cast<int>(AnaglyphMode::dubois)) {
    throwInvalid("mode", static_cast<int>(mode), "is not an AnaglyphMode");
  }
  if (encoding != AnaglyphEncoding::srgb && encoding != AnaglyphEncoding::linear) {
    throwInvalid("encoding", static_cast<int>(encoding), "is not an AnaglyphEncoding");
  }
  switch (mode) {
  case AnaglyphMode::trueAnaglyph:
    return {luma(left), 0.0, luma(right)};
  case AnaglyphMode::gray:
    return {luma(left), luma(right), luma(right)};
  case AnaglyphMode::color:
    return {left.r, right.g, right.b};
  case AnaglyphMode::halfColor:
    return {luma(left), right.g, right.b};
  case AnaglyphMode::optimized:
    return {0.7 * left.g + 0.3 * left.b, right.g, right.b};
  case AnaglyphMode::dubois: {
    const bool srgb = encoding == AnaglyphEncoding::srgb;
    const Rgb l = srgb ? map(left, srgbToLinear) : left;
    const Rgb r = srgb ? map(right, srgbToLinear) : right;
    const Rgb a = times(duboisLeft, l);
    const Rgb b = times(duboisRight, r);
    const Rgb out = map({a.r + b.r, a.g + b.g, a.b + b.b}, clamp01);
    return srgb ? map(out, linearToSrgb) : out;
  }
  }
  return {};
}

void anaglyphImage(std::span<const Rgb> left, std::span<const Rgb> right, std::span<Rgb> out, AnaglyphMode mode,
                   AnaglyphEncoding encoding) {
  if (right.size() != left.size()) {
    throwInvalid("right", static_cast<double>(right.size()), "must have as many pixels as left");
  }
  if (out.size() != left.size()) {
    throwInvalid("out", static_cast<double>(out.size()), "must have as many pixels as left");
  }
  for (std::size_t i = 0; i < left.size(); ++i) {
    // The pixel at fault by its index, as arrays are named elsewhere ("left[3]").
    requirePixel(left[i], "left[" + std::to_string(i) + "]");
    requirePixel(right[i], "right[" + std::to_string(i) + "]");
    out[i] = anaglyph(left[i], right[i], mode, encoding);
  }
}

std::string_view toString(AnaglyphMode mode) noexcept {
  switch (mode) {
  case AnaglyphMode::trueAnaglyph:
    return "true";
  case AnaglyphMode::gray:
    return "gray";
  case AnaglyphMode::color:
    return "color";
  case AnaglyphMode::halfColor:
    return "half-color";
  case AnaglyphMode::optimized:
    return "optimized";
  case AnaglyphMode::dubois:
    return "dubois";
  }
  return "?";
}

AnaglyphMode anaglyphModeFromString(std::string_view name) {
  for (const AnaglyphMode m : {AnaglyphMode::trueAnaglyph, AnaglyphMode::gray, AnaglyphMode::color,
                               AnaglyphMode::halfColor, AnaglyphMode::optimized, AnaglyphMode::dubois}) {
    if (toString(m) == name) {
      return m;
    }
  }
  throw Error("mode", "mode = '" + std::string(name) + "': must be true, gray, color, half-color, optimized or dubois");
}

} // namespace impetus::display
