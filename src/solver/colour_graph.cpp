#include "solver/colour_graph.hpp"

#include <bit>

namespace impetus::solver {

namespace {

constexpr std::uint32_t allColours = (std::uint32_t{1} << graphColourCount) - 1;
constexpr std::uint32_t movingPairColours = (std::uint32_t{1} << (graphColourCount - graphStaticColourCount)) - 1;
static_assert(graphColourCount < 32 && graphStaticColourCount < graphColourCount);

} // namespace

std::uint32_t ColourGraph::add(std::uint32_t id, std::uint32_t bodyA, std::uint32_t bodyB) {
  const bool withStatic = bodyA == noBody || bodyB == noBody;
  const std::uint32_t free = (withStatic ? allColours : movingPairColours) & ~(coloursOf(bodyA) | coloursOf(bodyB));
  const std::uint32_t colour = free == 0 ? overflow : static_cast<std::uint32_t>(std::countr_zero(free));
  place(id, bodyA, bodyB, colour, static_cast<std::uint32_t>(members_[colour].size()));
  return colour;
}

bool ColourGraph::restore(std::uint32_t id, std::uint32_t bodyA, std::uint32_t bodyB, Place at, std::uint32_t bound) {
  if (at.colour > overflow || at.index >= bound || contains(id) || !isFree(at.colour, bodyA, bodyB)) {
    return false;
  }
  std::vector<std::uint32_t>& members = members_[at.colour];
  if (at.index >= members.size()) {
    members.resize(std::size_t{at.index} + 1, absent);
  } else if (members[at.index] != absent) {
    return false;
  }
  place(id, bodyA, bodyB, at.colour, at.index);
  return true;
}

bool ColourGraph::whole() const noexcept {
  for (const std::vector<std::uint32_t>& members : members_) {
    for (const std::uint32_t id : members) {
      if (id == absent) {
        return false;
      }
    }
  }
  return true;
}

void ColourGraph::place(std::uint32_t id, std::uint32_t bodyA, std::uint32_t bodyB, std::uint32_t colour,
                        std::uint32_t index) {
  if (id >= places_.size()) {
    places_.resize(std::size_t{id} + 1);
  }
  std::vector<std::uint32_t>& members = members_[colour];
  places_[id] = {colour, index, bodyA, bodyB};
  if (index == members.size()) {
    members.push_back(id);
  } else {
    members[index] = id;
  }
  if (colour == overflow) {
    return; // the overflow is solved one at a time: it holds no body
  }
  for (const std::uint32_t body : {bodyA, bodyB}) {
    if (body != noBody) {
      if (body >= bodyColours_.size()) {
        bodyColours_.resize(std::size_t{body} + 1, 0);
      }
      bodyColours_[body] |= std::uint32_t{1} << colour;
    }
  }
}

void ColourGraph::remove(std::uint32_t id) noexcept {
  if (!contains(id)) {
    return;
  }
  Member& p = places_[id];
  std::vector<std::uint32_t>& members = members_[p.colour];
  const std::uint32_t last = members.back();
  members[p.index] = last;
  places_[last].index = p.index;
  members.pop_back();
  if (p.colour != overflow) {
    for (const std::uint32_t body : {p.bodyA, p.bodyB}) {
      if (body != noBody) {
        bodyColours_[body] &= ~(std::uint32_t{1} << p.colour);
      }
    }
  }
  p = Member{};
}

std::size_t ColourGraph::size() const noexcept {
  std::size_t count = 0;
  for (const std::vector<std::uint32_t>& members : members_) {
    count += members.size();
  }
  return count;
}

void ColourGraph::clear() noexcept {
  for (std::vector<std::uint32_t>& members : members_) {
    for (const std::uint32_t id : members) {
      if (id != absent) {
        places_[id] = Member{};
      }
    }
    members.clear();
  }
  bodyColours_.assign(bodyColours_.size(), 0);
}

} // namespace impetus::solver
