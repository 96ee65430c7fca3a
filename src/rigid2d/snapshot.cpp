// Snapshots of a world's dynamic state, for rollback (lockstep games rewind and replay a few
// frames when late input arrives) and replays.
//
// What the next steps depend on, and so what is saved: every live body's motion, applied force
// and sleep state; every shape's fat box (it decides when the broadphase looks for new pairs);
// the broadphase's move buffer; the contact pool slot by slot (slot order is the solve order)
// with its free list and every contact's manifold and warm-start impulses; every joint; the
// awake set and the islands. What is
// not: the trees' shape (new pairs are sorted before they become contacts, so the order a tree
// finds them in never matters), the solver's scratch (rebuilt each step), and the structure
// (bodies, shapes and joints), which must be the one the snapshot was saved from: a hash of the
// live ids and body types guards it.
#include "rigid2d/joints.hpp"
#include "rigid2d/world_impl.hpp"

#include <impetus/core/state_hash.hpp>
#include <impetus/error.hpp>

#include <cstring>
#include <span>
#include <string>
#include <type_traits>

namespace impetus::rigid2d {
namespace {

using detail::Body;
using detail::Contact;
using detail::Joint;
using detail::Shape;
using detail::WorldState;

constexpr std::uint32_t snapshotMagic = 0x53443249; // "I2DS"
constexpr std::uint32_t snapshotVersion = 8;

static_assert(std::is_trivially_copyable_v<Contact>);
static_assert(std::is_trivially_copyable_v<Joint>);

/// Appends trivially copyable values to a byte buffer.
class Writer {
public:
  explicit Writer(std::vector<std::byte>& bytes) : bytes_(bytes) { bytes_.clear(); }
  template <class T> void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
  }

private:
  std::vector<std::byte>& bytes_;
};

/// Reads them back in the same order; running past the end is a truncated snapshot.
class Reader {
public:
  explicit Reader(const std::vector<std::byte>& bytes) : bytes_(bytes) {}
  template <class T> T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    if (at_ + sizeof(T) > bytes_.size()) {
      throw Error("snapshot", "snapshot: truncated (" + std::to_string(bytes_.size()) + " bytes)");
    }
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  [[nodiscard]] bool done() const noexcept { return at_ == bytes_.size(); }

private:
  const std::vector<std::byte>& bytes_;
  std::size_t at_ = 0;
};

/// The world's structure: which bodies, shapes and joints exist (ids with generations), what
/// type each body is and which body each shape is on.
std::uint64_t structureHash(const WorldState& w) {
  StateHash hash;
  hash.add(static_cast<std::uint32_t>(w.bodies.size()));
  for (const Body& b : w.bodies) {
    hash.add(b.alive);
    if (b.alive) {
      hash.add(b.id.generation);
      hash.add(static_cast<std::uint32_t>(b.type));
    }
  }
  hash.add(static_cast<std::uint32_t>(w.shapes.size()));
  for (const Shape& s : w.shapes) {
    hash.add(s.alive);
    if (s.alive) {
      hash.add(s.id.generation);
      hash.add(s.body);
      hash.add(s.inStaticTree);
    }
  }
  hash.add(static_cast<std::uint32_t>(w.joints.size()));
  for (const Joint& j : w.joints) {
    hash.add(j.alive);
    if (j.alive) {
      hash.add(j.id.generation);
    }
  }
  return hash.value();
}

/// Writes the count and then each value of a list of slots.
void putList(Writer& out, const std::vector<std::uint32_t>& list) {
  out.put(static_cast<std::uint32_t>(list.size()));
  for (std::uint32_t v : list) {
    out.put(v);
  }
}

/// Writes a slot list's slots in order, without its holes.
void putSlots(Writer& out, const solver::SlotList& list) {
  out.put(static_cast<std::uint32_t>(list.size()));
  for (const std::uint32_t slot : list.items()) {
    if (slot != solver::SlotList::hole) {
      out.put(slot);
    }
  }
}

/// Reads what putSlots wrote into `list` (its own storage: nothing allocated once warmed up).
template <class Valid>
void getSlots(Reader& in, solver::SlotList& list, std::size_t bound, const char* what, const Valid& valid) {
  const auto n = in.get<std::uint32_t>();
  list.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto slot = in.get<std::uint32_t>();
    if (slot >= bound || !valid(slot)) {
      throw Error("snapshot",
                  std::string("snapshot: an awake ") + what + " that is not (" + std::to_string(slot) + ")");
    }
    list.add(slot);
  }
}

