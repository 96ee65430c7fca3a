// Parsing, validation and printing for `impetus calc`.
#include "calc/calc.hpp"
#include "numbers.hpp"

#include <impetus/error.hpp>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

namespace impetus::cli {
namespace {

using nlohmann::ordered_json;

/// A usage problem: reported as one line on stderr with exit status 2.
struct UsageError {
  std::string message;
};

ordered_json toJson(const Value& value) {
  return std::visit([](const auto& v) { return ordered_json(v); }, value);
}

std::string formatNumber(double v) { return fmt::format("{:.10g}", v); }

std::string toText(const Value& value) {
  struct Visitor {
    std::string operator()(double v) const { return formatNumber(v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return v; }
    std::string operator()(const Vector& v) const {
      std::string s = "(";
      for (std::size_t i = 0; i < v.size(); ++i) {
        s += (i > 0 ? ", " : "") + formatNumber(v[i]);
      }
      return s + ")";
    }
    std::string operator()(const Matrix& m) const {
      std::string s = "[";
      for (std::size_t i = 0; i < m.size(); ++i) {
        s += (i > 0 ? ", " : "") + (*this)(m[i]);
      }
      return s + "]";
    }
  };
  return std::visit(Visitor{}, value);
}

ordered_json modelJson(const Model& m) {
  ordered_json params = ordered_json::array();
  for (const Param& p : m.params) {
    ordered_json j{{"name", p.name},
                   {"unit", p.unit},
                   {"help", p.help},
                   {"kind", p.kind == ParamKind::number ? "number" : (p.kind == ParamKind::text ? "text" : "path")},
                   {"required", !p.defaultValue.has_value()}};
    j["default"] = p.defaultValue ? ordered_json(*p.defaultValue) : ordered_json(nullptr);
    params.push_back(std::move(j));
  }
  return {{"name", m.name}, {"topic", m.topic}, {"summary", m.summary}, {"params", std::move(params)}};
}

std::string paramLine(const Param& p) {
  std::string line = fmt::format("    --{}", p.name);
  if (!p.unit.empty()) {
    line += fmt::format(" [{}]", p.unit);
  }
  line += fmt::format("  {}", p.help);
  if (!p.defaultValue) {
    line += " (required)";
  } else if (p.defaultValue->empty()) {
    line += " (optional)";
  } else {
    line += fmt::format(" (default {})", *p.defaultValue);
  }
  return line;
}

void printList(bool json) {
  if (json) {
    ordered_json models = ordered_json::array();
    for (const Model& m : registry().models()) {
      models.push_back(modelJson(m));
    }
    fmt::print("{}\n", models.dump(2));
    return;
  }
  std::string topic;
  for (const Model& m : registry().models()) {
    if (m.topic != topic) {
      topic = m.topic;
      fmt::print("\n{}\n", topic);
    }
    fmt::print("  {:<24} {}\n", m.name, m.summary);
    for (const Param& p : m.params) {
      fmt::print("{}\n", paramLine(p));
    }
  }
}

void printModelHelp(const Model& m) {
  fmt::print("impetus calc {} [--param value ...] [--json]\n{}\n({})\n\nparameters:\n", m.name, m.summary, m.topic);
  for (const Param& p : m.params) {
    fmt::print("{}\n", paramLine(p));
  }
}

Args parseArgs(const Model& model, const std::vector<std::string>& extra, bool& json, bool& help) {
  std::map<std::string, std::string> values;
  for (std::size_t i = 0; i < extra.size(); ++i) {
    const std::string& token = extra[i];
    if (token == "--json") {
      json = true;
      continue;
    }
    if (token == "--help" || token == "-h") {
      help = true;
      continue;
    }
    if (token.size() < 3 || token.rfind("--", 0) != 0) {
      throw UsageError{
          fmt::format("unexpected argument '{}' for model '{}' (parameters are --name value)", token, model.name)};
    }
    std::string name = token.substr(2);
    std::string value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name.resize(eq);
    } else if (i + 1 < extra.size()) {
      value = extra[++i];
    } else {
      throw UsageError{fmt::format("--{}: missing value", name)};
    }
    const bool known =
        std::any_of(model.params.begin(), model.params.end(), [&](const Param& p) { return p.name == name; });
    if (!known) {
      throw UsageError{fmt::format("unknown parameter --{} for model '{}' (impetus calc {} --help lists them)", name,
                                   model.name, model.name)};
    }
    if (values.contains(name)) {
      throw UsageError{fmt::format("--{} given twice", name)};
    }
    values[name] = value;
  }
  std::map<std::string, double> numbers;
  if (help) {
    return Args(values, numbers);
  }
  for (const Param& p : model.params) {
    auto it = values.find(p.name);
    if (it == values.end()) {
      if (!p.defaultValue) {
        throw UsageError{fmt::format("missing parameter --{} [{}] for model '{}'", p.name, p.unit, model.name)};
      }
      it = values.emplace(p.name, *p.defaultValue).first;
    }
    if (p.kind == ParamKind::number) {
      numbers[p.name] = parseParameter(p.name, it->second);
    }
  }
  return Args(std::move(values), std::move(numbers));
}

void printResult(const Model& model, const Args& args, const Result& result, bool json) {
  if (json) {
    ordered_json inputs = ordered_json::object();
    for (const Param& p : model.params) {
      const std::string& raw = args.text(p.name);
      ordered_json value = p.kind == ParamKind::number ? ordered_json(args.number(p.name)) : ordered_json(raw);
      inputs[p.name] = {{"value", std::move(value)}, {"unit", p.unit}};
    }
    ordered_json outputs = ordered_json::object();
    for (const Output& o : result.outputs) {
      outputs[o.name] = {{"value", toJson(o.value)}, {"unit", o.unit}};
    }
    const ordered_json doc{
        {"model", model.name}, {"inputs", std::move(inputs)}, {"outputs", std::move(outputs)}, {"notes", result.notes}};
    fmt::print("{}\n", doc.dump(2));
    return;
  }
  fmt::print("{}: {}\n", model.name, model.summary);
  for (const Param& p : model.params) {
    const std::string& value = args.text(p.name);
    fmt::print("  {:<22} = {}\n", p.name, value.empty() ? "(not given)" : value + " " + p.unit);
  }
  fmt::print("results:\n");
  for (const Output& o : result.outputs) {
    fmt::print("  {:<22} = {} {}\n", o.name, toText(o.value), o.unit);
  }
  for (const std::string& note : result.notes) {
    fmt::print("note: {}\n", note);
  }
}

/// "innerRadius" -> "inner-radius": the library's field names as the CLI spells parameters.
std::string kebabCase(const std::string& field) {
  std::string out;
  for (const char c : field) {
    if (c >= 'A' && c <= 'Z') {
      out += '-';
      out += static_cast<char>(c - 'A' + 'a');
    } else {
      out += c;
    }
  }
  return out;
}

/// The library's camelCase name of a parameter: "inner-radius" -> "innerRadius".
std::string camelCase(const std::string& param) {
  std::string out;
  for (std::size_t i = 0; i < param.size(); ++i) {
    if (param[i] == '-' && i + 1 < param.size()) {
      out += static_cast<char>(std::toupper(static_cast<unsigned char>(param[++i])));
    } else {
      out += param[i];
    }
  }
  return out;
}

/// The reason of a message ("must not exceed outerRadius") with every other parameter of the
/// model that it names spelled as the user types it ("must not exceed --outer-radius").
std::string withParameterNames(const Model& model, std::string reason) {
  for (const Param& p : model.params) {
    const std::string library = camelCase(p.name);
    if (library == p.name) {
      continue; // one word: the same in both spellings, and too common to rewrite in prose
    }
    for (std::size_t at = reason.find(library); at != std::string::npos; at = reason.find(library, at)) {
      const bool wordStart = at == 0 || !std::isalnum(static_cast<unsigned char>(reason[at - 1]));
      const std::size_t end = at + library.size();
      const bool wordEnd = end == reason.size() || !std::isalnum(static_cast<unsigned char>(reason[end]));
      if (wordStart && wordEnd) {
        reason.replace(at, library.size(), "--" + p.name);
        at += p.name.size() + 2;
      } else {
        at = end;
      }
    }
  }
  return reason;
}

/// Rewrites "innerRadius = 2: must not exceed outerRadius" as "--inner-radius = 2: must not
/// exceed --outer-radius" when the library's field is one of the model's parameters, so the
/// message names what the user typed.
std::string asParameterMessage(const Model& model, const Error& e) {
  std::string what = e.what();
  const auto isParam = [&](const std::string& name) {
    return std::any_of(model.params.begin(), model.params.end(), [&](const Param& p) { return p.name == name; });
  };
  const std::string param = kebabCase(e.field());
  if (isParam(param) && what.rfind(e.field(), 0) == 0) {
    return "--" + param + withParameterNames(model, what.substr(e.field().size()));
  }
  // A component of a vector parameter: "fluidVelocity.x = nan: ..." -> "--fluid-velocity.x = nan: ...".
  const std::size_t dot = e.field().rfind('.');
  if (dot != std::string::npos && isParam(kebabCase(e.field().substr(0, dot))) && what.rfind(e.field(), 0) == 0) {
    return "--" + kebabCase(e.field().substr(0, dot)) + withParameterNames(model, what.substr(dot));
  }
  return what;
}

} // namespace

double parseParameter(const std::string& name, const std::string& text) {
  try {
    return cli::parseNumber("--" + name, text);
  } catch (const Error& e) {
    throw Error(name, e.what()); // the model's field, as the other refusals name it
  }
}

double Args::number(const std::string& name) const {
  const auto it = numbers_.find(name);
  if (it == numbers_.end()) {
    throw std::logic_error("calc model read an undeclared number parameter: " + name);
  }
  return it->second;
}

const std::string& Args::text(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) {
    throw std::logic_error("calc model read an undeclared parameter: " + name);
  }
  return it->second;
}

