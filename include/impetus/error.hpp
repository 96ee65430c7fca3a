// impetus::Error, the one exception Impetus throws, and the checks that raise it.
//
// This header sits below every layer (math included): it has no dependency but the standard
// library, so the math types can refuse a singular matrix or a zero rotation axis with the same
// error the rest of the library uses.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

namespace impetus {

/// Raised when something is created or evaluated from values that make no physical or
/// mathematical sense. The message always names the offending field and its value, e.g.
/// "mass = -2: must be positive".
class Error : public std::runtime_error {
public:
  Error(std::string_view field, std::string_view message);

  /// The name of the parameter, field or argument that was rejected.
  [[nodiscard]] const std::string& field() const noexcept { return field_; }

private:
  std::string field_;
};

/// Formats a value the way error messages show it: shortest round-trip decimal, "nan", "inf".
[[nodiscard]] std::string formatValue(double value);
/// A float as error messages show it: its own shortest round-trip decimal (1e+30, not the
/// 1.0000000150474662e+30 of its double).
[[nodiscard]] std::string formatFloat(float value);

/// Throws Error("<field> = <value>: <requirement>").
[[noreturn]] void throwInvalid(std::string_view field, double value, std::string_view requirement);

/// Returns `value` when finite, otherwise throws naming `field`.
inline double requireFinite(double value, std::string_view field) {
  if (!std::isfinite(value)) {
    throwInvalid(field, value, "must be finite");
  }
  return value;
}

/// Returns `value` when finite and > 0, otherwise throws naming `field`.
inline double requirePositive(double value, std::string_view field) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throwInvalid(field, value, "must be finite and positive");
  }
  return value;
}

/// Returns `value` when finite and >= 0, otherwise throws naming `field`.
inline double requireNonNegative(double value, std::string_view field) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throwInvalid(field, value, "must be finite and non-negative");
  }
  return value;
}

} // namespace impetus
