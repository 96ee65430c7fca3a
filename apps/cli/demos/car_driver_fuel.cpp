// The book's example 1.1: a top-down racing game's car, seated driver and fuel tank, each a box
// with its weight (fuel: its density), combined into one body (ch. 1, table 1-2).
#include "demos/demos.hpp"

#include <impetus/core/mass_properties.hpp>
#include <impetus/core/solid.hpp>

#include <fmt/core.h>

#include <array>
#include <cmath>

namespace impetus::cli {

int demoCarDriverFuel(const DemoOptions& /*options*/) {
  constexpr double g = 9.8; // the book's value in chapter 1
  struct Item {
    const char* name;
    Vec3d size;     // length (x), width (y), height, m
    Vec3d position; // centroid, m
    double weight;  // N (fuel: from its density)
  };
  const Box fuelBox{{0.50, 0.90, 0.30}};
  const double fuelWeight = 750.0 * g * volume(fuelBox); // rho g V
  const std::array<Item, 3> items{{{"car", {4.70, 1.80, 1.25}, {30.5, 30.5, 0.0}, 17500.0},
                                   {"driver", {0.90, 0.50, 1.10}, {31.50, 31.00, 0.0}, 850.0},
                                   {"fuel", fuelBox.size, {28.00, 30.50, 0.0}, fuelWeight}}};
  std::array<MassPart, 3> parts{};
  for (std::size_t i = 0; i < items.size(); ++i) {
    const double mass = items[i].weight / g;
    parts[i] = {mass, items[i].position, inertiaTensor(Box{items[i].size}, mass), Mat33d::identity()};
  }
  const MassProperties3 body = combine(parts);

  fmt::print("fuel weight = rho g V = 750 x {} x {:.3f} = {:.2f} N\n", g, volume(fuelBox), fuelWeight);
  fmt::print("  (the book prints 920.6 N, which its own inputs do not give)\n\n");
  fmt::print("{:<8} {:>10} {:>12} {:>10} {:>12} {:>12} {:>15}\n", "part", "mass kg", "I_local", "d^2 m^2", "m d^2",
             "I_cg", "I_local / m d^2");
  std::array<double, 3> ratios{};
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Vec3d d = parts[i].position - body.centerOfMass;
    const double d2 = d.x * d.x + d.y * d.y; // about the axis out of the screen (z)
    const double local = parts[i].inertia(2, 2);
    ratios[i] = local / (parts[i].mass * d2);
    fmt::print("{:<8} {:>10.3f} {:>12.3f} {:>10.4f} {:>12.3f} {:>12.3f} {:>15.3f}\n", items[i].name, parts[i].mass,
               local, d2, parts[i].mass * d2, local + parts[i].mass * d2, ratios[i]);
  }
  // The last column is each part's own moment against its parallel-axis term: the car's centre is
  // only centimetres from the whole's, so its own inertia is hundreds of times its transfer term;
  // the small parts far out are the other way round.
  const Vec3d carOffset = parts[0].position - body.centerOfMass;
  fmt::print("(I_local / m d^2: the car's centre is {:.0f} mm from the whole's, so its own inertia is {:.0f} times "
             "its transfer term; the driver's and the fuel's are {:.1f}% and {:.1f}% of theirs)\n",
             1000.0 * std::hypot(carOffset.x, carOffset.y), ratios[0], 100.0 * ratios[1], 100.0 * ratios[2]);
  fmt::print("\ntotal weight  {:.2f} N, mass {:.2f} kg\n", body.mass * g, body.mass);
  fmt::print("centre of mass ({:.4f}, {:.4f}) m\n", body.centerOfMass.x, body.centerOfMass.y);
  fmt::print("Izz about it   {:.2f} kg m^2\n", body.inertia(2, 2));
  fmt::print("(the book's 2.7% and 2.1% local-to-transfer ratios do not follow from its inputs either)\n");
  return 0;
}

} // namespace impetus::cli
