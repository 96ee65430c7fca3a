// The input validation audit of the display layer (docs/reliability.md, "Input validation"):
// stereo parallax, stereo cameras and frustums, view matrices and anaglyphs refuse NaN,
// infinity, negative or zero sizes, planes out of order, degenerate directions and values
// outside their enumerations with an impetus::Error naming the field and showing the value.
#include "support/validation_table.hpp"

#include <impetus/display/anaglyph.hpp>
#include <impetus/display/stereo.hpp>
#include <impetus/display/stereo_frustum.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace impetus::display {
namespace {

using impetus::testing::expectAccepted;
using impetus::testing::expectRejected;
using impetus::testing::infd;
using impetus::testing::nand;

TEST(DisplayValidation, parallax_and_fields_of_view) {
  expectRejected({
      {"interaxial", "-0.1", [] { (void)screenParallax(-0.1, 10.0, 20.0); }},
      {"interaxial", "nan", [] { (void)screenParallax(nand, 10.0, 20.0); }},
      {"convergence", "0", [] { (void)screenParallax(0.065, 0.0, 20.0); }},
      {"depth", "0", [] { (void)screenParallax(0.065, 10.0, 0.0); }},
      {"depth", "inf", [] { (void)screenParallax(0.065, 10.0, infd); }},
      {"verticalFov", "0", [] { (void)horizontalFov(0.0, 1.5); }},
      {"verticalFov", "3.141592653589793", [] { (void)horizontalFov(3.141592653589793, 1.5); }},
      {"verticalFov", "nan", [] { (void)horizontalFov(nand, 1.5); }},
      {"aspect", "0", [] { (void)horizontalFov(1.0, 0.0); }},
      {"aspect", "-inf", [] { (void)horizontalFov(1.0, -infd); }},
      {"convergence", "-1", [] { (void)convergencePlaneWidth(-1.0, 1.0); }},
      {"horizontalFov", "4", [] { (void)convergencePlaneWidth(10.0, 4.0); }},
      {"separation", "-0.01", [] { (void)interaxialFromSeparation(-0.01, 10.0, 1.0); }},
      {"interaxial", "inf", [] { (void)separationFromInteraxial(infd, 10.0, 1.0); }},
      {"screenParallax", "nan", [] { (void)perceivedDistance(nand, 2.0); }},
      {"viewingDistance", "0", [] { (void)perceivedDistance(0.01, 0.0); }},
      {"eyeSeparation", "-0.065", [] { (void)perceivedDistance(0.01, 2.0, -0.065); }},
      {"depth", "nan", [] { (void)depthZone(nand, 10.0); }},
      {"convergence", "-1", [] { (void)depthZone(1.0, -1.0); }},
  });
  expectAccepted({
      {"zero interaxial (mono)", [] { (void)screenParallax(0.0, 10.0, 20.0); }},
      {"zero separation", [] { (void)interaxialFromSeparation(0.0, 10.0, 1.0); }},
      {"parallax at the eye separation (infinity)", [] { EXPECT_FALSE(perceivedDistance(0.065, 2.0).has_value()); }},
      {"negative parallax (in front)", [] { (void)perceivedDistance(-0.1, 2.0); }},
  });
}

TEST(DisplayValidation, stereo_cameras_and_frustums) {
  const auto camera = [](auto change) {
    return [change] {
      StereoCamera c;
      change(c);
      (void)offAxisFrustum(c, Eye::left);
    };
  };
  expectRejected({
      {"interaxial", "-0.065", camera([](StereoCamera& c) { c.interaxial = -0.065; })},
      {"nearPlane", "0", camera([](StereoCamera& c) { c.nearPlane = 0.0; })},
      {"nearPlane", "nan", camera([](StereoCamera& c) { c.nearPlane = nand; })},
      {"farPlane", "0.05", camera([](StereoCamera& c) { c.farPlane = 0.05; })},
      {"farPlane", "inf", camera([](StereoCamera& c) { c.farPlane = infd; })},
      {"convergence", "0.1", camera([](StereoCamera& c) { c.convergence = 0.1; })},
      {"convergence", "nan", camera([](StereoCamera& c) { c.convergence = nand; })},
      {"verticalFov", "3.2", camera([](StereoCamera& c) { c.verticalFov = 3.2; })},
      {"verticalFov", "-1", camera([](StereoCamera& c) { c.verticalFov = -1.0; })},
      {"aspect", "0", camera([](StereoCamera& c) { c.aspect = 0.0; })},
      {"interaxial", "nan", [] { (void)eyeOffset(StereoCamera{nand}, Eye::right); }},
      {"convergence", "inf",
       [] {
         (void)toeInAngle(StereoCamera{0.065, infd});
       }},
      {"nearPlane", "0",
       [] {
         (void)frustumMatrix({-1.0, 1.0, -1.0, 1.0, 0.0, 10.0});
       }},
      {"farPlane", "0.1",
       [] {
         (void)frustumMatrix({-1.0, 1.0, -1.0, 1.0, 0.1, 0.1});
       }},
      {"left", "nan",
       [] {
         (void)frustumMatrix({nand, 1.0, -1.0, 1.0, 0.1, 10.0});
       }},
      {"top", "inf",
       [] {
         (void)frustumMatrix({-1.0, 1.0, -1.0, infd, 0.1, 10.0});
       }},
      {"right", "-1",
       [] {
         (void)frustumMatrix({1.0, -1.0, -1.0, 1.0, 0.1, 10.0});
       }},
      {"top", "-1",
       [] {
         (void)frustumMatrix({-1.0, 1.0, 1.0, -1.0, 0.1, 10.0});
       }},
  });
  expectAccepted({
      {"zero interaxial", camera([](StereoCamera& c) { c.interaxial = 0.0; })},
      {"a very wide field of view", camera([](StereoCamera& c) { c.verticalFov = 3.1; })},
  });
}

TEST(DisplayValidation, view_matrices_and_poses) {
  const auto pose = [](auto change) {
    return [change] {
      CameraPose p;
      change(p);
      (void)offAxisEye(p, StereoCamera{}, Eye::left);
    };
  };
  expectRejected({
      {"eye.x", "nan",
       [] {
         (void)lookAt({nand, 0.0, 0.0}, {0.0, 0.0, -1.0}, {0.0, 1.0, 0.0});
       }},
      {"target.z", "-inf",
       [] {
         (void)lookAt({}, {0.0, 0.0, -infd}, {0.0, 1.0, 0.0});
       }},
      {"up.y", "inf",
       [] {
         (void)lookAt({}, {0.0, 0.0, -1.0}, {0.0, infd, 0.0});
       }},
      // Degenerate directions show the length at fault: 0.
      {"target", "0",
       [] {
         (void)lookAt({1.0, 2.0, 3.0}, {1.0, 2.0, 3.0}, {0.0, 1.0, 0.0});
       }},
      {"up", "0",
       [] {
         (void)lookAt({}, {0.0, 1.0, 0.0}, {0.0, 2.0, 0.0});
       }},
      {"up", "0",
       [] {
         (void)lookAt({}, {0.0, 0.0, -1.0}, {});
       }},
      {"position.y", "nan", pose([](CameraPose& p) { p.position.y = nand; })},
      {"forward.x", "inf", pose([](CameraPose& p) { p.forward.x = infd; })},
      {"forward", "0", pose([](CameraPose& p) { p.forward = {}; })},
      {"up", "0", pose([](CameraPose& p) {
         p.up = {0.0, 0.0, -3.0};
       })},
      {"up", "0",
       [] {
         (void)toeInView({{}, {0.0, 0.0, -1.0}, {}}, StereoCamera{}, Eye::right);
       }},
      {"convergence", "0.01",
       [] {
         (void)toeInEye(CameraPose{}, StereoCamera{0.065, 0.01}, Eye::left);
       }},
  });
  expectAccepted({
      {"forward need not be unit", pose([](CameraPose& p) {
         p.forward = {0.0, 0.0, -250.0};
       })},
      {"up need not be perpendicular", pose([](CameraPose& p) {
         p.up = {0.0, 1.0, -1.0};
       })},
  });
}

TEST(DisplayValidation, anaglyphs) {
  const std::vector<Rgb> two{{0.5, 0.5, 0.5}, {0.2, 0.4, 0.6}};
  const std::vector<Rgb> one{{0.5, 0.5, 0.5}};
  expectRejected({
      {"left", "1.2",
       [] {
         (void)anaglyph({1.2, 0.0, 0.0}, {}, AnaglyphMode::gray);
       }},
      {"left", "-0.1",
       [] {
         (void)anaglyph({0.0, -0.1, 0.0}, {}, AnaglyphMode::color);
       }},
      {"right", "nan",
       [] {
         (void)anaglyph({}, {0.0, 0.0, nand}, AnaglyphMode::dubois);
       }},
      {"right", "inf",
       [] {
         (void)anaglyph({}, {infd, 0.0, 0.0}, AnaglyphMode::trueAnaglyph);
       }},
      {"mode", "99", [] { (void)anaglyph({}, {}, static_cast<AnaglyphMode>(99)); }},
      {"mode", "-1", [] { (void)anaglyph({}, {}, static_cast<AnaglyphMode>(-1)); }},
      {"encoding", "7", [] { (void)anaglyph({}, {}, AnaglyphMode::dubois, static_cast<AnaglyphEncoding>(7)); }},
      {"right", "1",
       [&] {
         std::vector<Rgb> out(2);
         anaglyphImage(two, one, out, AnaglyphMode::gray);
       }},
      {"out", "1",
       [&] {
         std::vector<Rgb> out(1);
         anaglyphImage(two, two, out, AnaglyphMode::gray);
       }},
      {"left[1]", "2",
       [&] {
         std::vector<Rgb> left = two;
         left[1].g = 2.0;
         std::vector<Rgb> out(2);
         anaglyphImage(left, two, out, AnaglyphMode::halfColor);
       }},
      {"right[0]", "nan",
       [&] {
         std::vector<Rgb> right = two;
         right[0].b = nand;
         std::vector<Rgb> out(2);
         anaglyphImage(two, right, out, AnaglyphMode::optimized);
       }},
      {"mode", "'purple'", [] { (void)anaglyphModeFromString("purple"); }},
  });
  expectAccepted({
      {"black and white",
       [] {
         (void)anaglyph({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, AnaglyphMode::dubois);
       }},
      {"linear dubois",
       [] {
         (void)anaglyph({1.0, 0.0, 0.0}, {}, AnaglyphMode::dubois, AnaglyphEncoding::linear);
       }},
      {"an empty image", [] { anaglyphImage({}, {}, {}, AnaglyphMode::color); }},
  });
}

} // namespace
} // namespace impetus::display
