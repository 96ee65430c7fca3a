#include "calc/values.hpp"

#include <impetus/error.hpp>

#include <algorithm>
#include <sstream>

namespace impetus::cli {

Param vectorParam(std::string name, std::string unit, std::string help, std::optional<std::string> defaultValue) {
  return {std::move(name), std::move(unit), std::move(help) + " as x,y,z", std::move(defaultValue), ParamKind::text};
}

Param optionalParam(std::string name, std::string unit, std::string help) {
  return {std::move(name), std::move(unit), std::move(help), std::string{}, ParamKind::text};
}

std::optional<double> optionalNumber(const Args& args, const std::string& name) {
  const std::string& text = args.text(name);
  if (text.empty()) {
    return std::nullopt;
  }
  return parseParameter(name, text);
}

Vec3d vector3(const Args& args, const std::string& name) {
  std::string text = args.text(name);
  std::replace(text.begin(), text.end(), ',', ' ');
  std::istringstream in(text);
  std::vector<double> values;
  for (std::string token; in >> token;) {
    values.push_back(parseParameter(name, token));
  }
  if (values.size() != 3) {
    throw Error(name, "--" + name + " = '" + args.text(name) + "': expected three numbers x,y,z");
  }
  return {values[0], values[1], values[2]};
}

} // namespace impetus::cli
