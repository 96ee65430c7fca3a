#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/sensors/hourglass.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace impetus::sensors {
namespace {

/// splitmix64: a fixed, portable sequence (std's distributions differ between libraries).
class Random {
public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  /// Uniform in [0, 1).
  double next() {
    state_ += 0x9E3779B97F4A7C15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
    z ^= z >> 31U;
    return static_cast<double>(z >> 11U) * 0x1.0p-53;
  }

private:
  std::uint64_t state_;
};

void validate(const HourglassSettings& s) {
  requirePositive(s.bulbWidth, "bulbWidth");
  requirePositive(s.bulbHeight, "bulbHeight");
  requirePositive(s.neckWidth, "neckWidth");
  requirePositive(s.grainDiameter, "grainDiameter");
  requirePositive(s.grainDensity, "grainDensity");
  requireNonNegative(s.gravity, "gravity");
  requireNonNegative(s.wallFriction, "wallFriction");
  requireNonNegative(s.damping, "damping");
  // Funnel walls flatter than 45 degrees would hold sand on them (mu up to 1).
  if (!(std::isfinite(s.funnelAngle) && s.funnelAngle >= 0.25 * pi<double> && s.funnelAngle < 0.5 * pi<double>)) {
    throwInvalid("funnelAngle", s.funnelAngle, "must be in [pi/4, pi/2) rad");
  }
  if (!(std::isfinite(s.sizeSpread) && s.sizeSpread >= 0.0 && s.sizeSpread < 0.5)) {
    throwInvalid("sizeSpread", s.sizeSpread, "must be in [0, 0.5)");
  }
  if (!(std::isfinite(s.wallRestitution) && s.wallRestitution >= 0.0 && s.wallRestitution <= 1.0)) {
    throwInvalid("wallRestitution", s.wallRestitution, "must be in [0, 1]");
  }
  requireNonNegative(s.settleTime, "settleTime");
  if (s.substeps < 1) {
    throwInvalid("substeps", s.substeps, "must be at least 1");
  }
  if (s.grainCount < 1) {
    throwInvalid("grainCount", s.grainCount, "must be at least 1");
  }
  const double largest = s.grainDiameter * (1.0 + s.sizeSpread);
  if (s.neckWidth <= largest) {
    throwInvalid("neckWidth", s.neckWidth,
                 "must exceed the largest grain's diameter, " + formatValue(largest) + " m (no grain could pass)");
  }
  if (s.neckWidth >= s.bulbWidth) {
    throwInvalid("neckWidth", s.neckWidth, "must be narrower than bulbWidth, " + formatValue(s.bulbWidth) + " m");
  }
  const double funnel = 0.5 * (s.bulbWidth - s.neckWidth) * std::tan(s.funnelAngle);
  if (s.bulbHeight <= funnel) {
    throwInvalid("bulbHeight", s.bulbHeight, "must exceed the funnel's height, " + formatValue(funnel) + " m");
  }
}

/// The sites a bulb offers to grains of diameter up to `largest`: rows from the neck outward
/// (y > 0: the top bulb), each row centred and every other one shifted by half a spacing (a
/// triangular lattice), 5 % apart so that no two grains start in contact.
std::vector<Vec2d> fillSites(const HourglassSettings& s, double largest, std::size_t wanted) {
  const double spacing = 1.05 * largest;
  const double rowPitch = spacing * 0.8660254037844386; // sqrt(3)/2
  const double r = 0.5 * spacing;
  const double slope = 1.0 / std::tan(s.funnelAngle); // half-width gained per metre up the funnel
  std::vector<Vec2d> sites;
  int row = 0;
  for (double y = r; y + r <= s.bulbHeight && sites.size() < wanted; y += rowPitch, ++row) {
    // The narrowest half-width over the row's height is at its bottom, y - r.
    const double halfWidth = std::min(0.5 * s.bulbWidth, 0.5 * s.neckWidth + std::max(0.0, y - r) * slope);
    // A grain's centre stays a radius inside the wall; on the slanted funnel wall that is
    // r / sin(angle) across.
    const double room = halfWidth - r / std::sin(s.funnelAngle);
    // Sites at x = shift + i spacing within the room: a triangular lattice about x = 0.
    const double shift = (row % 2 == 1) ? 0.5 * spacing : 0.0;
    const auto first = static_cast<int>(std::ceil((-room - shift) / spacing));
    const auto last = static_cast<int>(std::floor((room - shift) / spacing));
    for (int i = first; i <= last && sites.size() < wanted; ++i) {
      sites.emplace_back(shift + spacing * i, y);
    }
  }
  return sites;
}

} // namespace

