#include "rigid2d_draw.hpp"

#include "ui.hpp"

#include <imgui.h>

#include <array>
#include <span>
#include <vector>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;

AABB shapeBox(const ShapeGeometry& g, const Transform2f& xf) {
  return std::visit([&](const auto& shape) { return computeAABB(shape, xf); }, g);
}

void drawJoint(const World& world, DebugDraw& draw, JointId joint) {
  const BodyId a = world.jointBodyA(joint);
  const BodyId b = world.jointBodyB(joint);
  const Transform2f xfA = world.transform(a);
  const Transform2f xfB = world.transform(b);
  const Vec2f pA = world.jointAnchorA(joint);
  const Vec2f pB = world.jointAnchorB(joint);
  const Color c = palette::joint;
  switch (world.jointType(joint)) {
  case JointType::distance:
    draw.segment(pA, pB, c);
    draw.point(pA, 5.0f, c);
    draw.point(pB, 5.0f, c);
    break;
  case JointType::mouse:
    draw.point(pB, 6.0f, c);
    break;
  case JointType::motor:
    // Drives B's origin toward an offset from A's: the line between them, unless A is static
    // (whose origin is usually far away).
    if (world.bodyType(a) != BodyType::staticBody) {
      draw.segment(xfA.p, xfB.p, c.withAlpha(0.5f));
    }
    draw.point(xfB.p, 5.0f, c);
    break;
  case JointType::filter:
    // No constraint: a faint line between the two origins says which bodies ignore each other.
    draw.segment(xfA.p, xfB.p, c.withAlpha(0.25f));
    break;
  default:
    // As Box2D draws them: body A's origin to its anchor, the anchors, B's anchor to its origin
    // (not from a static body's origin: the ground's is usually far away).
    if (world.bodyType(a) != BodyType::staticBody) {
      draw.segment(xfA.p, pA, c.withAlpha(0.6f));
    }
    draw.segment(pA, pB, c);
    if (world.bodyType(b) != BodyType::staticBody) {
      draw.segment(xfB.p, pB, c.withAlpha(0.6f));
    }
    draw.point(pA, 5.0f, c);
    break;
  }
}

/// The length of one solver substep of a step of `stepDt` seconds: the soft step solves its
/// contacts `substeps` times a step, the book's response once.
float substepOf(const World& world, float stepDt) {
  const WorldDef& def = world.settings();
  return def.solver == SolverKind::softStep ? stepDt / static_cast<float>(def.substeps) : stepDt;
}

void drawContacts(const World& world, DebugDraw& draw, const Rigid2dDrawOptions& options, float stepDt) {
  std::vector<ContactData> contacts;
  world.contacts(contacts);
  const float normalLength = 16.0f * draw.pixelSize();
  const float substep = substepOf(world, stepDt);
  // Impulse (N s) over a substep is the force (N); the scale turns newtons into metres drawn.
  const float metresPerImpulse = substep > 0.0f ? 1.0f / (substep * options.forceScale) : 0.0f;
  for (const ContactData& c : contacts) {
    const Manifold& m = c.manifold;
    const Vec2f tangent{m.normal.y, -m.normal.x}; // the solver's friction direction
    for (int i = 0; i < m.pointCount; ++i) {
      const ManifoldPoint& p = m.points[static_cast<std::size_t>(i)];
      if (options.contacts) {
        draw.point(p.point, 5.0f, palette::contact);
        draw.segment(p.point, p.point + m.normal * normalLength, palette::normal);
      }
      if (options.contactForces && p.normalImpulse != 0.0f) {
        draw.segment(p.point, p.point + m.normal * (p.normalImpulse * metresPerImpulse), palette::contactForce);
      }
      if (options.frictionForces && p.tangentImpulse != 0.0f) {
        draw.segment(p.point, p.point + tangent * (p.tangentImpulse * metresPerImpulse), palette::frictionForce);
      }
    }
  }
}

} // namespace

Color bodyColor(const World& world, BodyId body) {
  switch (world.bodyType(body)) {
  case BodyType::staticBody:
    return palette::staticBody;
  case BodyType::kinematicBody:
    return palette::kinematic;
  case BodyType::dynamicBody:
    break;
  }
  return world.isAwake(body) ? palette::awake : palette::asleep;
}

