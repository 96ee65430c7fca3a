// Book/Stereo frustums (ch. 24): the off-axis stereo pair, seen from above, against the toe-in
// method. Two cameras e apart look straight ahead, each with the asymmetric frustum of
// display/stereo_frustum.hpp; the two frustums share one rectangle on the convergence plane (the
// screen) at distance C. A probe point moves in depth from C/2 to 4 C: its lines of sight from the
// two eyes cross the convergence plane e (1 - C/Z) apart (red: left eye, cyan: right), negative
// (crossed, in front of the screen) nearer than C and tending to e at infinity. With "toe-in" the
// cameras turn in by atan((e/2)/C) and keep the symmetric frustum: the inset below shows what each
// eye sees of a wall of points at 2 C through the library's projection and view matrices - the
// off-axis images differ only horizontally, the toe-in ones are keystoned (vertical parallax).
// Plot: P/e against depth with the book's budget ([C/2, 100 C]; the action in [C, 10 C]).
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/display/stereo.hpp>
#include <impetus/display/stereo_frustum.hpp>
#include <impetus/math/scalar.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace impetus::samples {
namespace {

using namespace impetus::display;

const Color leftColor{1.0f, 0.25f, 0.25f, 1.0f};
const Color rightColor{0.2f, 0.9f, 0.95f, 1.0f};

/// Top view: x right, depth (-z of the camera) up the page.
Vec2f top(double x, double depth) { return {static_cast<float>(x), static_cast<float>(depth)}; }

class StereoFrustums final : public Sample {
public:
  void setup() override {
    t_ = 0.0;
    updateCurve();
  }

  void step(float dt) override {
    t_ += dt;
    // The probe goes from C/2 to 4 C and back every 8 s (geometric, so each octave takes as long).
    const double phase = 0.5 - 0.5 * std::cos(2.0 * pi<double> * t_ / 8.0);
    probeDepth_ = camera().convergence * 0.5 * std::pow(8.0, phase);
    parallax_.push(static_cast<float>(screenParallax(camera().interaxial, camera().convergence, probeDepth_)));
  }

  [[nodiscard]] bool finite() const override { return std::isfinite(probeDepth_); }
  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 4.0f}, 15.0f, 16.0f}; }
  [[nodiscard]] std::string summary() const override {
    const StereoCamera c = camera();
    char text[160];
    std::snprintf(text, sizeof text, "e = %.2f m, C = %.1f m: probe at %.2f m, parallax %.3f m (%s)", c.interaxial,
                  c.convergence, probeDepth_, screenParallax(c.interaxial, c.convergence, probeDepth_),
                  toString(depthZone(probeDepth_, c.convergence)));
    return text;
  }

  void draw(DebugDraw& draw) override {
    const StereoCamera c = camera();
    const double reach = 1.6 * c.convergence; // how far the frustums are drawn
    // The screen: the convergence plane's width W = 2 C tan(hfov/2).
    const double w = 0.5 * convergencePlaneWidth(c.convergence, horizontalFov(c.verticalFov, c.aspect));
    draw.segment(top(-w, c.convergence), top(w, c.convergence), palette::reference);
    draw.text(top(w + 0.3, c.convergence), "convergence plane (the screen)", palette::text);
    // Each eye's frustum: the near-plane rectangle [l, r] at n scaled to depth d.
    for (const Eye eye : {Eye::left, Eye::right}) {
      const double x = eyeOffset(c, eye);
      const Color col = eye == Eye::left ? leftColor : rightColor;
      if (toeIn_) {
        // Turned in by theta towards the convergence point: the symmetric frustum's edges rotated.
        const Frustum m = monoFrustum(c);
        const double theta = eye == Eye::left ? -toeInAngle(c) : toeInAngle(c); // + turns to -x
        for (const double edge : {m.left, m.right}) {
          const double a = std::atan2(edge, m.nearPlane) - theta;
          draw.segment(top(x, 0.0), top(x + reach * std::tan(a), reach), col.withAlpha(0.8f));
        }
        draw.segment(top(x, 0.0), top(0.0, c.convergence), col.withAlpha(0.35f));
      } else {
        const Frustum f = offAxisFrustum(c, eye);
        const double s = reach / f.nearPlane;
        draw.segment(top(x, 0.0), top(x + f.left * s, reach), col.withAlpha(0.8f));
        draw.segment(top(x, 0.0), top(x + f.right * s, reach), col.withAlpha(0.8f));
        draw.segment(top(x + f.left, f.nearPlane), top(x + f.right, f.nearPlane), col);
      }
      draw.solidCircle(top(x, 0.0), 0.12f, 0.0f, col, col);
      // The line of sight to the probe and where it crosses the screen.
      draw.segment(top(x, 0.0), top(0.0, probeDepth_), col.withAlpha(0.5f));
      const double cross = x + (0.0 - x) * c.convergence / probeDepth_;
      draw.point(top(cross, c.convergence), 9.0f, col);
    }
    draw.solidCircle(top(0.0, probeDepth_), 0.2f, 0.0f, palette::sensor, palette::sensor);
    char text[128];
    std::snprintf(text, sizeof text, "probe Z = %.2f m: P = e(1 - C/Z) = %.3f m (%s)", probeDepth_,
                  screenParallax(c.interaxial, c.convergence, probeDepth_),
                  toString(depthZone(probeDepth_, c.convergence)));
    draw.text(top(0.4, probeDepth_), text, palette::text);
    drawEyeImages(draw);
  }

  void ui() override {
    bool changed = slider("interaxial e", &interaxial_, 0.05f, 3.0f, "%.2f m");
    changed |= slider("convergence C", &convergence_, 2.0f, 12.0f, "%.1f m");
    changed |= slider("vertical fov", &fovDeg_, 20.0f, 100.0f, "%.0f deg");
    checkbox("toe-in instead of off-axis (for comparison)", &toeIn_);
    if (changed) {
      updateCurve();
    }
    const StereoCamera c = camera();
    textWrapped("toe-in angle %.2f deg; separation e/W = %.4f", radToDeg(toeInAngle(c)),
                separationFromInteraxial(c.interaxial, c.convergence, horizontalFov(c.verticalFov, c.aspect)));
    textWrapped("largest vertical parallax in the eyes' images: off-axis %.2g, toe-in %.2g (NDC units)",
                verticalParallax(false), verticalParallax(true));
    parallax_.plot("probe's screen parallax (m)", "%.3f m");
    plotCurve("P/e for Z from C/2 to 20 C (0 at C, 0.9 at 10 C)", curve_, "budget: [C/2, 100 C]", 70.0f, -1.0f, 1.0f);
  }

