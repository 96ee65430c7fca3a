// Reads a composite body (a list of primitive parts with masses, positions and orientations)
// from a JSON file: the input of `impetus calc composite`. Format: docs/composite-format.md.
#pragma once

#include <impetus/core/mass_properties.hpp>

#include <string>
#include <vector>

namespace impetus::cli {

struct CompositeBody {
  std::vector<std::string> names;
  std::vector<MassPart> parts;
  double gravity = 0.0; ///< m/s^2, used to turn part weights into masses
};

/// Parses a composite body document. Throws impetus::Error naming the offending key
/// (e.g. "parts[2].size[0]") for malformed JSON, unknown keys, missing or invalid values.
[[nodiscard]] CompositeBody parseComposite(const std::string& jsonText);

/// Reads and parses a file; an unreadable file is an impetus::Error naming the path.
[[nodiscard]] CompositeBody loadComposite(const std::string& path);

} // namespace impetus::cli
