// The `impetus calc` framework: every model of the library registers a named entry with typed,
// unit-bearing parameters; the framework parses `--param value` pairs, validates them, runs the
// model and prints its outputs as text or JSON. A model plugs in by adding one register
// function (see registry.cpp).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace impetus::cli {

enum class ParamKind {
  number, ///< a finite or non-finite double; the model validates its range
  text,   ///< free text (a list of points, a name)
  path,   ///< a file path
};

struct Param {
  std::string name;                        ///< given as --name
  std::string unit;                        ///< SI unit, "" for dimensionless or text
  std::string help;                        ///< one line
  std::optional<std::string> defaultValue; ///< none: the parameter is required
  ParamKind kind = ParamKind::number;
};

/// The parsed parameter values of one evaluation, every one present (defaults filled in).
class Args {
public:
  explicit Args(std::map<std::string, std::string> values, std::map<std::string, double> numbers)
      : values_(std::move(values)), numbers_(std::move(numbers)) {}
  [[nodiscard]] double number(const std::string& name) const;
  [[nodiscard]] const std::string& text(const std::string& name) const;
  [[nodiscard]] const std::map<std::string, std::string>& all() const noexcept { return values_; }

private:
  std::map<std::string, std::string> values_;
  std::map<std::string, double> numbers_;
};

using Vector = std::vector<double>;
using Matrix = std::vector<std::vector<double>>;
using Value = std::variant<double, Vector, Matrix, std::string, bool>;

struct Output {
  std::string name;
  Value value;
  std::string unit; ///< "" for dimensionless
  std::string help; ///< optional one-line meaning
};

struct Result {
  std::vector<Output> outputs;
  std::vector<std::string> notes; ///< remarks, e.g. where the book differs

  void add(std::string name, Value value, std::string unit = {}, std::string help = {}) {
    outputs.push_back({std::move(name), std::move(value), std::move(unit), std::move(help)});
  }
};

struct Model {
  std::string name;    ///< e.g. "inertia-box"
  std::string topic;   ///< e.g. "mass properties (ch. 1)"
  std::string summary; ///< one line
  std::vector<Param> params;
  std::function<Result(const Args&)> evaluate;
};

class Registry {
public:
  /// Adds a model; a second model with the same name is a programming error (throws).
  void add(Model model);
  [[nodiscard]] const Model* find(const std::string& name) const noexcept;
  [[nodiscard]] std::span<const Model> models() const noexcept { return models_; }

private:
  std::vector<Model> models_;
};

/// Parses a number the way every parameter is parsed (a leading '+' is allowed; "nan" and
/// "inf" parse and are left to the model to reject). Throws impetus::Error naming --name.
[[nodiscard]] double parseParameter(const std::string& name, const std::string& text);

/// Every model of the library, in a fixed order.
[[nodiscard]] const Registry& registry();

/// `impetus calc ...` after the word "calc": returns the process exit status (0 ok, 2 usage or
/// invalid input). Writes results to stdout and a one-line error to stderr.
int runCalc(bool list, bool json, const std::string& modelName, const std::vector<std::string>& extraArgs);

// Register functions, one per topic.
void registerMassModels(Registry& registry);
void registerKinematicsModels(Registry& registry);
void registerForceModels(Registry& registry);
void registerKineticsModels(Registry& registry);
void registerImpactModels(Registry& registry);
void registerProjectileModels(Registry& registry);
void registerCannonModels(Registry& registry);
void registerSensorsModels(Registry& registry);
void registerDisplayModels(Registry& registry);
void registerRelativityModels(Registry& registry);
void registerIntegratorModels(Registry& registry);
void registerGeoModels(Registry& registry);
void registerAudioModels(Registry& registry);

} // namespace impetus::cli