private:
  [[nodiscard]] StereoCamera camera() const {
    StereoCamera c;
    c.interaxial = static_cast<double>(interaxial_);
    c.convergence = static_cast<double>(convergence_);
    c.nearPlane = 0.5;
    c.farPlane = 200.0;
    c.verticalFov = degToRad(static_cast<double>(fovDeg_));
    c.aspect = 16.0 / 9.0;
    return c;
  }

  /// The wall of points at 2 C that the inset shows: 5 x 4 points across the view.
  [[nodiscard]] std::vector<Vec3d> wall() const {
    const StereoCamera c = camera();
    const double z = 2.0 * c.convergence;
    const double h = 0.8 * z * std::tan(0.5 * c.verticalFov);
    std::vector<Vec3d> points;
    for (int i = 0; i < 5; ++i) {
      for (int j = 0; j < 4; ++j) {
        points.push_back({(i - 2) * 0.5 * h * c.aspect, (j - 1.5) * 0.6 * h, -z});
      }
    }
    return points;
  }

  [[nodiscard]] EyeMatrices eyeMatrices(Eye eye, bool toeIn) const {
    return toeIn ? toeInEye({}, camera(), eye) : offAxisEye({}, camera(), eye);
  }

  [[nodiscard]] double verticalParallax(bool toeIn) const {
    const EyeMatrices l = eyeMatrices(Eye::left, toeIn);
    const EyeMatrices r = eyeMatrices(Eye::right, toeIn);
    double worst = 0.0;
    for (const Vec3d& p : wall()) {
      const double yl = perspectiveDivide(l.projection * transformPoint(l.view, p)).y;
      const double yr = perspectiveDivide(r.projection * transformPoint(r.view, p)).y;
      worst = std::max(worst, std::abs(yl - yr));
    }
    return worst;
  }

  /// What each eye sees of the wall, in NDC, drawn in a box under the top view.
  void drawEyeImages(DebugDraw& draw) const {
    const Vec2f centre{0.0f, -5.5f};
    const Vec2f halfSize{8.0f, 4.5f}; // 16:9
    draw.box(centre - halfSize, centre + halfSize, palette::grid.scaled(2.5f));
    draw.text(centre + Vec2f{-halfSize.x, -halfSize.y - 0.4f},
              toeIn_ ? "each eye's image of a wall at 2C: toe-in (keystone, vertical parallax)"
                     : "each eye's image of a wall at 2C: off-axis (horizontal parallax only)",
              palette::text);
    for (const Eye eye : {Eye::left, Eye::right}) {
      const EyeMatrices m = eyeMatrices(eye, toeIn_);
      const Color col = eye == Eye::left ? leftColor : rightColor;
      for (const Vec3d& p : wall()) {
        const Vec3d ndc = perspectiveDivide(m.projection * transformPoint(m.view, p));
        draw.point(centre + Vec2f{static_cast<float>(ndc.x) * halfSize.x, static_cast<float>(ndc.y) * halfSize.y}, 7.0f,
                   col);
      }
    }
  }

  void updateCurve() {
    curve_.clear();
    const StereoCamera c = camera();
    for (int i = 0; i <= 120; ++i) {
      const double z = c.convergence * 0.5 * std::pow(40.0, i / 120.0);
      curve_.push_back(static_cast<float>(screenParallax(1.0, c.convergence, z)));
    }
  }

  float interaxial_ = 0.8f;
  float convergence_ = 8.0f;
  float fovDeg_ = 50.0f;
  bool toeIn_ = false;
  double t_ = 0.0;
  double probeDepth_ = 4.0;
  History parallax_;
  std::vector<float> curve_;
};

const SampleRegistrar registrar{"Book", "Stereo frustums",
                                "Off-axis stereo frustums from above (ch. 24), the parallax of a probe moving in "
                                "depth, and each eye's image: off-axis against toe-in's vertical parallax.",
                                [] { return std::make_unique<StereoFrustums>(); }};

} // namespace
} // namespace impetus::samples