void getList(Reader& in, std::vector<std::uint32_t>& list, std::size_t bound) {
  const auto n = in.get<std::uint32_t>();
  list.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto v = in.get<std::uint32_t>();
    if (v >= bound) {
      throw Error("snapshot", "snapshot: a slot out of range (" + std::to_string(v) + ")");
    }
    list.push_back(v);
  }
}

/// Puts a restored contact back in the constraint graph where saveState found it: a contact the
/// step solves, in a colour free for its bodies, every such contact in one.
void restoreContactColour(WorldState& w, std::uint32_t slot, solver::ColourGraph::Place at) {
  const Contact& c = w.contacts[slot];
  const bool solved = c.bodyA < w.bodies.size() && c.bodyB < w.bodies.size() && detail::solvedByStep(w, c);
  const bool placed =
      at.colour == solver::ColourGraph::absent
          ? !solved
          : solved && w.contactGraph.restore(slot, detail::graphBodyOf(w, c.bodyA), detail::graphBodyOf(w, c.bodyB), at,
                                             static_cast<std::uint32_t>(w.contacts.size()));
  if (!placed) {
    throw Error("snapshot", "snapshot: contact " + std::to_string(slot) + " out of place in the constraint graph");
  }
}

} // namespace

void World::saveState(WorldSnapshot& out) const {
  const WorldState& w = *impl_;
  Writer put(out.bytes_);
  put.put(snapshotMagic);
  put.put(snapshotVersion);
  put.put(structureHash(w));
  put.put(w.lastInverseH);
  for (const Body& b : w.bodies) {
    if (b.alive) {
      put.put(b.transform);
      put.put(b.center);
      put.put(b.linearVelocity);
      put.put(b.angularVelocity);
      put.put(b.force);
      put.put(b.torque);
      put.put(b.awake);
      put.put(b.sleepTime);
      put.put(b.contactHead);
    }
  }
  for (std::size_t slot = 0; slot < w.shapes.size(); ++slot) {
    if (w.shapes[slot].alive) {
      put.put(w.fatBoxes[slot]);
    }
  }
  putList(put, w.moveBuffer);
  put.put(static_cast<std::uint32_t>(w.contacts.size()));
  for (const Contact& c : w.contacts) {
    put.put(c.alive);
    if (c.alive) {
      put.put(c);
      // Its colour: what the solve gives depends on it, and it on the timeline.
      put.put(w.contactGraph.placeOf(static_cast<std::uint32_t>(&c - w.contacts.data())));
    }
  }
  putList(put, w.freeContacts);
  for (std::uint32_t slot = 0; slot < w.joints.size(); ++slot) {
    if (w.joints[slot].alive) {
      Joint j = w.joints[slot];
      j.data = detail::jointDataOf(w, slot); // the solver's copy holds it while the joint is awake
      put.put(j);
    }
  }
  putSlots(put, w.awakeBodySet);
  putSlots(put, w.awakeContactSet);
  putSlots(put, w.awakeJointSet);
  w.islands.save(put);
}

