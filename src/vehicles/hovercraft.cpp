// The book's ch. 9 hovercraft loads (CalcLoads), on a rigid2d body.
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/vehicles/hovercraft.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::vehicles {

Hovercraft::Hovercraft(rigid2d::World& world, const HovercraftParams& params, const Vec2f& position, float angle,
                       float initialThrust)
    : world_(&world), params_(params) {
  requirePositive(params.mass, "mass");
  requirePositive(params.inertia, "inertia");
  requirePositive(params.length, "length");
  requirePositive(params.width, "width");
  requirePositive(params.height, "height");
  requireNonNegative(params.steeringForce, "steeringForce");
  requireNonNegative(params.dragCoefficient, "dragCoefficient");
  requireNonNegative(params.airDensity, "airDensity");
  requireNonNegative(params.thrustRate, "thrustRate");
  requireFinite(params.minThrust, "minThrust");
  requireFinite(params.maxThrust, "maxThrust");
  if (params.minThrust > params.maxThrust) {
    throwInvalid("minThrust", params.minThrust, "above maxThrust");
  }
  if (!(params.restitution >= 0.0f && params.restitution <= 1.0f)) {
    throwInvalid("restitution", params.restitution, "must be in [0, 1]");
  }
  requireFinite(params.centreOfDrag, "centreOfDrag");
  requireFinite(params.portThrusterPoint, "portThrusterPoint");
  requireFinite(params.starboardThrusterPoint, "starboardThrusterPoint");
  requireFinite(initialThrust, "initialThrust"); // before the body exists, under its own name
  rigid2d::BodyDef def;
  def.type = rigid2d::BodyType::dynamicBody;
  def.position = position;
  def.angle = angle;
  def.enableSleep = false; // a craft under way never rests
  body_ = world.createBody(def);
  rigid2d::ShapeDef shape;
  shape.density = params.mass / (params.length * params.width);
  shape.friction = 0.0f; // the book has no friction
  shape.restitution = params.restitution;
  world.createShape(body_, shape, rigid2d::makeBox(0.5f * params.length, 0.5f * params.width));
  world.setMassData(body_, {params.mass, {}, params.inertia});
  setThrust(initialThrust);
}

void Hovercraft::setThrust(float thrust) {
  requireFinite(thrust, "thrust");
  thrust_ = std::clamp(thrust, params_.minThrust, params_.maxThrust);
}

HovercraftLoads Hovercraft::applyLoads(const HovercraftControls& controls, float dt) {
  requirePositive(dt, "dt");
  thrust_ = std::clamp(thrust_ + static_cast<float>(controls.throttle) * params_.thrustRate * dt, params_.minThrust,
                       params_.maxThrust);
  const Transform2f xf = world_->transform(body_);
  const Vec2f velocity = world_->linearVelocity(body_);
  const float spin = world_->angularVelocity(body_);
  Vec2f force{thrust_, 0.0f}; // body frame: the propeller pushes along +x through the CG
  float moment = 0.0f;
  // Drag at the centre of drag, from that point's velocity (body frame): v_CD = v + w x r.
  const Vec2f r = params_.centreOfDrag;
  const Vec2f pointVelocity = inverseRotate(xf.q, velocity) + Vec2f{-spin * r.y, spin * r.x};
  const float speed = length(pointVelocity);
  Vec2f drag;
  if (speed > 1e-6f) {
    const float area = 0.5f * (params_.length + params_.width) * params_.height;
    drag = pointVelocity * (-0.5f * params_.airDensity * speed * area * params_.dragCoefficient);
    force += drag;
    moment += cross(r, drag);
  }
  // Bow thrusters push toward the other side: port's to starboard (-y), starboard's to port.
  if (controls.portThruster) {
    const Vec2f f{0.0f, -params_.steeringForce};
    force += f;
    moment += cross(params_.portThrusterPoint, f);
  }
  if (controls.starboardThruster) {
    const Vec2f f{0.0f, params_.steeringForce};
    force += f;
    moment += cross(params_.starboardThrusterPoint, f);
  }
  const Vec2f worldForce = rotate(xf.q, force);
  world_->applyForce(body_, worldForce, world_->worldCenterOfMass(body_));
  world_->applyTorque(body_, moment);
  return {worldForce, moment, rotate(xf.q, drag)};
}

std::array<Vec2f, 5> Hovercraft::outline() const noexcept {
  const float hl = 0.5f * params_.length;
  const float hw = 0.5f * params_.width;
  return {Vec2f{hl, hw}, Vec2f{-hl, hw}, Vec2f{-hl, -hw}, Vec2f{hl, -hw}, Vec2f{0.75f * params_.length, 0.0f}};
}

} // namespace impetus::vehicles
