// The book's cannon program (ch. 2) and Cannon2 (ch. 4), headless: fire at the target box and
// report where each shot ends, writing the trajectories as CSV.
#include "demos/demos.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/aiming.hpp>
#include <impetus/mechanics/cannon.hpp>

#include <fmt/core.h>

namespace impetus::cli {
namespace {

const char* outcomeName(ShotOutcome o) {
  return o == ShotOutcome::hit ? "HIT" : (o == ShotOutcome::ground ? "ground" : "timeout");
}

void appendRows(std::vector<std::vector<double>>& rows, double shot, const ShotResult& r) {
  for (const ShellState& s : r.trajectory) {
    rows.push_back({shot, s.time, s.position.x, s.position.y, s.position.z, s.velocity.x, s.velocity.y, s.velocity.z});
  }
}

constexpr const char* csvHeader = "shot,t,x,y,z,vx,vy,vz";

} // namespace

int demoCannon(const DemoOptions& options) {
  const TargetBox target{{400.0, 10.0, 60.0}, {20.0, 20.0, 20.0}};
  CannonSetup gun{70.0, degToRad(45.0), degToRad(8.5), 5.0, 2.0};
  fmt::print("target: centre ({}, {}, {}) m, {} x {} x {} m; muzzle speed {} m/s, barrel {} m, base {} m\n",
             target.center.x, target.center.y, target.center.z, target.size.x, target.size.y, target.size.z,
             gun.muzzleSpeed, gun.barrelLength, gun.baseHeight);
  std::vector<std::vector<double>> rows;
  int shot = 0;
  // A few hand-laid shots as a player would try them, then one aimed by the library.
  for (const double alpha : {60.0, 45.0, 52.0}) {
    gun.altitude = degToRad(alpha);
    const ShotResult r = fireAtTarget(ShellFlight(gun, 1.0, Atmosphere{}), target);
    fmt::print("alpha {:5.1f} deg, gamma {:4.1f} deg: {:<7} at t = {:6.3f} s, ({:7.2f}, {:6.2f}, {:6.2f}) m\n", alpha,
               radToDeg(gun.azimuth), outcomeName(r.outcome), r.time, r.position.x, r.position.y, r.position.z);
    appendRows(rows, ++shot, r);
  }
  // Aim from the pivot at the target's centre; the barrel's length shifts the muzzle a little.
  const Vec3d pivot{0.0, gun.baseHeight, 0.0};
  if (const std::optional<Aim3> aim = aimAt(pivot, target.center, gun.muzzleSpeed, 9.81)) {
    gun.altitude = std::acos(aim->lowDirection.y);
    gun.azimuth = std::atan2(aim->lowDirection.z, aim->lowDirection.x);
    const ShotResult r = fireAtTarget(ShellFlight(gun, 1.0, Atmosphere{}), target);
    fmt::print("aimed: alpha {:5.2f} deg, gamma {:4.2f} deg: {:<7} at t = {:6.3f} s, ({:7.2f}, {:6.2f}, {:6.2f}) m\n",
               radToDeg(gun.altitude), radToDeg(gun.azimuth), outcomeName(r.outcome), r.time, r.position.x,
               r.position.y, r.position.z);
    appendRows(rows, ++shot, r);
  }
  writeCsv(options, "cannon.csv", csvHeader, rows);
  return 0;
}

int demoCannon2(const DemoOptions& options) {
  const CannonSetup gun{70.0, degToRad(45.0), 0.0, 5.0, 2.0};
  const TargetBox target{{460.0, 10.0, 0.0}, {20.0, 20.0, 20.0}};
  const double mass = 10.0;
  struct Case {
    const char* name;
    Atmosphere air;
  };
  Atmosphere vacuum;
  Atmosphere drag;
  drag.dragCoefficient = 0.5;
  Atmosphere airWind = drag;
  airWind.windSpeed = 15.0;
  airWind.windDirection = degToRad(180.0); // from -x: a tail wind
  Atmosphere bookWind = airWind;
  bookWind.windModel = WindModel::bookConstantForce;
  bookWind.windCoefficient = 1.0;
  const Case cases[] = {{"vacuum", vacuum},
                        {"drag C = 0.5 kg/s", drag},
                        {"drag + 15 m/s tail wind (moving air)", airWind},
                        {"drag + book's wind force, Cw = 1.0", bookWind}};
  fmt::print("shell {} kg at {} m/s, alpha 45 deg; target at x = {} m\n", mass, gun.muzzleSpeed, target.center.x);
  std::vector<std::vector<double>> rows;
  int shot = 0;
  for (const Case& c : cases) {
    const ShellFlight flight(gun, mass, c.air);
    const ShotResult r = fireAtTarget(flight, target);
    fmt::print("{:<40} {:<7} t = {:6.3f} s, x = {:7.2f} m, impact speed {:6.2f} m/s\n", c.name, outcomeName(r.outcome),
               r.time, r.position.x, length(r.velocity));
    appendRows(rows, ++shot, r);
  }
  fmt::print("With linear drag, air moving at w adds the constant force C w: the book's wind force is the\n"
             "same physics only when Cw = C. With Cw = 2C the book's shell drifts at twice the wind speed\n"
             "(terminal horizontal velocity {:.1f} m/s in a {:.1f} m/s wind), which no air can do.\n",
             ShellFlight(gun, mass, bookWind).terminalVelocity().x, airWind.windSpeed);
  writeCsv(options, "cannon2.csv", csvHeader, rows);
  return 0;
}

} // namespace impetus::cli