void World::restoreState(const WorldSnapshot& snapshot) {
  WorldState& w = *impl_;
  if (snapshot.empty()) {
    throw Error("snapshot", "snapshot: empty (nothing was saved into it)");
  }
  Reader in(snapshot.bytes_);
  if (in.get<std::uint32_t>() != snapshotMagic || in.get<std::uint32_t>() != snapshotVersion) {
    throw Error("snapshot", "snapshot: not a snapshot of this version of Impetus");
  }
  if (in.get<std::uint64_t>() != structureHash(w)) {
    throw Error("snapshot", "snapshot: saved from a world with other bodies, shapes or joints (created, destroyed "
                            "or changed type since)");
  }
  // Everything is read into place only after the checks above: a structural mismatch leaves the
  // world untouched. (A truncated snapshot of a matching world cannot be written by saveState.)
  w.lastInverseH = in.get<float>();
  for (Body& b : w.bodies) {
    if (b.alive) {
      b.transform = in.get<Transform2f>();
      b.center = in.get<Vec2f>();
      b.linearVelocity = in.get<Vec2f>();
      b.angularVelocity = in.get<float>();
      b.force = in.get<Vec2f>();
      b.torque = in.get<float>();
      b.awake = in.get<bool>();
      b.sleepTime = in.get<float>();
      b.contactHead = in.get<std::uint32_t>();
    }
  }
  for (std::size_t slot = 0; slot < w.shapes.size(); ++slot) {
    if (const Shape& s = w.shapes[slot]; s.alive) {
      const AABB fatBox = in.get<AABB>();
      if (std::memcmp(&fatBox, &w.fatBoxes[slot], sizeof(AABB)) != 0) {
        w.fatBoxes[slot] = fatBox;
        w.treeOf(s).moveProxy(s.proxy, fatBox);
      }
    }
  }
  getList(in, w.moveBuffer, w.shapes.size());
  const auto contactSlots = in.get<std::uint32_t>();
  w.contacts.assign(contactSlots, Contact{});
  w.contactByPair.clear();
  w.contactGraph.clear();
  for (std::uint32_t slot = 0; slot < contactSlots; ++slot) {
    if (in.get<bool>()) {
      const auto c = in.get<Contact>();
      w.contacts[slot] = c;
      w.contactByPair.insert(detail::pairKey(c.shapeA, c.shapeB), slot);
      restoreContactColour(w, slot, in.get<solver::ColourGraph::Place>());
    }
  }
  if (!w.contactGraph.whole()) {
    throw Error("snapshot", "snapshot: a colour of the constraint graph has a hole");
  }
  getList(in, w.freeContacts, contactSlots);
  // The bodies' contact lists must stay inside the contacts restored (a snapshot of this world
  // always does; anything else is refused before a traversal could leave the array).
  const auto validEdge = [&](std::uint32_t key) {
    return key == detail::noContactEdge || ((key >> 1) < contactSlots && w.contacts[key >> 1].alive);
  };
  bool listsValid = true;
  for (const Body& b : w.bodies) {
    listsValid = listsValid && (!b.alive || validEdge(b.contactHead));
  }
  for (const Contact& c : w.contacts) {
    listsValid =
        listsValid &&
        (!c.alive || (validEdge(c.next[0]) && validEdge(c.next[1]) && validEdge(c.prev[0]) && validEdge(c.prev[1])));
  }
  if (!listsValid) {
    throw Error("snapshot", "snapshot: a body's contact list points outside the contacts");
  }
  detail::dropJointSims(w); // what they held is the timeline that was left
  for (Joint& j : w.joints) {
    if (j.alive) {
      const JointId id = j.id; // this world's (a replay's world has a number of its own)
      j = in.get<Joint>();
      j.id = id;
    }
  }
  // The awake set and the islands: only live bodies, contacts and joints.
  getSlots(in, w.awakeBodySet, w.bodies.size(), "body", [&](std::uint32_t slot) { return w.bodies[slot].moving(); });
  getSlots(in, w.awakeContactSet, contactSlots, "contact", [&](std::uint32_t slot) { return w.contacts[slot].alive; });
  getSlots(in, w.awakeJointSet, w.joints.size(), "joint", [&](std::uint32_t slot) { return w.joints[slot].alive; });
  w.islands.load(in, w.bodies.size(), [](std::uint32_t slot) {
    throw Error("snapshot", "snapshot: an island's body or slot out of place (" + std::to_string(slot) + ")");
  });
  for (const Body& b : w.bodies) {
    if (b.alive && (b.type != BodyType::staticBody) != (w.islands.islandOf(b.id.index) != solver::Islands::none)) {
      throw Error("snapshot",
                  "snapshot: a body in no island, or a static body in one (" + std::to_string(b.id.index) + ")");
    }
  }
  for (detail::SolverBodyInfo& info : w.bodyInfo) {
    info.solverIndex = detail::noSolverIndex; // refreshed for the awake bodies by the next step
  }
  if (!in.done()) {
    throw Error("snapshot", "snapshot: trailing bytes after the islands");
  }
  // This step's events belong to the timeline that was left (cleared, keeping their capacity).
  for (ContactEvents* events : {&w.contactEvents, &w.pendingEvents}) {
    events->begins.clear();
    events->ends.clear();
    events->hits.clear();
  }
  for (SensorEvents* events : {&w.sensorEvents, &w.pendingSensorEvents}) {
    events->begins.clear();
    events->ends.clear();
  }
  w.jointEvents.breaks.clear();
}

} // namespace impetus::rigid2d
