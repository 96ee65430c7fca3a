// Which shapes of a rigid2d::World touch, followed from its contact begin and end events (the
// world's inspection API has no list of contacts), and their manifolds recomputed with the
// engine's own narrowphase functions for drawing contact points and normals.
#pragma once

#include <impetus/rigid2d/world.hpp>

#include <array>
#include <cstdint>
#include <map>

namespace impetus::samples {

class ContactTracker {
public:
  struct Pair {
    rigid2d::ShapeId shapeA;
    rigid2d::ShapeId shapeB;
    rigid2d::BodyId bodyA; ///< kept to tell a destroyed shape from a live one
    rigid2d::BodyId bodyB;
  };

  void clear() { pairs_.clear(); }
  /// Takes in the last step's begin and end events: call after every World::step.
  void update(const rigid2d::World& world);
  /// The pairs touching now, in a fixed order; pairs whose bodies are gone are skipped.
  template <typename F> void forEach(const rigid2d::World& world, F&& f) const {
    for (const auto& [key, pair] : pairs_) {
      if (world.isValid(pair.bodyA) && world.isValid(pair.bodyB)) {
        f(pair);
      }
    }
  }
  [[nodiscard]] std::size_t size() const noexcept { return pairs_.size(); }

private:
  using Key = std::array<std::uint32_t, 4>;
  static Key key(rigid2d::ShapeId a, rigid2d::ShapeId b);
  std::map<Key, Pair> pairs_;
};

/// The manifold of two shapes at their bodies' current transforms (normal from A to B), by the
/// narrowphase function for their pair of shape types.
[[nodiscard]] rigid2d::Manifold currentManifold(const rigid2d::World& world, rigid2d::ShapeId a, rigid2d::ShapeId b);

} // namespace impetus::samples
