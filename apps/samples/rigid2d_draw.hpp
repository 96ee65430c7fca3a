// Draws a rigid2d::World through its public inspection API: shapes coloured by body type and
// sleeping state, centres of mass, contact points and normals, the contact forces the solver
// applied, joints and bounding boxes, each switched on or off by Rigid2dDrawOptions. Everything
// comes from the world itself (its contacts, joints and anchors), so a sample draws what it never
// recorded: joints made by a builder, contacts of bodies it did not create.
#pragma once

#include "draw.hpp"

#include <impetus/rigid2d/world.hpp>

#include <functional>
#include <optional>

namespace impetus::samples {

struct Rigid2dDrawOptions {
  bool shapes = true;
  bool joints = true;
  bool centersOfMass = false;
  bool contacts = false; ///< points and normals
  /// Each contact point's normal force (the solver's normal impulse over a substep), as a segment
  /// along the normal `forceScale` newtons per metre long.
  bool contactForces = false;
  bool frictionForces = false; ///< the same for the friction impulse, along the tangent
  float forceScale = 100.0f;   ///< N per metre of drawn segment
  bool aabbs = false;          ///< each shape's tight bounding box
  bool transforms = false;
};

/// A colour chosen by the sample for some bodies (a bullet, the player's craft); none: by type.
using BodyColorFn = std::function<std::optional<Color>(rigid2d::BodyId)>;

/// The colour of a body by its type and state: static green, kinematic blue, dynamic orange when
/// awake and grey when asleep.
[[nodiscard]] Color bodyColor(const rigid2d::World& world, rigid2d::BodyId body);

/// One shape's geometry at a transform.
void drawShape(DebugDraw& draw, const rigid2d::ShapeGeometry& geometry, const Transform2f& xf, const Color& fill,
               const Color& outline);

/// `stepDt` is the length of the world's last step (s, 0 before the first): the solver's impulses
/// are per substep, so they become forces by dividing by the substep it gives.
void drawWorld(const rigid2d::World& world, DebugDraw& draw, const Rigid2dDrawOptions& options, float stepDt,
               const BodyColorFn& colorOf = {});

/// The Dear ImGui checkboxes for the options (and the force scale's slider).
void drawOptionsUi(Rigid2dDrawOptions& options);

} // namespace impetus::samples