void drawShape(DebugDraw& draw, const ShapeGeometry& geometry, const Transform2f& xf, const Color& fill,
               const Color& outline) {
  if (const auto* c = std::get_if<Circle>(&geometry)) {
    draw.solidCircle(transformPoint(xf, c->center), c->radius, xf.q.angle(), fill, outline);
  } else if (const auto* cap = std::get_if<Capsule>(&geometry)) {
    draw.solidCapsule(transformPoint(xf, cap->center1), transformPoint(xf, cap->center2), cap->radius, fill, outline);
  } else if (const auto* poly = std::get_if<Polygon>(&geometry)) {
    std::array<Vec2f, maxPolygonVertices> points{};
    for (int i = 0; i < poly->count; ++i) {
      points[static_cast<std::size_t>(i)] = transformPoint(xf, poly->vertices[static_cast<std::size_t>(i)]);
    }
    draw.roundedPolygon(std::span(points.data(), static_cast<std::size_t>(poly->count)), poly->radius, fill, outline);
  } else if (const auto* seg = std::get_if<Segment>(&geometry)) {
    draw.segment(transformPoint(xf, seg->point1), transformPoint(xf, seg->point2), outline);
  } else if (const auto* chain = std::get_if<ChainSegment>(&geometry)) {
    const Vec2f p1 = transformPoint(xf, chain->segment.point1);
    const Vec2f p2 = transformPoint(xf, chain->segment.point2);
    draw.segment(p1, p2, outline);
    // The free side: a short tick along the right-hand normal (chain.hpp).
    const Vec2f mid = (p1 + p2) * 0.5f;
    const Vec2f n = normalize(Vec2f{p2.y - p1.y, p1.x - p2.x});
    draw.segment(mid, mid + n * (6.0f * draw.pixelSize()), outline.withAlpha(0.5f));
  }
}

void drawWorld(const World& world, DebugDraw& draw, const Rigid2dDrawOptions& options, float stepDt,
               const BodyColorFn& colorOf) {
  std::vector<BodyId> bodies;
  std::vector<ShapeId> shapes;
  world.bodyIds(bodies);
  for (const BodyId body : bodies) {
    const Transform2f xf = world.transform(body);
    std::optional<Color> chosen;
    if (colorOf) {
      chosen = colorOf(body);
    }
    const Color base = chosen.value_or(bodyColor(world, body));
    world.bodyShapes(body, shapes);
    for (const ShapeId shape : shapes) {
      const ShapeGeometry geometry = world.shapeGeometry(shape);
      if (options.shapes) {
        const bool sensor = world.isSensor(shape);
        const Color outline = sensor ? palette::sensor : base;
        const Color fill = sensor ? palette::sensor.withAlpha(0.12f) : base.scaled(0.5f).withAlpha(0.6f);
        drawShape(draw, geometry, xf, fill, outline);
      }
      if (options.aabbs) {
        const AABB box = shapeBox(geometry, xf);
        draw.box(box.lower, box.upper, palette::aabb);
      }
    }
    if (options.transforms) {
      draw.transform(xf);
    }
    if (options.centersOfMass && world.bodyType(body) == BodyType::dynamicBody) {
      draw.point(world.worldCenterOfMass(body), 4.0f, palette::centerOfMass);
    }
  }
  if (options.joints) {
    std::vector<JointId> joints;
    world.jointIds(joints);
    for (const JointId joint : joints) {
      drawJoint(world, draw, joint);
    }
  }
  if (options.contacts || options.contactForces || options.frictionForces) {
    drawContacts(world, draw, options, stepDt);
  }
}

void drawOptionsUi(Rigid2dDrawOptions& options) {
  ImGui::Checkbox("shapes", &options.shapes);
  ImGui::SameLine();
  ImGui::Checkbox("joints", &options.joints);
  ImGui::SameLine();
  ImGui::Checkbox("AABBs", &options.aabbs);
  ImGui::Checkbox("contacts", &options.contacts);
  ImGui::SameLine();
  ImGui::Checkbox("centres of mass", &options.centersOfMass);
  ImGui::Checkbox("body frames", &options.transforms);
  ImGui::Checkbox("contact forces", &options.contactForces);
  ImGui::SameLine();
  ImGui::Checkbox("friction", &options.frictionForces);
  if (options.contactForces || options.frictionForces) {
    slider("force scale", &options.forceScale, 1.0f, 1.0e5f, "%.0f N per m", ImGuiSliderFlags_Logarithmic);
  }
}

} // namespace impetus::samples
