// The 2D world: its settings, the broadphase, the narrowphase (contacts and their events) and
// the step's order. Bodies and shapes are created, read and pushed in world_bodies.cpp.
#include "rigid2d/world_impl.hpp"
#include "solver/stage_clock.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace impetus::rigid2d {

namespace detail {

ShapeProxy shapeProxy(const Shape& s) {
  return std::visit(
      [](const auto& g) {
        if constexpr (std::is_same_v<std::decay_t<decltype(g)>, ChainSegment>) {
          return makeProxy(g.segment);
        } else {
          return makeProxy(g);
        }
      },
      s.geometry);
}

AABB shapeBox(const Shape& s, const Transform2f& xf) {
  return std::visit([&](const auto& g) { return computeAABB(g, xf); }, s.geometry);
}

namespace {

/// The farthest a shape's outline reaches from its centre, m.
float extent(const Circle& c) { return c.radius; }
float extent(const Capsule& c) { return 0.5f * length(c.center2 - c.center1) + c.radius; }
float extent(const Polygon& p) {
  float farthest = 0.0f;
  for (int i = 0; i < p.count; ++i) {
    farthest = std::max(farthest, lengthSquared(p.vertices[static_cast<std::size_t>(i)] - p.centroid));
  }
  return std::sqrt(farthest) + p.radius;
}
float extent(const Segment& s) { return 0.5f * length(s.point2 - s.point1); }
float extent(const ChainSegment& c) { return extent(c.segment); }

} // namespace

float fatBoxMargin(const Geometry& g) {
  return std::min(aabbMargin, aabbMarginFraction * std::visit([](const auto& shape) { return extent(shape); }, g));
}

} // namespace detail

