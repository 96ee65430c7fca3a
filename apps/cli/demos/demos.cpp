#include "demos/demos.hpp"

#include <fmt/core.h>

#include <functional>
#include <vector>

namespace impetus::cli {
namespace {

struct Demo {
  const char* name;
  const char* summary;
  std::function<int()> run;
};

const std::vector<Demo>& demos() {
  static const std::vector<Demo> all{
      {"car-driver-fuel", "the book's example 1.1: mass properties of a car, its driver and fuel (ch. 1)",
       demoCarDriverFuel},
      {"tumbling-box", "torque-free rotation of a box about its intermediate axis (ch. 1, 11): it flips",
       demoTumblingBox},
  };
  return all;
}

} // namespace

int runDemo(const std::string& name, bool list) {
  if (list) {
    for (const Demo& d : demos()) {
      fmt::print("{:<18} {}\n", d.name, d.summary);
    }
    return 0;
  }
  if (name.empty()) {
    int status = 0;
    for (const Demo& d : demos()) {
      fmt::print("== {} ==\n", d.name);
      status |= d.run();
      fmt::print("\n");
    }
    return status;
  }
  for (const Demo& d : demos()) {
    if (name == d.name) {
      return d.run();
    }
  }
  fmt::print(stderr, "error: unknown demo '{}' (impetus demo --list lists them)\n", name);
  return 2;
}

} // namespace impetus::cli
