// Screenshots: the frame's pixels (glReadPixels on the back buffer, before the swap) as a PNG
// (stb_image_write from Debian's libstb). Used by --screenshot and by F12 in the app.
#pragma once

#include <filesystem>

namespace impetus::samples {

/// Writes the current GL framebuffer (width x height drawable pixels) to `path` as an RGB PNG,
/// top row first. Throws std::runtime_error naming the path when the file cannot be written.
void saveScreenshot(const std::filesystem::path& path, int width, int height);

/// Checks, before any work is done, that `path` can be written: its directory exists and a file
/// can be created there. Throws std::runtime_error naming the path and the reason otherwise.
void checkWritable(const std::filesystem::path& path);

} // namespace impetus::samples
