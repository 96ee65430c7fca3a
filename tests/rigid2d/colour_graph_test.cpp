// The persistent constraint graph: no two constraints of a colour share a moving body, whatever
// the history of adds and removes; static bodies take no colour; a snapshot's places come back
// exactly; and in a world, the graph holds exactly the contacts the step solves, through
// sleeping and waking.
#include "solver/colour_graph.hpp"

#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <utility>

namespace impetus::solver {
namespace {

using Bodies = std::pair<std::uint32_t, std::uint32_t>;

/// Every colour's constraints share no moving body, and every constraint is where placeOf says.
void expectValid(const ColourGraph& graph, const std::map<std::uint32_t, Bodies>& held) {
  std::size_t count = 0;
  for (std::uint32_t colour = 0; colour <= ColourGraph::overflow; ++colour) {
    std::set<std::uint32_t> bodies;
    const auto members = graph.members(colour);
    for (std::uint32_t k = 0; k < members.size(); ++k) {
      const std::uint32_t id = members[k];
      ASSERT_TRUE(held.contains(id)) << id;
      EXPECT_EQ(graph.placeOf(id).colour, colour);
      EXPECT_EQ(graph.placeOf(id).index, k);
      for (const std::uint32_t body : {held.at(id).first, held.at(id).second}) {
        if (colour != ColourGraph::overflow && body != ColourGraph::noBody) {
          EXPECT_TRUE(bodies.insert(body).second) << "body " << body << " twice in colour " << colour;
        }
      }
    }
    count += members.size();
  }
  EXPECT_EQ(count, held.size());
  EXPECT_EQ(graph.size(), held.size());
}

TEST(ColourGraph, a_colour_never_holds_a_moving_body_twice_whatever_the_history) {
  ColourGraph graph;
  std::map<std::uint32_t, Bodies> held;
  std::mt19937 twister(7);
  const auto random = [&twister] { return static_cast<std::uint32_t>(twister()); };
  constexpr std::uint32_t bodies = 12; // few bodies, many constraints: colours fill, the overflow too
  for (int op = 0; op < 4000; ++op) {
    const std::uint32_t id = random() % 200;
    if (held.contains(id)) {
      graph.remove(id);
      held.erase(id);
      EXPECT_FALSE(graph.contains(id));
    } else {
      const std::uint32_t a = random() % (bodies + 2);
      std::uint32_t b = random() % (bodies + 2);
      b = b == a ? bodies : b; // never a body with itself
      const auto body = [](std::uint32_t k) { return k >= bodies ? ColourGraph::noBody : k; };
      graph.add(id, body(a), body(b));
      held[id] = {body(a), body(b)};
    }
    if (op % 97 == 0) {
      expectValid(graph, held);
    }
  }
  expectValid(graph, held);
  EXPECT_FALSE(graph.members(ColourGraph::overflow).empty()) << "12 bodies cannot colour 100 constraints";
}

TEST(ColourGraph, static_bodies_take_no_colour_and_have_colours_of_their_own) {
  ColourGraph graph;
  // Twenty constraints of body 0 with other moving bodies fill the colours moving pairs may use.
  for (std::uint32_t k = 0; k < graphColourCount - graphStaticColourCount; ++k) {
    EXPECT_EQ(graph.add(k, 0, k + 1), k);
  }
  EXPECT_EQ(graph.add(100, 0, 50), ColourGraph::overflow);
  // Body 0 on the ground still finds a colour: those kept for static contacts.
  EXPECT_EQ(graph.add(101, 0, ColourGraph::noBody), graphColourCount - graphStaticColourCount);
  // The ground is in none: another body's ground contact takes colour 0.
  EXPECT_EQ(graph.add(102, 60, ColourGraph::noBody), 0u);
  // A removal frees its colour for the bodies.
  graph.remove(3);
  EXPECT_EQ(graph.add(103, 0, 70), 3u);
}

TEST(ColourGraph, restored_places_are_the_saved_ones_and_bad_ones_are_refused) {
  ColourGraph graph;
  std::map<std::uint32_t, Bodies> held;
  for (std::uint32_t id = 0; id < 30; ++id) {
    held[id] = {id % 5, id % 7 == 0 ? ColourGraph::noBody : 5 + id % 3};
    graph.add(id, held[id].first, held[id].second);
  }
  for (const std::uint32_t id : {4U, 11U, 17U}) {
    graph.remove(id);
    held.erase(id);
  }
  std::map<std::uint32_t, ColourGraph::Place> saved;
  for (const auto& [id, bodies] : held) {
    saved[id] = graph.placeOf(id);
  }
  graph.clear();
  EXPECT_EQ(graph.size(), 0u);
  // Restored in another order (by id, descending), the places are the saved ones.
  for (auto it = held.rbegin(); it != held.rend(); ++it) {
    ASSERT_TRUE(graph.restore(it->first, it->second.first, it->second.second, saved[it->first], 100));
  }
  EXPECT_TRUE(graph.whole());
  expectValid(graph, held);
  for (const auto& [id, place] : saved) {
    EXPECT_EQ(graph.placeOf(id).colour, place.colour);
    EXPECT_EQ(graph.placeOf(id).index, place.index);
  }
  // Refused: a taken place, a colour the bodies are in, a place past the bound, an id held.
  const ColourGraph::Place first = saved.begin()->second;
  EXPECT_FALSE(graph.restore(200, 40, 41, first, 100));
  EXPECT_FALSE(graph.restore(201, held.begin()->second.first, 42, {first.colour, 50}, 100));
  EXPECT_FALSE(graph.restore(202, 43, 44, {0, 100}, 100));
  EXPECT_FALSE(graph.restore(saved.begin()->first, 45, 46, {0, 60}, 100));
  // A place beyond a colour's end leaves a hole until it is filled.
  ColourGraph gappy;
  ASSERT_TRUE(gappy.restore(1, 0, 1, {2, 1}, 100));
  EXPECT_FALSE(gappy.whole());
  ASSERT_TRUE(gappy.restore(2, 2, 3, {2, 0}, 100));
  EXPECT_TRUE(gappy.whole());
}

} // namespace
} // namespace impetus::solver

