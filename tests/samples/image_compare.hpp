// Reading screenshots back (stb_image) and comparing them: the samples tests' image checks.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace impetus::testing {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgb; ///< width * height * 3, top row first
};

/// The PNG at `path` as RGB, or none when it cannot be read.
[[nodiscard]] std::optional<Image> readPng(const std::string& path);

/// Number of distinct RGB colours.
[[nodiscard]] std::size_t distinctColours(const Image& image);

/// Fraction of pixels (0 to 1) whose colour is not one of the `common` most frequent colours: what
/// is drawn beyond the background and the grid lines.
[[nodiscard]] double fractionBeyondCommonest(const Image& image, std::size_t common);

/// Fraction of pixels (0 to 1) that differ from the reference by more than `tolerance` (0-255)
/// in any channel; 1 when the sizes differ.
[[nodiscard]] double differingFraction(const Image& image, const Image& reference, int tolerance);

} // namespace impetus::testing
