#include "image_compare.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <unordered_map>
#include <unordered_set>

namespace impetus::testing {

std::optional<Image> readPng(const std::string& path) {
  int w = 0;
  int h = 0;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (data == nullptr) {
    return std::nullopt;
  }
  Image image{w, h,
              std::vector<unsigned char>(data, data + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3)};
  stbi_image_free(data);
  return image;
}

std::size_t distinctColours(const Image& image) {
  std::unordered_set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    colours.insert(static_cast<std::uint32_t>(image.rgb[i]) << 16 | static_cast<std::uint32_t>(image.rgb[i + 1]) << 8 |
                   image.rgb[i + 2]);
  }
  return colours.size();
}

double fractionBeyondCommonest(const Image& image, std::size_t common) {
  std::unordered_map<std::uint32_t, std::size_t> counts;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    ++counts[static_cast<std::uint32_t>(image.rgb[i]) << 16 | static_cast<std::uint32_t>(image.rgb[i + 1]) << 8 |
             image.rgb[i + 2]];
  }
  std::vector<std::size_t> sorted;
  for (const auto& [colour, n] : counts) {
    sorted.push_back(n);
  }
  std::sort(sorted.begin(), sorted.end(), std::greater<>());
  std::size_t beyond = 0;
  for (std::size_t i = common; i < sorted.size(); ++i) {
    beyond += sorted[i];
  }
  const std::size_t pixels = image.rgb.size() / 3;
  return pixels == 0 ? 0.0 : static_cast<double>(beyond) / static_cast<double>(pixels);
}

double differingFraction(const Image& image, const Image& reference, int tolerance) {
  if (image.width != reference.width || image.height != reference.height || image.rgb.size() != reference.rgb.size()) {
    return 1.0;
  }
  std::size_t differing = 0;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (std::abs(static_cast<int>(image.rgb[i + c]) - static_cast<int>(reference.rgb[i + c])) > tolerance) {
        ++differing;
        break;
      }
    }
  }
  return static_cast<double>(differing) / static_cast<double>(image.rgb.size() / 3);
}

} // namespace impetus::testing
