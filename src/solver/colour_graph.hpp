// The persistent constraint graph (the solver layer: no dimension in it), as Box2D v3 keeps it:
// constraints in colours such that no two of a colour share a moving body, so that a colour's
// constraints can be solved at once (in SIMD lanes, on threads) with results that do not depend
// on their order. A constraint takes its colour when it begins (a contact begins touching, an
// island wakes) and gives it back when it ends; the colours are not found again each step, so a
// step does not read every constraint to colour it.
//
// Static bodies take no colour (nothing writes them): a constraint with one is free in every
// colour its moving body is. What finds no free colour (a body touching very many others) goes
// to the overflow, solved one at a time. The colours a constraint may take depend only on the
// masks of its two bodies: the graph's state, and what it gives, depends on the order in which
// constraints were added and removed, which the world keeps deterministic (and a snapshot saves).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace impetus::solver {

/// Colours in the graph (a body's colours are the bits of one 32-bit mask).
inline constexpr std::uint32_t graphColourCount = 24;
/// Colours kept for constraints with a static body, which take up one moving body only: those
/// between two moving bodies use [0, graphColourCount - graphStaticColourCount). Without them a
/// pile's contacts would fill every colour and leave the ground's contacts in the overflow.
/// (Box2D v3 also keeps static contacts out of colour 0; that delays the ground's support of a
/// stack by a colour each substep and let a 10-box stack sway 2 cm, against 0.5 cm.)
inline constexpr std::uint32_t graphStaticColourCount = 4;

class ColourGraph {
public:
  /// A static body, which takes no colour.
  static constexpr std::uint32_t noBody = 0xffffffffU;
  /// The overflow's index among the colours (members(overflow): what found no colour).
  static constexpr std::uint32_t overflow = graphColourCount;

  /// Adds constraint `id` between two bodies (slots, or noBody), in the lowest colour free for
  /// both that it may take; returns the colour (or overflow). `id` must not be in the graph.
  std::uint32_t add(std::uint32_t id, std::uint32_t bodyA, std::uint32_t bodyB);
  /// Not in the graph (a Place's colour).
  static constexpr std::uint32_t absent = 0xffffffffU;
  /// Where a constraint is: its colour (or overflow) and its index there, for a snapshot.
  struct Place {
    std::uint32_t colour = absent; ///< absent: not in the graph
    std::uint32_t index = 0;
  };
  [[nodiscard]] Place placeOf(std::uint32_t id) const noexcept {
    return contains(id) ? Place{places_[id].colour, places_[id].index} : Place{};
  }
  /// Puts `id` back where a snapshot of the graph found it, after clear(): false (nothing
  /// changed) when `id` is in the graph, the colour is not free for both bodies, the index is
  /// taken or not below `bound`. The graph is whole again once every member was put back
  /// (whole()).
  bool restore(std::uint32_t id, std::uint32_t bodyA, std::uint32_t bodyB, Place at, std::uint32_t bound);
  /// Whether no colour has a hole left by restore.
  [[nodiscard]] bool whole() const noexcept;
  /// Takes `id` out of the graph (nothing when it is not in it). The colour's last member takes
  /// its place.
  void remove(std::uint32_t id) noexcept;

  [[nodiscard]] bool contains(std::uint32_t id) const noexcept {
    return id < places_.size() && places_[id].colour != absent;
  }
  /// The constraints of a colour (or of the overflow), in the order they were placed.
  [[nodiscard]] std::span<const std::uint32_t> members(std::uint32_t colour) const noexcept { return members_[colour]; }
  /// How many constraints the graph holds.
  [[nodiscard]] std::size_t size() const noexcept;
  /// Empties the graph, keeping its storage.
  void clear() noexcept;

private:
  struct Member {
    std::uint32_t colour = absent;
    std::uint32_t index = 0; ///< in members_[colour]
    std::uint32_t bodyA = noBody;
    std::uint32_t bodyB = noBody;
  };

  /// Adds `id` at members_[colour][index] (index: the colour's end, or a hole restore fills).
  void place(std::uint32_t id, std::uint32_t bodyA, std::uint32_t bodyB, std::uint32_t colour, std::uint32_t index);
  [[nodiscard]] bool isFree(std::uint32_t colour, std::uint32_t bodyA, std::uint32_t bodyB) const noexcept {
    return colour == overflow || ((coloursOf(bodyA) | coloursOf(bodyB)) & (std::uint32_t{1} << colour)) == 0;
  }
  [[nodiscard]] std::uint32_t coloursOf(std::uint32_t body) const noexcept {
    return body < bodyColours_.size() ? bodyColours_[body] : 0;
  }

  std::vector<std::uint32_t> bodyColours_; ///< by body slot: bit c set when colour c holds the body
  std::array<std::vector<std::uint32_t>, graphColourCount + 1> members_;
  std::vector<Member> places_; ///< by constraint id
};

} // namespace impetus::solver
