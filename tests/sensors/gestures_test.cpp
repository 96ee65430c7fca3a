// Multitouch tracking, gestures and the book's touch explosion (ch. 20), driven by touch
// sequences written out here: fingers on known paths, so the expected ids, gestures, scales and
// angles follow from the paths by hand.
#include <impetus/math/scalar.hpp>
#include <impetus/sensors/gestures.hpp>
#include <impetus/sensors/touch_explosion.hpp>
#include <impetus/sensors/touch_recording.hpp>
#include <impetus/sensors/touch_tracker.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace impetus::sensors {
namespace {

std::vector<GestureEvent> play(GestureRecognizer& g, TouchTracker& t, const std::vector<TouchFrame>& frames) {
  std::vector<GestureEvent> all;
  for (const TouchFrame& f : frames) {
    const auto touches = t.update(f.time, f.points);
    for (const GestureEvent& e : g.update(f.time, touches)) {
      all.push_back(e);
    }
  }
  return all;
}

int count(const std::vector<GestureEvent>& events, GestureKind kind, GesturePhase phase) {
  int n = 0;
  for (const GestureEvent& e : events) {
    n += e.kind == kind && e.phase == phase ? 1 : 0;
  }
  return n;
}

// ---- Tracker ------------------------------------------------------------------------------------

TEST(TouchTracker, ids_follow_fingers_across_frames_and_are_never_reused) {
  TouchTracker tracker(40.0);
  // Two fingers moving towards each other 10 px a frame; the controller lists them in varying order.
  std::vector<Vec2d> a{{100, 100}, {300, 100}};
  auto f = tracker.update(0.0, a);
  ASSERT_EQ(f.size(), 2U);
  EXPECT_EQ(f[0].id, 1);
  EXPECT_EQ(f[1].id, 2);
  EXPECT_EQ(f[0].phase, TouchPhase::began);
  for (int k = 1; k <= 8; ++k) {
    const double dx = 10.0 * k;
    std::vector<Vec2d> pts{{300 - dx, 100}, {100 + dx, 100}}; // reversed order
    f = tracker.update(0.01 * k, pts);
    ASSERT_EQ(f.size(), 2U);
    EXPECT_EQ(f[0].id, 1);
    EXPECT_DOUBLE_EQ(f[0].position.x, 100 + dx);
    EXPECT_EQ(f[1].id, 2);
    EXPECT_DOUBLE_EQ(f[1].position.x, 300 - dx);
    EXPECT_EQ(f[0].phase, TouchPhase::moved);
  }
  // Finger 2 lifts: reported ended once, then gone; a new finger gets id 3.
  std::vector<Vec2d> one{{180, 100}};
  f = tracker.update(0.1, one);
  ASSERT_EQ(f.size(), 2U);
  EXPECT_EQ(f[0].id, 1);
  EXPECT_EQ(f[0].phase, TouchPhase::stationary);
  EXPECT_EQ(f[1].id, 2);
  EXPECT_EQ(f[1].phase, TouchPhase::ended);
  std::vector<Vec2d> again{{180, 100}, {400, 300}};
  f = tracker.update(0.11, again);
  ASSERT_EQ(f.size(), 2U);
  EXPECT_EQ(f[1].id, 3);
  EXPECT_EQ(f[1].phase, TouchPhase::began);
  EXPECT_EQ(tracker.activeCount(), 2U);
  // A jump beyond maxJump is a different finger.
  std::vector<Vec2d> jumped{{180, 100}, {500, 300}};
  f = tracker.update(0.12, jumped);
  ASSERT_EQ(f.size(), 3U);
  EXPECT_EQ(f[1].phase, TouchPhase::ended);
  EXPECT_EQ(f[2].id, 4);
  expectErrorField([&] { (void)tracker.update(0.0, jumped); }, "time");
  expectErrorField([] { TouchTracker bad(0.0); }, "maxJump");
}

// ---- Gestures -----------------------------------------------------------------------------------

TEST(Gestures, quick_still_touch_is_a_tap_and_a_long_one_is_not) {
  TouchTracker tracker(50.0);
  GestureRecognizer gestures;
  const auto events = play(gestures, tracker, parseTouchRecording("0: 100,200; 0.05: 102,201; 0.1: 103,199; 0.15:"));
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].kind, GestureKind::tap);
  EXPECT_DOUBLE_EQ(events[0].position.x, 103.0);
  TouchTracker tracker2(50.0);
  GestureRecognizer gestures2;
  EXPECT_TRUE(play(gestures2, tracker2, parseTouchRecording("0: 100,200; 0.2: 100,200; 0.4: 100,200; 0.5:")).empty());
}