namespace {

/// The first number of `value` that is not finite, if any.
std::optional<double> firstNonFinite(const Value& value) {
  std::optional<double> found;
  const auto check = [&](double x) {
    if (!found && !std::isfinite(x)) {
      found = x;
    }
  };
  if (const auto* x = std::get_if<double>(&value)) {
    check(*x);
  } else if (const auto* v = std::get_if<Vector>(&value)) {
    std::for_each(v->begin(), v->end(), check);
  } else if (const auto* m = std::get_if<Matrix>(&value)) {
    for (const Vector& row : *m) {
      std::for_each(row.begin(), row.end(), check);
    }
  }
  return found;
}

/// A model's inputs may each be valid and still overflow double, or leave an explicit method past
/// its stability limit: such a result is refused, naming the output, never printed as inf or nan.
void requireFiniteOutputs(const Result& result) {
  for (const Output& out : result.outputs) {
    if (const std::optional<double> bad = firstNonFinite(out.value)) {
      throwInvalid(out.name, *bad,
                   "the result is not finite for these inputs (they overflow, or take the model outside its "
                   "range)");
    }
  }
}

} // namespace

int runCalc(bool list, bool json, const std::string& modelName, const std::vector<std::string>& extraArgs) {
  const Model* model = nullptr;
  try {
    if (list) {
      printList(json || std::find(extraArgs.begin(), extraArgs.end(), "--json") != extraArgs.end());
      return 0;
    }
    if (modelName.empty()) {
      throw UsageError{"missing model name (impetus calc --list lists the models)"};
    }
    model = registry().find(modelName);
    if (model == nullptr) {
      throw UsageError{fmt::format("unknown model '{}' (impetus calc --list lists the models)", modelName)};
    }
    bool help = false;
    const Args args = parseArgs(*model, extraArgs, json, help);
    if (help) {
      if (json) {
        fmt::print("{}\n", modelJson(*model).dump(2));
      } else {
        printModelHelp(*model);
      }
      return 0;
    }
    const Result result = model->evaluate(args);
    requireFiniteOutputs(result);
    printResult(*model, args, result, json);
    return 0;
  } catch (const UsageError& e) {
    fmt::print(stderr, "error: {}\n", e.message);
  } catch (const Error& e) {
    fmt::print(stderr, "error: {}\n", model != nullptr ? asParameterMessage(*model, e) : std::string(e.what()));
  }
  return 2;
}

} // namespace impetus::cli
