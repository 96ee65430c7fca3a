#include "numbers.hpp"

#include <impetus/error.hpp>

#include <fmt/core.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace impetus::cli {

double parseNumber(const std::string& option, const std::string& text) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  // std::from_chars does not accept a leading '+'; allow it as people type it.
  if (first != last && *first == '+') {
    ++first;
  }
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range && ptr == last) {
    // from_chars leaves the value unset: strtod tells an overflow (huge) from an underflow (tiny).
    errno = 0;
    const double nearest = std::strtod(std::string(first, last).c_str(), nullptr);
    const bool overflows = std::abs(nearest) > 1.0;
    throw Error(option, fmt::format("{} = {}: {}", option, text,
                                    overflows ? fmt::format("overflows: beyond {:g} in magnitude",
                                                            std::numeric_limits<double>::max())
                                              : fmt::format("underflows: below {:g} in magnitude (use 0)",
                                                            std::numeric_limits<double>::min())));
  }
  if (text.empty() || ec != std::errc() || ptr != last) {
    throw Error(option, fmt::format("{} = {}: not a number", option, text.empty() ? "''" : text));
  }
  return value;
}

std::int64_t parseWholeNumber(const std::string& option, const std::string& text, std::int64_t lowest,
                              std::int64_t highest) {
  const std::string requirement = fmt::format("must be a whole number from {} to {}", lowest, highest);
  double value = 0.0;
  try {
    value = parseNumber(option, text);
  } catch (const Error&) {
    throw Error(option, fmt::format("{} = {}: {}", option, text.empty() ? "''" : text, requirement));
  }
  if (!(value >= static_cast<double>(lowest) && value <= static_cast<double>(highest)) || value != std::floor(value)) {
    throw Error(option, fmt::format("{} = {}: {}", option, text, requirement));
  }
  return static_cast<std::int64_t>(value);
}

} // namespace impetus::cli
