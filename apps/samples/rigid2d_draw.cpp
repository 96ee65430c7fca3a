#include "rigid2d_draw.hpp"

#include <imgui.h>

#include <array>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;

AABB shapeBox(const ShapeGeometry& g, const Transform2f& xf) {
  return std::visit([&](const auto& shape) { return computeAABB(shape, xf); }, g);
}

void drawJoint(const World& world, DebugDraw& draw, const JointDrawInfo& info) {
  if (!world.isValid(info.id)) {
    return; // destroyed (or broken and removed) since it was recorded
  }
  const BodyId a = world.jointBodyA(info.id);
  const BodyId b = world.jointBodyB(info.id);
  const Transform2f xfA = world.transform(a);
  const Transform2f xfB = world.transform(b);
  const Vec2f pA = transformPoint(xfA, info.localAnchorA);
  const Vec2f pB = transformPoint(xfB, info.localAnchorB);
  const Color c = palette::joint;
  switch (world.jointType(info.id)) {
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

void drawWorld(const World& world, DebugDraw& draw, const Rigid2dDrawOptions& options,
               std::span<const JointDrawInfo> joints, const ContactTracker& contacts, const BodyColorFn& colorOf) {
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
    for (const JointDrawInfo& j : joints) {
      drawJoint(world, draw, j);
    }
  }
  if (options.contacts) {
    const float normalLength = 16.0f * draw.pixelSize();
    contacts.forEach(world, [&](const ContactTracker::Pair& pair) {
      const Manifold m = currentManifold(world, pair.shapeA, pair.shapeB);
      for (int i = 0; i < m.pointCount; ++i) {
        const ManifoldPoint& p = m.points[static_cast<std::size_t>(i)];
        draw.point(p.point, 5.0f, palette::contact);
        draw.segment(p.point, p.point + m.normal * normalLength, palette::normal);
      }
    });
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
}

} // namespace impetus::samples
