// The 3D world's collision stage: the pairs of shapes whose boxes overlap (the broadphase), kept
// as contacts in the order of their keys with the impulses their points carry, and each pair's
// manifold (the narrowphase's table by shape kind).
#include "rigid3d/world_impl.hpp"

#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/manifold.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <variant>

namespace impetus::rigid3d::detail {

namespace {

/// A shape's box in the world, grown by the speculative distance (a pair closer than that has
/// speculative points) and a margin of its own.
struct ShapeBox {
  Vec3f lower, upper;
  std::uint32_t shape = 0; ///< slot
};

/// How much a shape's box is grown beyond its speculative reach, m: two boxes that only the
/// margin makes overlap give a contact with no points, which costs a manifold's test; without
/// it a pair would begin and end each step as its gap crossed the speculative distance.
constexpr float boxMargin = linearSlop;

ShapeBox shapeBox(const Shape& shape, const Transform3f& xf, std::uint32_t slot) {
  Vec3f lower{3.4e38f, 3.4e38f, 3.4e38f};
  Vec3f upper = -lower;
  float radius = 0.0f;
  const auto add = [&](const Vec3f& local) {
    const Vec3f p = transformPoint(xf, local);
    lower = min(lower, p);
    upper = max(upper, p);
  };
  std::visit(
      [&](const auto& g) {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, Sphere>) {
          add(g.center);
          radius = g.radius;
        } else if constexpr (std::is_same_v<G, Capsule>) {
          add(g.center1);
          add(g.center2);
          radius = g.radius;
        } else {
          for (const Vec3f& p : g.points) {
            add(p);
          }
        }
      },
      shape.geometry);
  const float grow = radius + speculativeDistance + boxMargin;
  const Vec3f g{grow, grow, grow};
  return {lower - g, upper + g, slot};
}

bool overlaps(const ShapeBox& a, const ShapeBox& b) {
  return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y &&
         a.lower.z <= b.upper.z && b.lower.z <= a.upper.z;
}

/// How far a shape's surface lies out from its core, m: a sphere's or capsule's radius (a hull
/// is its own core). It is also the radius the shape rolls on.
float roundingRadius(const Shape& s) {
  if (const auto* sphere = std::get_if<Sphere>(&s.geometry)) {
    return sphere->radius;
  }
  if (const auto* capsule = std::get_if<Capsule>(&s.geometry)) {
    return capsule->radius;
  }
  return 0.0f;
}

/// Whether a manifold's shapes overlap (a point below zero separation), not merely come near.
bool overlapping(const Manifold& m) {
  for (int k = 0; k < m.pointCount; ++k) {
    if (m.points[static_cast<std::size_t>(k)].separation < 0.0f) {
      return true;
    }
  }
  return false;
}

/// A sensor pair's event: the sensor shape and the shape it sees.
SensorEvent sensorEvent(const WorldState& w, const Contact& c) {
  const ShapeId a = w.shapeIdOf(c.keyA);
  const ShapeId b = w.shapeIdOf(c.keyB);
  return c.sensorIsA ? SensorEvent{a, b} : SensorEvent{b, a};
}

/// Whether a body is in this step's motion: awake and not static.
bool awakeAndMoving(const Body& b) { return b.awake && b.type != BodyType::staticBody; }

/// A sleeping body touched by one that moves (a dynamic body awake, a kinematic one in motion)
/// wakes, with its island.
void wakeTouched(WorldState& w, const Contact& c) {
  const Body& a = w.bodies[c.bodyA];
  const Body& b = w.bodies[c.bodyB];
  const auto disturbs = [](const Body& x) {
    return awakeAndMoving(x) && (x.type == BodyType::dynamicBody || lengthSquared(x.linearVelocity) > 0.0f ||
                                 lengthSquared(x.angularVelocity) > 0.0f);
  };
  if (!b.awake && disturbs(a)) {
    wakeBody(w, c.bodyB);
  } else if (!a.awake && disturbs(b)) {
    wakeBody(w, c.bodyA);
  }
}

/// Whether two shapes' bodies can touch: different bodies, at least one of them dynamic.
bool mayCollide(const Body& a, const Body& b) {
  return &a != &b && (a.type == BodyType::dynamicBody || b.type == BodyType::dynamicBody);
}

/// The narrowphase's order of shape kinds: a pair's A is the shape whose kind comes later
/// (hull, capsule, sphere), so one function serves each pair of kinds.
bool comesFirst(const Shape& a, const Shape& b) {
  return a.geometry.index() != b.geometry.index() ? a.geometry.index() > b.geometry.index() : a.id.index < b.id.index;
}

Manifold collide(const Shape& a, const Transform3f& xfA, const Shape& b, const Transform3f& xfB) {
  return std::visit(
      [&](const auto& ga, const auto& gb) -> Manifold {
        using A = std::decay_t<decltype(ga)>;
        using B = std::decay_t<decltype(gb)>;
        if constexpr (std::is_same_v<A, Hull> && std::is_same_v<B, Hull>) {
          return collideHulls(ga, xfA, gb, xfB);
        } else if constexpr (std::is_same_v<A, Hull> && std::is_same_v<B, Capsule>) {
          return collideHullAndCapsule(ga, xfA, gb, xfB);
        } else if constexpr (std::is_same_v<A, Hull> && std::is_same_v<B, Sphere>) {
          return collideHullAndSphere(ga, xfA, gb, xfB);
        } else if constexpr (std::is_same_v<A, Capsule> && std::is_same_v<B, Capsule>) {
          return collideCapsules(ga, xfA, gb, xfB);
        } else if constexpr (std::is_same_v<A, Capsule> && std::is_same_v<B, Sphere>) {
          return collideCapsuleAndSphere(ga, xfA, gb, xfB);
        } else if constexpr (std::is_same_v<A, Sphere> && std::is_same_v<B, Sphere>) {
          return collideSpheres(ga, xfA, gb, xfB);
        } else {
          return Manifold{}; // never: A's kind comes after B's (comesFirst)
        }
      },
      a.geometry, b.geometry);
}

/// The tangents of a manifold: the last step's first tangent made perpendicular to the new
/// normal where it still can be (so the friction impulses carried along them keep their
/// meaning), else one perpendicular to the normal, from the axis it leans on least.
void updateTangents(Contact& c, bool carried) {
  const Vec3f n = c.manifold.normal;
  Vec3f t = carried ? c.tangent1 - n * dot(n, c.tangent1) : Vec3f{};
  // Under this length the old tangent is (nearly) along the new normal: it says nothing.
  constexpr float minCarriedTangentLength = 0.5f;
  if (const float len = length(t); len > minCarriedTangentLength) {
    t = t * (1.0f / len);
  } else {
    const Vec3f a = std::abs(n.x) < 0.57735f ? Vec3f{1.0f, 0.0f, 0.0f} : Vec3f{0.0f, 1.0f, 0.0f};
    t = normalize(cross(a, n));
  }
  c.tangent1 = t;
  c.tangent2 = cross(n, t);
}

/// How far a new manifold point may be from an old one of other features and still take its
/// impulse, m. Flush faces (a box on a box of its width, a pyramid's boxes) put corners exactly on
/// the reference face's side planes, where the jitter of a resting stack moves each across and
/// back: the same corner is by turns a vertex inside the face, a cut of an edge by the side plane
/// or the face's own corner, three ids for one point. Matched by id alone, a tenth of a resting
/// pyramid's points restarted from zero impulse each step and the pyramid sank under it.
constexpr float maxCarryDistance = 2.0f * linearSlop;

/// The new manifold's points take the impulses of the old points: of the same feature ids, or
/// else of the nearest old point not taken, within maxCarryDistance (by their anchors on A, so
/// that the pair moving together does not count).
void carryImpulses(Contact& c, const Manifold& old, const std::array<PointImpulse, 4>& oldImpulses) {
  std::array<bool, 4> taken{};
  std::array<int, 4> source{-1, -1, -1, -1};
  const auto& next = c.manifold.points;
  for (int k = 0; k < c.manifold.pointCount; ++k) {
    for (int j = 0; j < old.pointCount; ++j) {
      if (!taken[static_cast<std::size_t>(j)] &&
          old.points[static_cast<std::size_t>(j)].id == next[static_cast<std::size_t>(k)].id) {
        taken[static_cast<std::size_t>(j)] = true;
        source[static_cast<std::size_t>(k)] = j;
        break;
      }
    }
  }
  for (int k = 0; k < c.manifold.pointCount; ++k) {
    float nearest = maxCarryDistance * maxCarryDistance;
    for (int j = 0; j < old.pointCount && source[static_cast<std::size_t>(k)] < 0; ++j) {
      const float d2 =
          lengthSquared(old.points[static_cast<std::size_t>(j)].anchorA - next[static_cast<std::size_t>(k)].anchorA);
      if (!taken[static_cast<std::size_t>(j)] && d2 <= nearest) {
        nearest = d2;
        source[static_cast<std::size_t>(k)] = j;
      }
    }
    if (source[static_cast<std::size_t>(k)] >= 0) {
      taken[static_cast<std::size_t>(source[static_cast<std::size_t>(k)])] = true;
    }
  }
  for (int k = 0; k < c.manifold.pointCount; ++k) {
    const int j = source[static_cast<std::size_t>(k)];
    c.impulses[static_cast<std::size_t>(k)] = j >= 0 ? oldImpulses[static_cast<std::size_t>(j)] : PointImpulse{};
  }
}

/// The pairs of shapes whose boxes overlap, by sweeping the boxes in the order of their lower x:
/// sorted by key (A's, then B's), as the contacts are kept.
void findPairs(const WorldState& w, std::vector<ShapeBox>& boxes, std::vector<Contact>& pairs) {
  boxes.clear();
  for (std::uint32_t slot = 0; slot < w.shapes.size(); ++slot) {
    const Shape& s = w.shapes[slot];
    if (s.alive) {
      boxes.push_back(shapeBox(s, w.bodies[s.body].transform, slot));
    }
  }
  std::sort(boxes.begin(), boxes.end(), [](const ShapeBox& a, const ShapeBox& b) {
    return a.lower.x != b.lower.x ? a.lower.x < b.lower.x : a.shape < b.shape;
  });
  pairs.clear();
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size() && boxes[j].lower.x <= boxes[i].upper.x; ++j) {
      if (!overlaps(boxes[i], boxes[j])) {
        continue;
      }
      const Shape* a = &w.shapes[boxes[i].shape];
      const Shape* b = &w.shapes[boxes[j].shape];
      if (!shouldCollide(a->filter, b->filter) || !mayCollide(w.bodies[a->body], w.bodies[b->body])) {
        continue;
      }
      if (!comesFirst(*a, *b)) {
        std::swap(a, b);
      }
      if (a->sensor && b->sensor) {
        continue; // sensors see bodies, not each other
      }
      Contact c;
      c.sensor = a->sensor || b->sensor;
      c.sensorIsA = a->sensor;
      c.shapeA = a->id.index;
      c.shapeB = b->id.index;
      c.keyA = shapeKey(a->id.index, a->id.generation);
      c.keyB = shapeKey(b->id.index, b->id.generation);
      c.bodyA = a->body;
      c.bodyB = b->body;
      pairs.push_back(c);
    }
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const Contact& a, const Contact& b) { return a.keyA != b.keyA ? a.keyA < b.keyA : a.keyB < b.keyB; });
}

} // namespace