namespace {

using detail::Body;
using detail::Contact;
using detail::pairKey;
using detail::Shape;
using detail::shouldCollide;
using detail::WorldState;

/// A manifold computed with the shapes the other way round, turned back to A -> B.
Manifold reversed(Manifold m) {
  m.normal = -m.normal;
  for (int i = 0; i < m.pointCount; ++i) {
    std::swap(m.points[static_cast<std::size_t>(i)].anchorA, m.points[static_cast<std::size_t>(i)].anchorB);
  }
  return m;
}

/// A chain segment against any other shape (chain against a line: nothing).
Manifold collideChain(const ChainSegment& chain, const Transform2f& xfChain, const Shape& other,
                      const Transform2f& xfOther) {
  if (const auto* circle = std::get_if<Circle>(&other.geometry)) {
    return collideChainSegmentAndCircle(chain, xfChain, *circle, xfOther);
  }
  if (detail::isLine(other.geometry)) {
    return {};
  }
  return collideChainSegmentAndPolygon(chain, xfChain, other.collisionPolygon, xfOther);
}

Manifold collide(const Shape& a, const Transform2f& xfA, const Shape& b, const Transform2f& xfB) {
  if (const auto* chain = std::get_if<ChainSegment>(&a.geometry)) {
    return collideChain(*chain, xfA, b, xfB);
  }
  if (const auto* chain = std::get_if<ChainSegment>(&b.geometry)) {
    return reversed(collideChain(*chain, xfB, a, xfA));
  }
  const Circle* ca = std::get_if<Circle>(&a.geometry);
  const Circle* cb = std::get_if<Circle>(&b.geometry);
  if (ca != nullptr && cb != nullptr) {
    return collideCircles(*ca, xfA, *cb, xfB);
  }
  if (cb != nullptr) {
    return collidePolygonAndCircle(a.collisionPolygon, xfA, *cb, xfB);
  }
  if (ca != nullptr) {
    // Circle first: collide the other way round and turn the result around.
    return reversed(collidePolygonAndCircle(b.collisionPolygon, xfB, *ca, xfA));
  }
  return collidePolygons(a.collisionPolygon, xfA, b.collisionPolygon, xfB);
}

/// Reports a contact that stops touching (or is destroyed while touching) to `events`.
void reportEnd(const WorldState& w, const Contact& c, ContactEvents& events, SensorEvents& sensors) {
  if (c.manifold.pointCount == 0) {
    return;
  }
  const Shape& a = w.shapes[c.shapeA];
  const Shape& b = w.shapes[c.shapeB];
  if (c.sensor) {
    sensors.ends.push_back(a.sensor ? SensorEvent{a.id, b.id} : SensorEvent{b.id, a.id});
  } else {
    events.ends.push_back({a.id, b.id});
  }
}

/// The radius a shape rolls on (circles and capsules roll; polygons do not), m.
float rollingRadius(const Shape& s) {
  if (const auto* circle = std::get_if<Circle>(&s.geometry)) {
    return circle->radius;
  }
  if (const auto* capsule = std::get_if<Capsule>(&s.geometry)) {
    return capsule->radius;
  }
  return 0.0f;
}

/// How far a shape's surface lies out from its core, m: a circle's radius, a capsule's, a rounded
/// polygon's (0 for sharp polygons and segments). Manifold reuse carries the cores.
float roundingRadius(const Shape& s) {
  if (const auto* circle = std::get_if<Circle>(&s.geometry)) {
    return circle->radius;
  }
  return s.collisionPolygon.radius;
}

/// How far a shape reaches from its body's origin, m: the farthest of its surface's points.
float reachFromOrigin(const Shape& s) {
  if (const auto* circle = std::get_if<Circle>(&s.geometry)) {
    return length(circle->center) + circle->radius;
  }
  const Polygon& p = s.collisionPolygon;
  float reach = 0.0f;
  for (int i = 0; i < p.count; ++i) {
    reach = std::max(reach, length(p.vertices[static_cast<std::size_t>(i)]));
  }
  return reach + p.radius;
}

void createContact(WorldState& w, std::uint64_t key) {
  std::uint32_t slot = 0;
  if (!w.freeContacts.empty()) {
    slot = w.freeContacts.back();
    w.freeContacts.pop_back();
  } else {
    slot = static_cast<std::uint32_t>(w.contacts.size());
    w.contacts.emplace_back();
  }
  Contact& c = w.contacts[slot];
  c = Contact{};
  c.shapeA = static_cast<std::uint32_t>(key >> 32);
  c.shapeB = static_cast<std::uint32_t>(key & 0xffffffffU);
  const Shape& a = w.shapes[c.shapeA];
  const Shape& b = w.shapes[c.shapeB];
  c.bodyA = a.body;
  c.bodyB = b.body;
  c.friction = std::sqrt(a.friction * b.friction);
  c.restitution = std::max(a.restitution, b.restitution);
  // Torque per unit normal force: the pair's coefficient times the radius that rolls.
  c.rollingResistance =
      std::max(a.rollingResistance, b.rollingResistance) * std::max(rollingRadius(a), rollingRadius(b));
  c.tangentSpeed = a.tangentSpeed + b.tangentSpeed;
  c.sensor = a.sensor || b.sensor;
  c.preSolve = !c.sensor && (a.preSolve || b.preSolve);
  // A carried manifold skips the collide pass, where the pre-solve callback is asked.
  c.reusable = !c.preSolve;
  c.frame.radiusA = roundingRadius(a);
  c.frame.radiusB = roundingRadius(b);
  c.frame.reachB = reachFromOrigin(b);
  c.alive = true;
  w.contactByPair.insert(key, slot);
  // At the head of both bodies' lists.
  for (std::uint32_t edge = 0; edge < 2; ++edge) {
    Body& body = w.bodies[edge == 0 ? c.bodyA : c.bodyB];
    c.prev[edge] = detail::noContactEdge;
    c.next[edge] = body.contactHead;
    if (body.contactHead != detail::noContactEdge) {
      w.contacts[body.contactHead >> 1].prev[body.contactHead & 1U] = detail::contactEdgeKey(slot, edge);
    }
    body.contactHead = detail::contactEdgeKey(slot, edge);
  }
  if (w.bodies[c.bodyA].moving() || w.bodies[c.bodyB].moving()) {
    w.awakeContactSet.add(slot);
  }
}

/// Whether the game's custom filter lets a new pair (key: lower shape slot, higher) collide:
/// asked only when either shape enables it.
bool passesCustomFilter(const WorldState& w, std::uint64_t key) {
  const Shape& a = w.shapes[static_cast<std::uint32_t>(key >> 32)];
  const Shape& b = w.shapes[static_cast<std::uint32_t>(key & 0xffffffffU)];
  return !(a.customFiltering || b.customFiltering) || !w.customFilter || w.customFilter(a.id, b.id);
}

/// Finds new pairs for the shapes whose fat boxes changed and makes their contacts (contacts
/// whose fat boxes no longer overlap end in collideContacts). The queries run on threads, a block of the move buffer
/// each, and every test that needs no shape data comes first: a pair of two moved shapes is left to the query of the
/// lower slot, and a pair that has its contact already is done.
void updatePairs(WorldState& w) {
  w.movingTree.rebuild();
  if (w.movedShapes.size() < w.shapes.size()) {
    w.movedShapes.resize(w.shapes.size(), 0);
  }
  for (const std::uint32_t slot : w.moveBuffer) {
    w.movedShapes[slot] = 1;
  }
  const auto moved = static_cast<std::uint32_t>(w.moveBuffer.size());
  const std::uint32_t blockSize =
      std::max(detail::minPairQueryBlock, (moved + detail::pairQueryBlocks - 1) / detail::pairQueryBlocks);
  const std::uint32_t blocks = (moved + blockSize - 1) / blockSize;
  w.parallelFor(blocks, 1, [&](std::uint32_t firstBlock, std::uint32_t endBlock) {
    for (std::uint32_t block = firstBlock; block < endBlock; ++block) {
      std::vector<std::uint64_t>& found = w.pairBlocks[block];
      found.clear();
      const std::uint32_t end = std::min(moved, (block + 1) * blockSize);
      for (std::uint32_t k = block * blockSize; k < end; ++k) {
        const std::uint32_t slot = w.moveBuffer[k];
        const Shape& s = w.shapes[slot];
        if (!s.alive) {
          continue;
        }
        const auto visit = [&](std::int32_t, std::uint64_t other64) {
          const auto other = static_cast<std::uint32_t>(other64);
          if (other == slot || (w.movedShapes[other] != 0 && other < slot)) {
            return true;
          }
          const Shape& o = w.shapes[other];
          // The filters are in the shapes' records, read already: a pair they keep apart (a
          // ragdoll's bones, a cloth's jointed neighbours) spares the reads of both bodies.
          if (o.body == s.body || !shouldCollide(s.filter, o.filter)) {
            return true;
          }
          const Body& ba = w.bodies[s.body];
          const Body& bb = w.bodies[o.body];
          // Something must be able to respond.
          if (ba.type != BodyType::dynamicBody && bb.type != BodyType::dynamicBody) {
            return true;
          }
          // The pair's contact, if it has one, is in both bodies' lists: a body without contacts
          // (a cloth's jointed neighbours) spares the index's lookup, a cache miss in a big world.
          const std::uint64_t key = pairKey(slot, other);
          if (ba.contactHead != detail::noContactEdge && bb.contactHead != detail::noContactEdge &&
              w.contactByPair.contains(key)) {
            return true;
          }
          if (w.jointBlocksCollision(s.body, o.body)) {
            return true;
          }
          found.push_back(key);
          return true;
        };
        w.movingTree.query(w.fatBoxes[slot], visit);
        if (!s.inStaticTree) {
          w.staticTree.query(w.fatBoxes[slot], visit);
        }
      }
    }
  });
  for (const std::uint32_t slot : w.moveBuffer) {
    w.movedShapes[slot] = 0;
  }
  w.moveBuffer.clear();
  w.newPairs.clear();
  for (std::uint32_t block = 0; block < blocks; ++block) {
    w.newPairs.insert(w.newPairs.end(), w.pairBlocks[block].begin(), w.pairBlocks[block].end());
  }
  std::sort(w.newPairs.begin(), w.newPairs.end()); // deterministic creation order
  // A shape listed twice in the move buffer finds its pairs twice.
  w.newPairs.erase(std::unique(w.newPairs.begin(), w.newPairs.end()), w.newPairs.end());
  for (std::uint64_t key : w.newPairs) {
    if (passesCustomFilter(w, key)) {
      createContact(w, key);
    }
  }
}

/// What the collide pass found for a contact, in WorldState::touchChanges: a change (the low
/// bits) and whether it touches a sleeping body (a flag).
enum TouchChange : std::uint8_t {
  unchanged = 0,
  began = 1,
  ended = 2,
  disjoint = 3,
  changeBits = 3,
  touchesSleeper = 4
};

/// How many contacts ahead the collide pass asks the cache for a contact (and, half as far
/// ahead, for its shapes' boxes and its bodies, read from the contact by then): the awake set
/// lists contacts in slot order, a few hundred bytes apart and far apart in the body and shape
/// arrays, too sparse for the hardware to follow, and each is a chain of dependent loads.
constexpr std::uint32_t collidePrefetchDistance = 8;

/// Asks the cache for all of a contact's bytes. Always inlined: GCC 12 finds a function of
/// nothing but prefetches free of side effects and deletes its calls.
[[gnu::always_inline]] inline void prefetchContact(const Contact& contact) {
  const auto* bytes = reinterpret_cast<const char*>(&contact);
  for (std::size_t offset = 0; offset < sizeof(Contact); offset += 64) {
    __builtin_prefetch(bytes + offset);
  }
}

/// Asks the cache for what the collide pass reads through a contact: its shapes' fat boxes and
/// records, and its bodies.
[[gnu::always_inline]] inline void prefetchContactBodies(const WorldState& w, const Contact& contact) {
  __builtin_prefetch(&w.fatBoxes[contact.shapeA]);
  __builtin_prefetch(&w.fatBoxes[contact.shapeB]);
  __builtin_prefetch(&w.shapes[contact.shapeA]);
  __builtin_prefetch(&w.shapes[contact.shapeB]);
  __builtin_prefetch(&w.bodies[contact.bodyA]);
  __builtin_prefetch(&w.bodies[contact.bodyB]);
}

[[nodiscard]] bool asleep(const Body& b) noexcept { return b.alive && b.type != BodyType::staticBody && !b.awake; }

/// Recomputes the manifolds of the awake set's contacts (in parallel: each writes only its own
/// contact), then, in slot order, ends the contacts whose fat boxes no longer overlap,
/// wakes the sleeping islands that a moving body touches, joins the islands of contacts that
/// begin touching, and reports begin and end events.
void collideContacts(WorldState& w) {
  w.awakeContactSet.compact();
  const auto count = static_cast<std::uint32_t>(w.awakeContactSet.size());
  w.touchChanges.assign(count, unchanged);
  const float reuseDistance = w.def.contactReuseDistance;
  const float reuseTurnSine = std::sin(w.def.contactReuseAngle);
  const std::uint32_t* awakeContacts = w.awakeContactSet.items().data();
  w.parallelFor(count, 64, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t k = begin; k < end; ++k) {
      if (k + collidePrefetchDistance < end) {
        prefetchContact(w.contacts[awakeContacts[k + collidePrefetchDistance]]);
      }
      if (k + collidePrefetchDistance / 2 < end) {
        prefetchContactBodies(w, w.contacts[awakeContacts[k + collidePrefetchDistance / 2]]);
      }
      Contact& contact = w.contacts[awakeContacts[k]];
      if (!overlaps(w.fatBoxes[contact.shapeA], w.fatBoxes[contact.shapeB])) {
        w.touchChanges[k] = disjoint;
        continue;
      }
      const Body& bodyA = w.bodies[contact.bodyA];
      const Body& bodyB = w.bodies[contact.bodyB];
      if (contact.manifold.pointCount == 0 && staysApart(contact, bodyA.transform, bodyB.transform)) {
        continue; // still apart: nothing to collide, nothing changed
      }
      const bool sleeper = !contact.sensor && (asleep(bodyA) || asleep(bodyB));
      if (reuseDistance > 0.0f && contact.reusable && contact.manifold.pointCount > 0 &&
          carryManifold(contact, bodyA.transform, bodyB.transform, reuseDistance, reuseTurnSine)) {
        // The same features, points carried along: still touching, impulses kept.
        w.touchChanges[k] = sleeper ? touchesSleeper : unchanged;
        continue;
      }
      const Manifold old = contact.manifold;
      contact.manifold = collide(w.shapes[contact.shapeA], bodyA.transform, w.shapes[contact.shapeB], bodyB.transform);
      if (contact.preSolve && contact.manifold.pointCount > 0 && w.preSolve &&
          !w.preSolve(w.shapes[contact.shapeA].id, w.shapes[contact.shapeB].id, contact.manifold)) {
        contact.manifold.pointCount = 0; // not solved, not touching, this step
      }
      const bool touching = contact.manifold.pointCount > 0;
      if (touching) {
        recordManifoldFrame(contact, bodyA.transform, bodyB.transform);
      } else {
        recordSeparation(contact, bodyA.transform, bodyB.transform);
      }
      const bool wasTouching = old.pointCount > 0;
      if (touching != wasTouching) {
        // Remember the old manifold's point count: the end event needs to know it touched.
        w.touchChanges[k] = touching ? began : ended;
      }
      if (touching && sleeper) {
        w.touchChanges[k] |= touchesSleeper;
      }
      // Warm starting: a point with the same features as last step keeps its impulses.
      for (int i = 0; i < contact.manifold.pointCount; ++i) {
        ManifoldPoint& p = contact.manifold.points[static_cast<std::size_t>(i)];
        for (int j = 0; j < old.pointCount; ++j) {
          const ManifoldPoint& q = old.points[static_cast<std::size_t>(j)];
          if (q.id == p.id) {
            p.normalImpulse = q.normalImpulse;
            p.tangentImpulse = q.tangentImpulse;
          }
        }
      }
      if (!touching) {
        contact.rollingImpulse = 0.0f;
      }
    }
  });
  // The awake set grows as islands wake, and holes open where contacts end: by index, over the
  // contacts collided above.
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint8_t flags = w.touchChanges[k];
    if (flags == unchanged) {
      continue;
    }
    const std::uint32_t slot = w.awakeContactSet.items()[k];
    const Contact& c = w.contacts[slot];
    if ((flags & touchesSleeper) != 0) {
      // A moving body touches a sleeping one: its island wakes and joins this step's solve.
      for (const std::uint32_t body : {c.bodyA, c.bodyB}) {
        if (asleep(w.bodies[body])) {
          detail::wakeIsland(w, w.islands.islandOf(body));
        }
      }
    }
    const std::uint8_t change = flags & changeBits;
    if (change == disjoint) {
      if (c.manifold.pointCount > 0) {
        // A support went away (teleported, say): what rested on it must fall.
        detail::wakeBody(w, c.bodyA);
        detail::wakeBody(w, c.bodyB);
      }
      detail::destroyContact(w, slot, w.contactEvents, w.sensorEvents);
      continue;
    }
    detail::updateContactColour(w, slot);
    if (change != unchanged && detail::joinsIslands(w, c)) {
      if (change == began) {
        w.islands.link(c.bodyA, c.bodyB);
      } else {
        w.islands.unlink(c.bodyA, c.bodyB);
      }
    }
    const Shape& a = w.shapes[c.shapeA];
    const Shape& b = w.shapes[c.shapeB];
    if (change == unchanged) {
      continue;
    }
    if (c.sensor) {
      const SensorEvent e = a.sensor ? SensorEvent{a.id, b.id} : SensorEvent{b.id, a.id};
      (change == began ? w.sensorEvents.begins : w.sensorEvents.ends).push_back(e);
    } else if (change == began) {
      w.contactEvents.begins.push_back({a.id, b.id});
    } else {
      w.contactEvents.ends.push_back({a.id, b.id});
    }
  }
  w.awakeContactSet.compact();
}

} // namespace

