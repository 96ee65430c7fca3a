#include <impetus/error.hpp>

#include <array>
#include <charconv>

namespace impetus {

Error::Error(std::string_view field, std::string_view message)
    : std::runtime_error(std::string(message)), field_(field) {}

std::string formatValue(double value) {
  if (std::isnan(value)) {
    return "nan";
  }
  if (std::isinf(value)) {
    return value > 0 ? "inf" : "-inf";
  }
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return {buffer.data(), result.ptr};
}

std::string formatFloat(float value) {
  if (!std::isfinite(value)) {
    return formatValue(value);
  }
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return {buffer.data(), result.ptr};
}

void throwInvalid(std::string_view field, double value, std::string_view requirement) {
  std::string message;
  message.append(field).append(" = ").append(formatValue(value)).append(": ").append(requirement);
  throw Error(field, message);
}

} // namespace impetus
