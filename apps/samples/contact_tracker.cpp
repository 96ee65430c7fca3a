#include "contact_tracker.hpp"

#include <impetus/rigid2d/manifold.hpp>

#include <utility>

namespace impetus::samples {
namespace {

using rigid2d::Manifold;

Manifold reversed(Manifold m) {
  m.normal = -m.normal;
  return m;
}

/// Any convex shape as the narrowphase sees it (chains are handled before).
rigid2d::Polygon convex(const rigid2d::ShapeGeometry& g) {
  if (const auto* c = std::get_if<rigid2d::Circle>(&g)) {
    return rigid2d::asPolygon(*c);
  }
  if (const auto* c = std::get_if<rigid2d::Capsule>(&g)) {
    return rigid2d::asPolygon(*c);
  }
  if (const auto* s = std::get_if<rigid2d::Segment>(&g)) {
    return rigid2d::asPolygon(*s);
  }
  return std::get<rigid2d::Polygon>(g);
}

Manifold collide(const rigid2d::ShapeGeometry& a, const Transform2f& xfA, const rigid2d::ShapeGeometry& b,
                 const Transform2f& xfB) {
  if (const auto* chain = std::get_if<rigid2d::ChainSegment>(&a)) {
    if (std::holds_alternative<rigid2d::ChainSegment>(b)) {
      return {};
    }
    if (const auto* circle = std::get_if<rigid2d::Circle>(&b)) {
      return rigid2d::collideChainSegmentAndCircle(*chain, xfA, *circle, xfB);
    }
    return rigid2d::collideChainSegmentAndPolygon(*chain, xfA, convex(b), xfB);
  }
  if (std::holds_alternative<rigid2d::ChainSegment>(b)) {
    return reversed(collide(b, xfB, a, xfA));
  }
  const auto* ca = std::get_if<rigid2d::Circle>(&a);
  const auto* cb = std::get_if<rigid2d::Circle>(&b);
  if (ca != nullptr && cb != nullptr) {
    return rigid2d::collideCircles(*ca, xfA, *cb, xfB);
  }
  if (cb != nullptr) {
    return rigid2d::collidePolygonAndCircle(convex(a), xfA, *cb, xfB);
  }
  if (ca != nullptr) {
    return reversed(rigid2d::collidePolygonAndCircle(convex(b), xfB, *ca, xfA));
  }
  return rigid2d::collidePolygons(convex(a), xfA, convex(b), xfB);
}

} // namespace

ContactTracker::Key ContactTracker::key(rigid2d::ShapeId a, rigid2d::ShapeId b) {
  return {a.index, a.generation, b.index, b.generation};
}

void ContactTracker::update(const rigid2d::World& world) {
  const rigid2d::ContactEvents& events = world.contactEvents();
  for (const rigid2d::ContactEndEvent& e : events.ends) {
    pairs_.erase(key(e.shapeA, e.shapeB));
  }
  for (const rigid2d::ContactBeginEvent& e : events.begins) {
    pairs_[key(e.shapeA, e.shapeB)] = {e.shapeA, e.shapeB, world.shapeBody(e.shapeA), world.shapeBody(e.shapeB)};
  }
}

Manifold currentManifold(const rigid2d::World& world, rigid2d::ShapeId a, rigid2d::ShapeId b) {
  const Transform2f xfA = world.transform(world.shapeBody(a));
  const Transform2f xfB = world.transform(world.shapeBody(b));
  return collide(world.shapeGeometry(a), xfA, world.shapeGeometry(b), xfB);
}

} // namespace impetus::samples