TEST(Gestures, drag_begins_past_the_slop_and_reports_its_translation) {
  TouchTracker tracker(50.0);
  GestureRecognizer gestures({0.3, 10.0, 0.05, 0.087});
  // 4 px a frame: within the 10 px slop for two frames, then a drag.
  std::vector<TouchFrame> frames;
  for (int k = 0; k <= 10; ++k) {
    frames.push_back({0.02 * k, {{100.0 + 4.0 * k, 50.0}}});
  }
  frames.push_back({0.22, {}});
  const auto events = play(gestures, tracker, frames);
  ASSERT_EQ(count(events, GestureKind::drag, GesturePhase::began), 1);
  EXPECT_EQ(events.front().kind, GestureKind::drag);
  EXPECT_DOUBLE_EQ(events.front().translation.x, 12.0); // the first frame past 10 px
  EXPECT_EQ(count(events, GestureKind::drag, GesturePhase::changed), 7);
  ASSERT_EQ(count(events, GestureKind::drag, GesturePhase::ended), 1);
  EXPECT_DOUBLE_EQ(events.back().translation.x, 40.0);
  EXPECT_EQ(count(events, GestureKind::tap, GesturePhase::ended), 0);
}

TEST(Gestures, pinch_scale_is_the_ratio_of_finger_distances) {
  TouchTracker tracker(50.0);
  GestureRecognizer gestures;
  // Fingers 100 px apart, spreading 4 px a frame (2 each way) to 200 px.
  std::vector<TouchFrame> frames;
  for (int k = 0; k <= 25; ++k) {
    const double half = 50.0 + 2.0 * k;
    frames.push_back({0.016 * k, {{400.0 - half, 300.0}, {400.0 + half, 300.0}}});
  }
  frames.push_back({0.4, {}});
  const auto events = play(gestures, tracker, frames);
  ASSERT_EQ(count(events, GestureKind::pinch, GesturePhase::began), 1);
  // It begins at the first frame past 5 %: 104 px is 4 %, 108 px is past.
  const auto began = std::find_if(events.begin(), events.end(), [](const GestureEvent& e) {
    return e.kind == GestureKind::pinch && e.phase == GesturePhase::began;
  });
  EXPECT_DOUBLE_EQ(began->scale, 1.08);
  const auto last = std::find_if(events.rbegin(), events.rend(), [](const GestureEvent& e) {
    return e.kind == GestureKind::pinch && e.phase == GesturePhase::changed;
  });
  EXPECT_DOUBLE_EQ(last->scale, 2.0);
  EXPECT_NEAR(last->position.x, 400.0, 1e-12);
  EXPECT_EQ(count(events, GestureKind::pinch, GesturePhase::ended), 1);
  EXPECT_EQ(count(events, GestureKind::rotate, GesturePhase::began), 0); // no turn
  EXPECT_EQ(count(events, GestureKind::tap, GesturePhase::ended), 0);
}

TEST(Gestures, rotation_is_summed_through_plus_minus_pi_without_a_jump) {
  TouchTracker tracker(80.0);
  GestureRecognizer gestures;
  // Two fingers 60 px either side of (300, 300), turning 270 degrees counter-clockwise in 3-degree
  // steps: the line between them passes the -x direction (atan2's +-pi) on the way.
  std::vector<TouchFrame> frames;
  for (int k = 0; k <= 90; ++k) {
    const double a = degToRad(3.0 * k);
    const Vec2d r{60.0 * std::cos(a), 60.0 * std::sin(a)};
    frames.push_back({0.01 * k, {Vec2d{300.0, 300.0} - r, Vec2d{300.0, 300.0} + r}});
  }
  const auto events = play(gestures, tracker, frames);
  ASSERT_EQ(count(events, GestureKind::rotate, GesturePhase::began), 1);
  const GestureEvent& last = events.back();
  EXPECT_EQ(last.kind, GestureKind::rotate);
  EXPECT_NEAR(last.rotation, degToRad(270.0), 1e-12);
  EXPECT_NEAR(last.scale, 1.0, 1e-12);
  EXPECT_EQ(count(events, GestureKind::pinch, GesturePhase::began), 0);
  // The threshold (5 degrees): the first frame past it is the 6-degree one.
  const auto began = std::find_if(events.begin(), events.end(), [](const GestureEvent& e) {
    return e.kind == GestureKind::rotate && e.phase == GesturePhase::began;
  });
  EXPECT_NEAR(began->rotation, degToRad(6.0), 1e-12);
}

TEST(Gestures, bad_settings_are_refused) {
  expectErrorField([] { GestureRecognizer g({0.0, 10.0, 0.05, 0.1}); }, "tapMaxDuration");
  expectErrorField([] { GestureRecognizer g({0.3, -1.0, 0.05, 0.1}); }, "slop");
  expectErrorField([] { GestureRecognizer g({0.3, 10.0, std::nan(""), 0.1}); }, "pinchThreshold");
}

// ---- Recording ----------------------------------------------------------------------------------

