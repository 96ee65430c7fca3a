#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/sensors/gestures.hpp>

#include <cmath>

namespace impetus::sensors {
namespace {

const TrackedTouch* findTouch(std::span<const TrackedTouch> touches, int id) noexcept {
  for (const TrackedTouch& t : touches) {
    if (t.id == id) {
      return &t;
    }
  }
  return nullptr;
}

/// a - b folded into (-pi, pi]: the smallest turn from b to a.
double angleDifference(double a, double b) noexcept {
  double d = std::remainder(a - b, 2.0 * pi<double>);
  if (d <= -pi<double>) {
    d += 2.0 * pi<double>;
  }
  return d;
}

} // namespace

GestureRecognizer::GestureRecognizer(const GestureSettings& settings) : settings_(settings) {
  requirePositive(settings.tapMaxDuration, "tapMaxDuration");
  requireNonNegative(settings.slop, "slop");
  requireNonNegative(settings.pinchThreshold, "pinchThreshold");
  requireNonNegative(settings.rotateThreshold, "rotateThreshold");
}

std::vector<GestureEvent> GestureRecognizer::update(double time, std::span<const TrackedTouch> touches) {
  requireFinite(time, "time");
  std::vector<GestureEvent> events;
  std::vector<const TrackedTouch*> active;
  for (const TrackedTouch& t : touches) {
    if (t.phase != TouchPhase::ended) {
      active.push_back(&t);
    }
  }

  // ---- One finger: tap or drag.
  if (single_) {
    const TrackedTouch* t = findTouch(touches, *single_);
    if (t == nullptr) {
      single_.reset(); // the caller reset its tracker: forget the finger without an event
      dragging_ = false;
    } else if (t->phase == TouchPhase::ended) {
      GestureEvent e;
      e.time = time;
      e.position = t->position;
      e.translation = t->position - t->start;
      if (dragging_) {
        e.kind = GestureKind::drag;
        e.phase = GesturePhase::ended;
        events.push_back(e);
      } else if (!multi_ && !wandered_ && time - t->startTime <= settings_.tapMaxDuration) {
        e.kind = GestureKind::tap;
        e.phase = GesturePhase::ended;
        events.push_back(e);
      }
      single_.reset();
      dragging_ = false;
    } else {
      wandered_ = wandered_ || distance(t->position, t->start) > settings_.slop;
      if (!multi_ && wandered_ && (!dragging_ || t->phase == TouchPhase::moved)) {
        GestureEvent e;
        e.kind = GestureKind::drag;
        e.phase = dragging_ ? GesturePhase::changed : GesturePhase::began;
        e.time = time;
        e.position = t->position;
        e.translation = t->position - t->start;
        events.push_back(e);
        dragging_ = true;
      }
    }
  }
  if (active.size() >= 2) {
    multi_ = true;
    if (dragging_ && single_) {
      const TrackedTouch* t = findTouch(touches, *single_);
      GestureEvent e;
      e.kind = GestureKind::drag;
      e.phase = GesturePhase::ended;
      e.time = time;
      e.position = t->position;
      e.translation = t->position - t->start;
      events.push_back(e);
      dragging_ = false;
    }
  }
  if (!single_ && !multi_ && active.size() == 1) {
    single_ = active.front()->id;
    wandered_ = distance(active.front()->position, active.front()->start) > settings_.slop;
  }

  // ---- Two fingers: pinch and rotate.
  if (pair_) {
    const TrackedTouch* a = findTouch(touches, pair_->first);
    const TrackedTouch* b = findTouch(touches, pair_->second);
    const bool over = a == nullptr || b == nullptr || a->phase == TouchPhase::ended || b->phase == TouchPhase::ended;
    const Vec2d pa = a != nullptr ? a->position : Vec2d{};
    const Vec2d pb = b != nullptr ? b->position : Vec2d{};
    GestureEvent e;
    e.time = time;
    e.position = (pa + pb) * 0.5;
    e.translation = e.position - pair_->startMidpoint;
    if (!over) {
      const Vec2d d = pb - pa;
      const double angle = std::atan2(d.y, d.x);
      pair_->rotation += angleDifference(angle, pair_->lastAngle);
      pair_->lastAngle = angle;
      e.scale = length(d) / pair_->startDistance;
    } else {
      e.scale = a != nullptr && b != nullptr ? distance(pa, pb) / pair_->startDistance : 1.0;
    }
    e.rotation = pair_->rotation;
    if (pair_->pinching || (!over && std::abs(e.scale - 1.0) > settings_.pinchThreshold)) {
      GestureEvent p = e;
      p.kind = GestureKind::pinch;
      p.phase = over ? GesturePhase::ended : (pair_->pinching ? GesturePhase::changed : GesturePhase::began);
      events.push_back(p);
      pair_->pinching = true;
    }
    if (pair_->rotating || (!over && std::abs(pair_->rotation) > settings_.rotateThreshold)) {
      GestureEvent r = e;
      r.kind = GestureKind::rotate;
      r.phase = over ? GesturePhase::ended : (pair_->rotating ? GesturePhase::changed : GesturePhase::began);
      events.push_back(r);
      pair_->rotating = true;
    }
    if (over) {
      pair_.reset();
    }
  }
  if (!pair_ && active.size() >= 2) {
    const Vec2d d = active[1]->position - active[0]->position;
    const double d0 = length(d);
    if (d0 > 0.0) { // two fingers on one point have no direction yet: wait for the next frame
      Pair p;
      p.first = active[0]->id;
      p.second = active[1]->id;
      p.startDistance = d0;
      p.lastAngle = std::atan2(d.y, d.x);
      p.startMidpoint = (active[0]->position + active[1]->position) * 0.5;
      pair_ = p;
    }
  }
  if (active.empty()) {
    multi_ = false;
    single_.reset();
    dragging_ = false;
    wandered_ = false;
  }
  return events;
}

const char* gestureKindName(GestureKind kind) noexcept {
  switch (kind) {
  case GestureKind::tap:
    return "tap";
  case GestureKind::drag:
    return "drag";
  case GestureKind::pinch:
    return "pinch";
  case GestureKind::rotate:
    return "rotate";
  }
  return "?";
}

const char* gesturePhaseName(GesturePhase phase) noexcept {
  switch (phase) {
  case GesturePhase::began:
    return "began";
  case GesturePhase::changed:
    return "changed";
  case GesturePhase::ended:
    return "ended";
  }
  return "?";
}

} // namespace impetus::sensors
