#include "screenshot.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <stb_image_write.h>

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace impetus::samples {

void saveScreenshot(const std::filesystem::path& path, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw std::runtime_error("screenshot: empty framebuffer");
  }
  const auto w = static_cast<std::size_t>(width);
  const auto h = static_cast<std::size_t>(height);
  std::vector<unsigned char> pixels(w * h * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  if (glGetError() != GL_NO_ERROR) {
    throw std::runtime_error("screenshot: glReadPixels failed");
  }
  // GL's rows run bottom-up; PNG's top-down.
  std::vector<unsigned char> flipped(pixels.size());
  const std::size_t row = w * 3;
  for (std::size_t y = 0; y < h; ++y) {
    std::memcpy(flipped.data() + y * row, pixels.data() + (h - 1 - y) * row, row);
  }
  if (stbi_write_png(path.c_str(), width, height, 3, flipped.data(), static_cast<int>(row)) == 0) {
    throw std::runtime_error("cannot write the screenshot '" + path.string() + "'");
  }
}

void checkWritable(const std::filesystem::path& path) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw std::runtime_error("cannot write '" + path.string() + "': directory '" + dir.string() + "' does not exist");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw std::runtime_error("cannot write '" + path.string() + "': it is a directory");
  }
  const bool existed = std::filesystem::exists(path, ec);
  {
    std::ofstream probe(path, std::ios::binary | std::ios::app);
    if (!probe) {
      throw std::runtime_error("cannot write '" + path.string() + "': " + std::strerror(errno));
    }
  }
  if (!existed) {
    std::filesystem::remove(path, ec); // leave nothing behind if the run fails later
  }
}

} // namespace impetus::samples