void updateContacts(WorldState& w) {
  std::vector<ShapeBox> boxes;
  findPairs(w, boxes, w.nextContacts);
  ContactEvents& events = w.contactEvents;
  events.begins.clear();
  events.ends.clear();
  events.hits.clear();
  w.sensorEvents.begins.clear();
  w.sensorEvents.ends.clear();
  // A pair that began or ended touching (a sensor's: overlapping) this step.
  const auto began = [&](const Contact& c) {
    if (c.sensor) {
      w.sensorEvents.begins.push_back(sensorEvent(w, c));
    } else {
      events.begins.push_back({w.shapeIdOf(c.keyA), w.shapeIdOf(c.keyB)});
      linkContact(w, c, true);
    }
  };
  const auto ended = [&](const Contact& c) {
    if (c.sensor) {
      w.sensorEvents.ends.push_back(sensorEvent(w, c));
    } else {
      events.ends.push_back({w.shapeIdOf(c.keyA), w.shapeIdOf(c.keyB)});
      linkContact(w, c, false);
    }
  };
  // The old contacts and the new pairs are both in key order: one merge finds the pairs that
  // carry on, and the old ones that went (their boxes apart, or a shape destroyed).
  std::size_t old = 0;
  const auto before = [](const Contact& a, const Contact& b) {
    return a.keyA != b.keyA ? a.keyA < b.keyA : a.keyB < b.keyB;
  };
  for (Contact& c : w.nextContacts) {
    while (old < w.contacts.size() && before(w.contacts[old], c)) {
      if (w.contacts[old].touching) {
        ended(w.contacts[old]);
      }
      ++old;
    }
    const bool carried = old < w.contacts.size() && !before(c, w.contacts[old]);
    if (carried && !awakeAndMoving(w.bodies[c.bodyA]) && !awakeAndMoving(w.bodies[c.bodyB])) {
      // Asleep (or asleep on a static body): nothing moved, the contact is as it was.
      c = w.contacts[old++];
      continue;
    }
    const Shape& a = w.shapes[c.shapeA];
    const Shape& b = w.shapes[c.shapeB];
    c.friction = std::sqrt(a.friction * b.friction);
    c.restitution = std::max(a.restitution, b.restitution);
    c.rollingResistance =
        std::max(a.rollingResistance, b.rollingResistance) * std::max(roundingRadius(a), roundingRadius(b));
    c.roundingA = roundingRadius(a);
    c.roundingB = roundingRadius(b);
    c.manifold = collide(a, w.bodies[c.bodyA].transform, b, w.bodies[c.bodyB].transform);
    // A sensor's pair is touching while the shapes overlap; any other while it has points.
    c.touching = c.sensor ? overlapping(c.manifold) : c.manifold.pointCount > 0;
    const bool wasTouching = carried && w.contacts[old].touching;
    if (carried) {
      const Contact& previous = w.contacts[old++];
      c.tangent1 = previous.tangent1;
      c.rollingImpulse = previous.rollingImpulse;
      carryImpulses(c, previous.manifold, previous.impulses);
    }
    if (c.touching && !c.sensor) {
      updateTangents(c, wasTouching);
      wakeTouched(w, c);
    }
    if (c.touching && !wasTouching) {
      began(c);
    } else if (!c.touching && wasTouching) {
      ended(c);
    }
  }
  for (; old < w.contacts.size(); ++old) {
    if (w.contacts[old].touching) {
      ended(w.contacts[old]);
    }
  }
  std::swap(w.contacts, w.nextContacts);
}

} // namespace impetus::rigid3d::detail