namespace impetus::rigid2d {
namespace {

std::uint32_t graphContacts(const World& world) {
  const ConstraintGraphCounts counts = world.constraintGraph();
  std::uint32_t total = counts.overflowContacts;
  for (const std::uint32_t n : counts.colourContacts) {
    total += n;
  }
  return total;
}

// The graph is updated when contacts begin and end and islands sleep and wake, never rebuilt:
// it must hold the touching contacts of awake bodies, no more, no less.
TEST(ColourGraph, holds_the_awake_touching_contacts_through_sleeping_and_waking) {
  World world;
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  BodyDef def;
  def.type = BodyType::dynamicBody;
  std::vector<BodyId> boxes;
  for (int row = 0; row < 6; ++row) {
    for (int i = 0; i < 6 - row; ++i) {
      def.position = {static_cast<float>(i) - 0.5f * static_cast<float>(5 - row), 0.5f + static_cast<float>(row)};
      boxes.push_back(world.createBody(def));
      world.createShape(boxes.back(), {}, makeBox(0.5f, 0.5f));
    }
  }
  for (int step = 0; step < 600; ++step) {
    world.step(1.0f / 60.0f);
    if (world.awakeBodyCount() == boxes.size()) {
      EXPECT_EQ(graphContacts(world), world.contactCount()) << "step " << step;
    }
  }
  ASSERT_EQ(world.awakeBodyCount(), 0u) << "the pyramid should have fallen asleep";
  EXPECT_EQ(graphContacts(world), 0u);
  EXPECT_GT(world.contactCount(), 20u);
  // Knocked, the pyramid wakes whole: its contacts are back in the graph.
  world.applyLinearImpulse(boxes.back(), {4.0f, 0.0f}, world.worldCenterOfMass(boxes.back()));
  EXPECT_EQ(graphContacts(world), world.contactCount());
  for (int step = 0; step < 30; ++step) {
    world.step(1.0f / 60.0f);
    EXPECT_EQ(graphContacts(world), world.contactCount()) << "step " << step;
  }
}

} // namespace
} // namespace impetus::rigid2d
