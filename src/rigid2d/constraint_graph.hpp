// The soft step's constraint graph (contact_solver.cpp, joint_graph.cpp): the joints and the
// touching contacts in colours such that no two joints, or two contacts, of a colour share a
// moving body (static bodies do not count: nothing writes them), with an overflow for what finds
// no colour. The contacts keep their colours from step to step (WorldState::contactGraph); the
// joints are coloured again when they or the moving bodies change. A colour's joints are solved
// before its contacts, so a joint and a contact of one colour may share a body.
#pragma once

#include "rigid2d/contact_constraint.hpp"
#include "rigid2d/joints.hpp"
#include "solver/colour_graph.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace impetus::rigid2d::detail {

inline constexpr int colourCount = static_cast<int>(solver::graphColourCount);
/// A joint without a solver copy, in ContactSolverData::simOfJoint.
inline constexpr std::uint32_t noJointSim = ~std::uint32_t{0};
/// Joints between two moving bodies use colours [0, dynamicColourCount); joints with a static
/// body may use any colour (as contacts: solver::graphStaticColourCount).
inline constexpr int dynamicColourCount = colourCount - static_cast<int>(solver::graphStaticColourCount);
inline constexpr std::uint32_t allColours = (std::uint32_t{1} << colourCount) - 1;
inline constexpr std::uint32_t dynamicColours = (std::uint32_t{1} << dynamicColourCount) - 1;
static_assert(colourCount < 32);

/// Storage for wide batches whose layout only the kernels know: aligned blocks.
struct alignas(wideAlignment) WideBlock {
  std::byte bytes[wideAlignment];
};

/// The soft step's constraint graph and its solver data: the contacts' wide batches and the
/// joints' copies, colour by colour.
struct ContactSolverData {
  const WideKernels* kernels = nullptr;
  std::vector<WideBlock> wide;                              ///< batches, colour by colour
  std::vector<std::uint32_t> slots;                         ///< contact slot per lane (or ~0), width per batch
  std::array<std::uint32_t, colourCount + 1> colourStart{}; ///< first batch of each colour
  std::vector<ContactConstraint> overflow;
  std::vector<std::uint32_t> bodyColours; ///< per solver body: bit c set when a joint of colour c holds it
  std::array<std::vector<std::uint32_t>, colourCount> colourJoints; ///< joint slots, in slot order
  std::vector<std::uint32_t> overflowJoints;
  /// The joints solved this step: the overflow's, then colour by colour (jointColourStart). Kept
  /// from step to step while the joints and moving bodies they were coloured for stay the same.
  std::vector<JointSim> jointSims;
  std::array<std::uint32_t, colourCount + 1> jointColourStart{};
  std::vector<std::uint32_t> simOfJoint;          ///< by joint slot: its index in jointSims, or noJointSim
  std::vector<std::uint32_t> colouredJoints;      ///< the solvedJoints the joint colours were made for
  std::vector<std::uint32_t> colouredBodies;      ///< ... and the awakeBodies
  std::vector<std::uint32_t> colouredAwakeJoints; ///< ... and the awake joint set they were collected from
  std::vector<std::uint32_t> breakableJoints;     ///< slots, in slot order, of the copies' joints with break limits
  bool jointColoursValid = false;                 ///< the copies match colouredJoints (no joint destroyed since)
  Softness soft, staticSoft;
  float pushSpeed = 0.0f;
  float restitutionThreshold = 0.0f;
  ContactSpeedCaps caps; ///< this step's, for the points' impulse bounds

  [[nodiscard]] void* batches() { return wide.data(); }
};

/// The first colour among `allowed` free for both moving bodies (static ones pass as null), or
/// -1; marks it taken. One mask of used colours per body: a lookup touches two words.
inline int findColour(ContactSolverData& d, std::uint32_t a, std::uint32_t b, std::uint32_t staticIndex,
                      std::uint32_t allowed) {
  std::uint32_t used = 0;
  if (a != staticIndex) {
    used |= d.bodyColours[a];
  }
  if (b != staticIndex) {
    used |= d.bodyColours[b];
  }
  const std::uint32_t free = allowed & ~used;
  if (free == 0) {
    return -1;
  }
  const std::uint32_t bit = free & (~free + 1); // the lowest free colour
  if (a != staticIndex) {
    d.bodyColours[a] |= bit;
  }
  if (b != staticIndex) {
    d.bodyColours[b] |= bit;
  }
  return std::countr_zero(bit);
}

/// The fewest joints of a colour worth a task of their own (a joint's solve is about a tenth of a
/// microsecond).
inline constexpr std::uint32_t minJointsPerTask = 64;

/// Collects and colours this step's joints before the contacts and makes (or keeps) their solver
/// copies; true if it kept last step's (their frames' solver indices are still this step's).
bool colourJoints(WorldState& w, ContactSolverData& d);
/// Each joint copy's frame for this step and its type's prepare, on threads; `kept`: the copies
/// are last step's (colourJoints).
void prepareJointSims(WorldState& w, ContactSolverData& d, const StepContext& context, bool kept);

} // namespace impetus::rigid2d::detail