TEST(TouchRecording, parses_and_round_trips) {
  const auto frames = parseTouchRecording("0: 100,200\n0.1:; 0.5: 50.5,-3 1e2,7 ;");
  ASSERT_EQ(frames.size(), 3U);
  EXPECT_EQ(frames[1].points.size(), 0U);
  ASSERT_EQ(frames[2].points.size(), 2U);
  EXPECT_DOUBLE_EQ(frames[2].points[1].x, 100.0);
  const auto again = parseTouchRecording(formatTouchRecording(frames));
  ASSERT_EQ(again.size(), 3U);
  EXPECT_EQ(again[2].points[0], frames[2].points[0]);
  expectErrorField([] { (void)parseTouchRecording("0: 1,2; 0.5: 3"); }, "recording");
  expectErrorField([] { (void)parseTouchRecording("1: 1,2; 0.5: 3,4"); }, "recording");
  expectErrorField([] { (void)parseTouchRecording("x: 1,2"); }, "recording");
  expectErrorField([] { (void)parseTouchRecording("0 1,2"); }, "recording");
  expectErrorField([] { (void)parseTouchRecording("0: nan,2"); }, "recording");
}

// ---- The book's touch explosion -----------------------------------------------------------------

TEST(TouchExplosion, each_finger_that_touches_sets_off_one_burst_where_it_touched) {
  TouchExplosionSettings s;
  s.screen = {480.0, 20.0}; // 480 px tall, 20 px/m
  s.explosion.speed = 8.0;
  s.explosion.life = 1.0;
  TouchExplosions demo(s);
  // A tap, a held and dragged finger, then two fingers at once (the multitouch version).
  const auto frames = parseTouchRecording("0: 100,100; 0.05: 104,102; 0.1:;"
                                          "0.5: 200,400; 0.55: 210,400; 0.6: 220,400; 0.65:;"
                                          "0.9: 40,40 400,240; 0.95: 41,40 400,241; 1.0:");
  std::vector<std::size_t> began;
  for (const TouchFrame& f : frames) {
    began.push_back(demo.update(f.time, f.points));
  }
  EXPECT_EQ(began, (std::vector<std::size_t>{1, 0, 0, 1, 0, 0, 0, 2, 0, 0}));
  EXPECT_EQ(demo.burstCount(), 4U);
  // Screen (px, y down) to world (m, y up): (100, 100) -> (5, 19); the held finger does not go
  // off again where it was dragged to.
  const auto& bursts = demo.bursts();
  ASSERT_EQ(bursts.size(), 3U); // the first (life <= 1 s) has burnt out by t = 1.0
  EXPECT_EQ(bursts[0].explosion.origin(), (Vec2d{10.0, 4.0}));
  EXPECT_EQ(bursts[1].explosion.origin(), (Vec2d{2.0, 22.0}));
  EXPECT_EQ(bursts[2].explosion.origin(), (Vec2d{20.0, 12.0}));
  EXPECT_DOUBLE_EQ(bursts[1].start, 0.9);
  EXPECT_GT(demo.aliveParticles(1.0), 0U);
  // Replaying the recording gives the same particles (seeded per burst).
  TouchExplosions replay(s);
  for (const TouchFrame& f : frames) {
    replay.update(f.time, f.points);
  }
  EXPECT_EQ(replay.bursts()[2].explosion.particles()[7].velocity, bursts[2].explosion.particles()[7].velocity);
  // The book's first version: one finger only, so two at once set nothing off.
  s.multitouch = false;
  TouchExplosions single(s);
  for (const TouchFrame& f : frames) {
    single.update(f.time, f.points);
  }
  EXPECT_EQ(single.burstCount(), 2U);
}

TEST(TouchExplosion, new_explosion_settings_apply_to_the_bursts_that_follow) {
  TouchExplosions demo({});
  std::vector<Vec2d> one{{100.0, 100.0}};
  demo.update(0.0, one);
  ExplosionSettings slow = demo.settings().explosion;
  slow.speed = 1.0;
  slow.direction = 0.5;
  slow.spread = 0.1;
  demo.setExplosion(slow);
  demo.update(0.1, {});
  std::vector<Vec2d> two{{300.0, 100.0}};
  demo.update(0.2, two);
  ASSERT_EQ(demo.bursts().size(), 2U);
  for (const ExplosionParticle& p : demo.bursts()[1].explosion.particles()) {
    EXPECT_LE(length(p.velocity), 1.0 + 1e-12);
    EXPECT_NEAR(std::atan2(p.velocity.y, p.velocity.x), 0.5, 0.1 + 1e-12);
  }
  slow.life = 0.0;
  expectErrorField([&] { demo.setExplosion(slow); }, "life");
}

TEST(TouchExplosion, bad_settings_are_refused) {
  TouchExplosionSettings s;
  s.screen.pixelsPerMetre = 0.0;
  expectErrorField([&] { TouchExplosions e(s); }, "pixelsPerMetre");
  s = {};
  s.explosion.life = -1.0;
  expectErrorField([&] { TouchExplosions e(s); }, "life");
  s = {};
  s.maxExplosions = 0;
  expectErrorField([&] { TouchExplosions e(s); }, "maxExplosions");
}

} // namespace
} // namespace impetus::sensors