Vec2d deviceGravity(const Vec3d& readingG, AccelConvention convention, double gravity) {
  requireFinite(readingG, "reading");
  // The gravity-direction reading points where things fall.
  const Vec3d down = convention == AccelConvention::gravityDirection ? readingG : -readingG;
  return Vec2d{down.x, down.y} * gravity;
}

double beverlooRate2d(double neckWidth, double grainDiameter, double gravity, double coefficient, double edgeFactor,
                      double packing) {
  requirePositive(neckWidth, "neckWidth");
  requirePositive(grainDiameter, "grainDiameter");
  requirePositive(gravity, "gravity");
  requirePositive(coefficient, "coefficient");
  requireNonNegative(edgeFactor, "edgeFactor");
  requirePositive(packing, "packing");
  const double open = neckWidth - edgeFactor * grainDiameter;
  if (open <= 0.0) {
    return 0.0;
  }
  const double grainArea = 0.25 * pi<double> * grainDiameter * grainDiameter;
  return coefficient * (packing / grainArea) * std::sqrt(gravity) * std::pow(open, 1.5);
}

Hourglass::Hourglass(const HourglassSettings& s, Bulb filled) : settings_(s) {
  validate(s);
  const double largest = s.grainDiameter * (1.0 + s.sizeSpread);
  std::vector<Vec2d> sites = fillSites(s, largest, static_cast<std::size_t>(s.grainCount));
  if (sites.size() < static_cast<std::size_t>(s.grainCount)) {
    // Count the whole bulb's room for the message.
    const std::size_t room = fillSites(s, largest, static_cast<std::size_t>(-1)).size();
    throwInvalid("grainCount", s.grainCount, "must fit in one bulb: it holds " + std::to_string(room));
  }

  ParticleWorldSettings ws;
  ws.gravity = {0.0f, 0.0f, 0.0f};
  ws.substeps = s.substeps;
  ws.particleCollisions = true;
  ws.particleRestitution = 0.0f; // sand does not bounce off sand
  const double mass = s.grainDensity * pi<double> * s.grainDiameter * s.grainDiameter * s.grainDiameter / 6.0;
  ws.linearDrag = static_cast<float>(s.damping * mass); // F = -k v with k = m c: a = -c v
  world_ = ParticleWorld(ws);

  // The outline, counter-clockwise; each edge's outward normal is (dy, -dx) / length.
  const double w = 0.5 * s.bulbWidth;
  const double h = s.bulbHeight;
  const double n = 0.5 * s.neckWidth;
  const double f = funnelHeight();
  outline_ = {{w, -h}, {w, -f}, {n, 0.0}, {w, f}, {w, h}, {-w, h}, {-w, f}, {-n, 0.0}, {-w, -f}, {-w, -h}};
  // The walls: boxes of thickness t whose inner face is each edge, a few grains thick (far more
  // than a grain moves into a wall in a substep). Each box runs on by t past its ends, closing
  // the bulbs' convex corners from outside, except at the neck: there the glass is a wedge
  // between the funnels, and a box run on past the neck would stick into the other bulb. The
  // funnel boxes stay in that wedge because funnelAngle >= 45 degrees.
  const double t = 3.0 * largest;
  const SurfaceMaterial glass{static_cast<float>(s.wallRestitution), static_cast<float>(s.wallFriction)};
  for (std::size_t i = 0; i < outline_.size(); ++i) {
    const Vec2d a = outline_[i];
    const Vec2d b = outline_[(i + 1) % outline_.size()];
    const double edge = length(b - a);
    const Vec2d along = (b - a) / edge;
    const Vec2d normal{along.y, -along.x}; // outward
    const double runA = std::abs(a.y) == 0.0 ? 0.0 : t;
    const double runB = std::abs(b.y) == 0.0 ? 0.0 : t;
    const Vec2d centre = a + along * (0.5 * (edge + runB - runA)) + normal * (0.5 * t);
    BoxObstacle box;
    box.center = {static_cast<float>(centre.x), static_cast<float>(centre.y), 0.0f};
    box.halfExtents = {static_cast<float>(0.5 * (edge + runA + runB)), static_cast<float>(0.5 * t),
                       static_cast<float>(t)};
    box.rotation = Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, static_cast<float>(std::atan2(along.y, along.x)));
    world_.addObstacle(box, glass);
  }

  // The sand: diameters even in d (1 -+ spread), one draw per grain in order.
  Random random(s.seed);
  const double side = filled == Bulb::top ? 1.0 : -1.0;
  radii_.reserve(sites.size());
  for (const Vec2d& site : sites) {
    const double diameter = s.grainDiameter * (1.0 + s.sizeSpread * (2.0 * random.next() - 1.0));
    ParticleDef def;
    def.position = {static_cast<float>(site.x), static_cast<float>(side * site.y), 0.0f};
    def.radius = static_cast<float>(0.5 * diameter);
    def.mass = static_cast<float>(mass);
    world_.createParticle(def);
    radii_.push_back(def.radius);
  }

  // Settling: a stopper across the neck (a capsule whose surface is the neck's line) and
  // gravity towards it until the sand lies packed in the funnel at rest; then the glass opens.
  if (s.settleTime > 0.0 && s.gravity > 0.0) {
    const auto stopperAxis = static_cast<float>(-side * t);
    const ObstacleId stopper = world_.addObstacle(CapsuleObstacle{{static_cast<float>(-n), stopperAxis, 0.0f},
                                                                  {static_cast<float>(n), stopperAxis, 0.0f},
                                                                  static_cast<float>(t)},
                                                  glass);
    ParticleWorldSettings settle = world_.settings();
    settle.gravity = {0.0f, static_cast<float>(-side * s.gravity), 0.0f};
    settle.substeps = std::max(s.substeps, 16); // h <= 1/960 s whatever the caller steps with
    world_.setSettings(settle);
    const double frame = 1.0 / 60.0;
    const auto frames = static_cast<int>(std::ceil(s.settleTime / frame));
    for (int i = 0; i < frames; ++i) {
      world_.step(static_cast<float>(frame));
    }
    world_.removeObstacle(stopper);
    settle.gravity = {};
    settle.substeps = s.substeps;
    world_.setSettings(settle);
    for (const ParticleId id : std::vector<ParticleId>(world_.ids().begin(), world_.ids().end())) {
      world_.setVelocity(id, {});
    }
  }
}

