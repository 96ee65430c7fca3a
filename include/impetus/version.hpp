#pragma once

namespace impetus {

inline constexpr int versionMajor = 0;
inline constexpr int versionMinor = 1;
inline constexpr int versionPatch = 0;
inline constexpr const char* versionString = "0.1.0";

} // namespace impetus