World::World(const WorldDef& def) : impl_(std::make_unique<Impl>()) {
  detail::validateWorldDef(def);
  impl_->def = def;
  // The ids it hands out record it: another world refuses them.
  const std::uint32_t number = nextWorldNumber();
  impl_->bodyIds = IdPool(number);
  impl_->shapeIds = IdPool(number);
  impl_->jointIds = IdPool(number);
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

int World::contactLanes() const noexcept { return detail::contactLanes(*impl_); }
const char* World::contactSimd() const noexcept { return detail::contactSimd(*impl_); }
const StepProfile& World::profile() const noexcept { return impl_->profile; }
ConstraintGraphCounts World::constraintGraph() const noexcept { return detail::constraintGraph(*impl_); }

std::size_t World::contactCount() const noexcept {
  return static_cast<std::size_t>(std::count_if(impl_->contacts.begin(), impl_->contacts.end(), [](const Contact& c) {
    return c.alive && !c.sensor && c.manifold.pointCount > 0;
  }));
}

// Here rather than with the other body setters: a teleport moves the body's shapes in the
// broadphase (synchronizeShapes), as the step's finalize does.
void World::setTransform(BodyId id, const Vec2f& position, float angle) {
  detail::requireWorldPosition(position);
  requireFinite(angle, "angle");
  Impl& w = *impl_;
  Body& b = w.body(id);
  detail::wakeBody(w, id.index);
  // What touches it (rests on it, or is pushed by it) reacts too: its own contacts only.
  for (std::uint32_t key = b.contactHead; key != detail::noContactEdge;) {
    const Contact& c = w.contacts[key >> 1];
    if (c.manifold.pointCount > 0) {
      detail::wakeBody(w, c.bodyA);
      detail::wakeBody(w, c.bodyB);
    }
    key = c.next[key & 1U];
  }
  b.transform = {position, Rot2f::fromAngle(angle)};
  b.center = transformPoint(b.transform, b.localCenter);
  detail::synchronizeShapes(*impl_, b);
}

void World::step(float dt) {
  if (!(dt > 0.0f && dt <= 1.0f)) {
    throwInvalid("dt", dt, "time step must be in (0, 1] s");
  }
  Impl& w = *impl_;
  // Last step's events make way for this step's, starting with those raised since (destroyed
  // bodies); the vectors keep their capacity, so a warmed-up step does not allocate.
  const auto take = [](auto& into, auto& from) {
    into.assign(from.begin(), from.end());
    from.clear();
  };
  take(w.contactEvents.begins, w.pendingEvents.begins);
  take(w.contactEvents.ends, w.pendingEvents.ends);
  take(w.contactEvents.hits, w.pendingEvents.hits);
  take(w.sensorEvents.begins, w.pendingSensorEvents.begins);
  take(w.sensorEvents.ends, w.pendingSensorEvents.ends);
  w.jointEvents.breaks.clear();
  solver::StageClock clock;
  StepProfile& profile = w.profile;
  profile = {};
  updatePairs(w);
  profile.pairs = clock.lap();
  collideContacts(w);
  w.maybeHit.assign(w.contacts.size(), 0);
  profile.collide = clock.lap();
  if (w.def.solver == SolverKind::bookImpulse) {
    detail::solveBookImpulse(w, dt);
  } else {
    detail::solve(w, dt);
  }
  profile.solve = clock.lap();
  for (const std::uint32_t slot : w.awakeContactSet.items()) {
    if (w.maybeHit[slot] == 0) {
      continue;
    }
    const Contact& contact = w.contacts[slot];
    if (contact.alive && !contact.sensor && contact.manifold.pointCount > 0 &&
        detail::approachMayHit(contact.approachSpeed, w.def.hitEventThreshold) &&
        (w.bodies[contact.bodyA].moving() || w.bodies[contact.bodyB].moving())) {
      const ManifoldPoint& p = contact.manifold.points[static_cast<std::size_t>(contact.fastestPoint)];
      w.contactEvents.hits.push_back({w.shapes[contact.shapeA].id, w.shapes[contact.shapeB].id, p.point,
                                      contact.manifold.normal, contact.approachSpeed});
    }
  }
  detail::finalizeBodies(w, dt);
  // The moving tree tight again for the game's queries between steps (and for the next pair
  // update, which rebuilds only what the game moved since).
  w.movingTree.rebuild();
  if (w.def.enableSleep) {
    detail::updateSleep(w, dt);
  }
  // The bodies the step moved (the solver's awake list, in slot order), and which fell asleep.
  w.bodyMoveEvents.clear();
  for (const std::uint32_t slot : w.awakeBodies) {
    const Body& b = w.bodies[slot];
    w.bodyMoveEvents.push_back({b.id, b.transform, !b.awake, b.userData});
  }
  profile.finalize = clock.lap();
  profile.step = clock.total();
}

const ContactEvents& World::contactEvents() const noexcept { return impl_->contactEvents; }
const SensorEvents& World::sensorEvents() const noexcept { return impl_->sensorEvents; }
const std::vector<BodyMoveEvent>& World::bodyMoveEvents() const noexcept { return impl_->bodyMoveEvents; }
void World::setCustomFilter(CustomFilterFcn filter) { impl_->customFilter = std::move(filter); }
void World::setPreSolve(PreSolveFcn preSolve) { impl_->preSolve = std::move(preSolve); }

namespace detail {

void destroyContact(WorldState& w, std::uint32_t slot, ContactEvents& events, SensorEvents& sensors) {
  Contact& c = w.contacts[slot];
  reportEnd(w, c, events, sensors);
  if (c.manifold.pointCount > 0 && joinsIslands(w, c)) {
    w.islands.unlink(c.bodyA, c.bodyB);
  }
  w.awakeContactSet.remove(slot);
  w.contactGraph.remove(slot);
  w.contactByPair.erase(pairKey(c.shapeA, c.shapeB));
  // Out of both bodies' lists.
  for (std::uint32_t edge = 0; edge < 2; ++edge) {
    const std::uint32_t before = c.prev[edge];
    const std::uint32_t after = c.next[edge];
    if (before != noContactEdge) {
      w.contacts[before >> 1].next[before & 1U] = after;
    } else {
      w.bodies[edge == 0 ? c.bodyA : c.bodyB].contactHead = after;
    }
    if (after != noContactEdge) {
      w.contacts[after >> 1].prev[after & 1U] = before;
    }
  }
  c.alive = false;
  w.freeContacts.push_back(slot);
}

void bodyContacts(const WorldState& w, std::uint32_t body, std::vector<std::uint32_t>& out) {
  out.clear();
  for (std::uint32_t key = w.bodies[body].contactHead; key != noContactEdge;) {
    out.push_back(key >> 1);
    key = w.contacts[key >> 1].next[key & 1U];
  }
  std::sort(out.begin(), out.end());
}

} // namespace detail

} // namespace impetus::rigid2d
