// Draws a rigid2d::World through its public inspection API: shapes coloured by body type and
// sleeping state, centres of mass, contact points and normals, joints and bounding boxes, each
// switched on or off by Rigid2dDrawOptions.
#pragma once

#include "contact_tracker.hpp"
#include "draw.hpp"

#include <impetus/rigid2d/world.hpp>

#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace impetus::samples {

struct Rigid2dDrawOptions {
  bool shapes = true;
  bool joints = true;
  bool centersOfMass = false;
  bool contacts = false; ///< points and normals
  bool aabbs = false;    ///< each shape's tight bounding box
  bool transforms = false;
};

/// What the drawing needs to know about a joint that the world does not say: its local anchors
/// (the world lists neither its joints nor their anchors; samples record them on creation).
struct JointDrawInfo {
  rigid2d::JointId id;
  Vec2f localAnchorA; ///< m, body A's frame
  Vec2f localAnchorB; ///< m, body B's frame
};

/// A colour chosen by the sample for some bodies (a bullet, the player's craft); none: by type.
using BodyColorFn = std::function<std::optional<Color>(rigid2d::BodyId)>;

/// The colour of a body by its type and state: static green, kinematic blue, dynamic orange when
/// awake and grey when asleep.
[[nodiscard]] Color bodyColor(const rigid2d::World& world, rigid2d::BodyId body);

/// One shape's geometry at a transform.
void drawShape(DebugDraw& draw, const rigid2d::ShapeGeometry& geometry, const Transform2f& xf, const Color& fill,
               const Color& outline);

void drawWorld(const rigid2d::World& world, DebugDraw& draw, const Rigid2dDrawOptions& options,
               std::span<const JointDrawInfo> joints, const ContactTracker& contacts, const BodyColorFn& colorOf = {});

/// The Dear ImGui checkboxes for the options.
void drawOptionsUi(Rigid2dDrawOptions& options);

} // namespace impetus::samples
