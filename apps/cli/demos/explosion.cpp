// The book's kinematic particle explosion (ch. 2), headless: how many particles live, how far
// the effect spreads, and the particles' positions and brightness frame by frame as CSV.
#include "demos/demos.hpp"

#include <impetus/mechanics/explosion.hpp>

#include <fmt/core.h>

namespace impetus::cli {

int demoExplosion(const DemoOptions& options) {
  ExplosionSettings settings;
  settings.origin = {0.0, 20.0};
  settings.speed = 15.0;
  settings.life = 2.0;
  settings.seed = 2024;
  const KinematicExplosion explosion(settings);
  fmt::print("{} particles at ({}, {}) m, speed up to {} m/s, life up to {} s, g = {} m/s^2\n",
             explosion.particles().size(), settings.origin.x, settings.origin.y, settings.speed, settings.life,
             settings.gravity);
  std::vector<std::vector<double>> rows;
  const double frame = 1.0 / 30.0;
  for (int f = 0; f * frame <= explosion.endTime(); ++f) {
    const double t = f * frame;
    double radius = 0.0;
    for (std::size_t i = 0; i < explosion.particles().size(); ++i) {
      const ParticleSnapshot p = explosion.particleAt(i, t);
      if (p.alive) {
        radius = std::max(radius, distance(p.position, settings.origin));
        rows.push_back({t, static_cast<double>(i), p.position.x, p.position.y, p.fade});
      }
    }
    if (f % 10 == 0) {
      fmt::print("t = {:4.2f} s: {:2} alive, spread {:5.2f} m\n", t, explosion.aliveCount(t), radius);
    }
  }
  fmt::print("the effect ends at t = {:.3f} s (the same at any frame rate: positions are closed-form in t)\n",
             explosion.endTime());
  writeCsv(options, "explosion.csv", "t,particle,x,y,fade", rows);
  return 0;
}

} // namespace impetus::cli