double Hourglass::funnelHeight() const noexcept {
  return 0.5 * (settings_.bulbWidth - settings_.neckWidth) * std::tan(settings_.funnelAngle);
}

void Hourglass::step(const Vec3d& readingG, double dt) {
  stepWithGravity(deviceGravity(readingG, settings_.convention, settings_.gravity), dt);
}

void Hourglass::stepAtTilt(double tilt, double dt) {
  requireFinite(tilt, "tilt");
  stepWithGravity(Vec2d{std::sin(tilt), -std::cos(tilt)} * settings_.gravity, dt);
}

void Hourglass::stepWithGravity(const Vec2d& gravity, double dt) {
  requireFinite(gravity, "gravity");
  if (!(std::isfinite(dt) && dt > 0.0 && dt <= 1.0)) {
    throwInvalid("dt", dt, "must be in (0, 1] s");
  }
  if (gravity.x != gravity_.x || gravity.y != gravity_.y) {
    ParticleWorldSettings ws = world_.settings();
    ws.gravity = {static_cast<float>(gravity.x), static_cast<float>(gravity.y), 0.0f};
    world_.setSettings(ws);
    gravity_ = gravity;
  }
  world_.step(static_cast<float>(dt));
  time_ += dt;
}

int Hourglass::grainsIn(Bulb bulb) const noexcept {
  int top = 0;
  for (const Vec3f& p : world_.positions()) {
    top += p.y > 0.0f ? 1 : 0;
  }
  return bulb == Bulb::top ? top : grainCount() - top;
}

} // namespace impetus::sensors
