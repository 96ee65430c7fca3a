// Book/Anaglyph (ch. 24): a stereo pair rendered through the off-axis frustums and mixed into a
// red-cyan anaglyph. A small ray tracer draws three balls over a checkered floor from each eye
// (display/stereo_frustum.hpp: each pixel's ray leaves the eye through its asymmetric near-plane
// rectangle), and display/anaglyph.hpp mixes the two images by the chosen method: true, gray,
// color, half-color, optimized or Dubois' least-squares matrices (in linear light). The balls orbit
// through the convergence plane, so they come out of the screen and go back in. Below: the left
// and right images. Plot: the orbiting ball's screen parallax in pixels.
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/display/anaglyph.hpp>
#include <impetus/display/stereo.hpp>
#include <impetus/display/stereo_frustum.hpp>
#include <impetus/math/scalar.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace impetus::samples {
namespace {

using namespace impetus::display;

constexpr int imageWidth = 80;
constexpr int imageHeight = 45;

struct Ball {
  Vec3d centre;
  double radius;
  Rgb colour;
};

/// The colour seen along a ray from `origin` in direction `d` (unit): the nearest ball, lit from
/// the upper left, or the floor y = -1.2 (a checkerboard), or the sky.
Rgb trace(const Vec3d& origin, const Vec3d& d, const std::vector<Ball>& balls) {
  double best = 1e30;
  const Ball* hit = nullptr;
  for (const Ball& b : balls) {
    const Vec3d oc = origin - b.centre;
    const double half = dot(oc, d);
    const double disc = half * half - (lengthSquared(oc) - b.radius * b.radius);
    if (disc > 0.0) {
      const double t = -half - std::sqrt(disc);
      if (t > 0.0 && t < best) {
        best = t;
        hit = &b;
      }
    }
  }
  const Vec3d light = normalize(Vec3d{-0.5, 0.8, 0.4});
  if (hit != nullptr) {
    const Vec3d n = (origin + d * best - hit->centre) / hit->radius;
    const double shade = 0.25 + 0.75 * std::max(0.0, dot(n, light));
    return {hit->colour.r * shade, hit->colour.g * shade, hit->colour.b * shade};
  }
  if (d.y < 0.0) {
    const double t = (-1.2 - origin.y) / d.y;
    const Vec3d p = origin + d * t;
    const bool dark = (static_cast<long>(std::floor(p.x)) + static_cast<long>(std::floor(p.z))) % 2 == 0;
    const double fog = std::exp(-0.04 * t);
    const double v = (dark ? 0.25 : 0.7) * fog + 0.35 * (1.0 - fog);
    return {v, v, v};
  }
  const double sky = std::clamp(0.55 + 0.4 * d.y, 0.0, 1.0);
  return {0.35 * sky, 0.5 * sky, 0.9 * sky};
}

class AnaglyphSample final : public Sample {
public:
  void setup() override {
    t_ = 0.0;
    render();
  }

  void step(float dt) override {
    t_ += dt;
    render();
    const StereoCamera c = camera();
    const double depth = -balls_[0].centre.z;
    const double w = convergencePlaneWidth(c.convergence, horizontalFov(c.verticalFov, c.aspect));
    parallax_.push(static_cast<float>(screenParallax(c.interaxial, c.convergence, depth) / w * imageWidth));
  }

  [[nodiscard]] bool finite() const override {
    for (const Rgb& p : mixed_) {
      if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) {
        return false;
      }
    }
    return true;
  }

  [[nodiscard]] CameraView initialView() const override { return {{0.0f, -2.5f}, 8.0f, 9.0f}; }
  [[nodiscard]] std::string summary() const override {
    char text[128];
    std::snprintf(text, sizeof text, "%s anaglyph of %d x %d px; orbiting ball at depth %.2f m (C = %.1f m)",
                  std::string(toString(mode_)).c_str(), imageWidth, imageHeight, -balls_[0].centre.z,
                  static_cast<double>(convergence_));
    return text;
  }

  void draw(DebugDraw& draw) override {
    drawImage(draw, mixed_, {-8.0f, -4.5f}, 16.0f / imageWidth);
    drawImage(draw, left_, {-8.0f, -10.0f}, 7.8f / imageWidth);
    drawImage(draw, right_, {0.2f, -10.0f}, 7.8f / imageWidth);
    // The title in two short lines above the image: one long line runs out of a small view.
    const std::string title = std::string(toString(mode_)) + " anaglyph";
    draw.text({-8.0f, 5.3f + DebugDraw::textLinePixels * draw.pixelSize()}, title, palette::text);
    draw.text({-8.0f, 5.3f}, "left eye red, right eye cyan", palette::text);
    draw.text({-8.0f, -5.1f}, "left eye", palette::text);
    draw.text({0.2f, -5.1f}, "right eye", palette::text);
  }

  void ui() override {
    static const char* names[] = {"true", "gray", "color", "half-color", "optimized", "dubois"};
    int m = static_cast<int>(mode_);
    labelColumn("method");
    if (ImGui::Combo("##method", &m, names, 6)) {
      mode_ = static_cast<AnaglyphMode>(m);
      render();
    }
    slider("interaxial e", &interaxial_, 0.0f, 1.0f, "%.2f m");
    slider("convergence C", &convergence_, 3.0f, 15.0f, "%.1f m");
    textWrapped("The front ball orbits from %.1f to %.1f m: in front of the screen when nearer than C.", 6.0 - 3.0,
                6.0 + 3.0);
    parallax_.plot("orbiting ball's parallax on the image (px)", "%.2f px");
  }

private:
  [[nodiscard]] StereoCamera camera() const {
    StereoCamera c;
    c.interaxial = static_cast<double>(interaxial_);
    c.convergence = static_cast<double>(convergence_);
    c.nearPlane = 0.2;
    c.farPlane = 100.0;
    c.verticalFov = degToRad(45.0);
    c.aspect = static_cast<double>(imageWidth) / imageHeight;
    return c;
  }

  /// Ray-traces both eyes through their off-axis frustums and mixes them.
  void render() {
    const double a = 0.7 * t_;
    balls_ = {{{2.2 * std::sin(a), 0.0, -6.0 - 3.0 * std::cos(a)}, 0.8, {0.95, 0.25, 0.2}},
              {{-2.2, -0.4, -8.0}, 0.8, {0.2, 0.8, 0.3}},
              {{1.2, 0.6, -11.0}, 1.0, {0.3, 0.45, 0.95}}};
    const StereoCamera c = camera();
    left_ = renderEye(c, Eye::left);
    right_ = renderEye(c, Eye::right);
    mixed_.resize(left_.size());
    anaglyphImage(left_, right_, mixed_, mode_);
  }

  [[nodiscard]] std::vector<Rgb> renderEye(const StereoCamera& c, Eye eye) const {
    const Frustum f = offAxisFrustum(c, eye);
    const Vec3d origin{eyeOffset(c, eye), 0.0, 0.0};
    std::vector<Rgb> image(static_cast<std::size_t>(imageWidth) * imageHeight);
    for (int j = 0; j < imageHeight; ++j) {
      for (int i = 0; i < imageWidth; ++i) {
        // The pixel's centre on the eye's near-plane rectangle.
        const double x = f.left + (i + 0.5) * (f.right - f.left) / imageWidth;
        const double y = f.top - (j + 0.5) * (f.top - f.bottom) / imageHeight;
        const Rgb p = trace(origin, normalize(Vec3d{x, y, -f.nearPlane}), balls_);
        image[static_cast<std::size_t>(j) * imageWidth + i] = {std::clamp(p.r, 0.0, 1.0), std::clamp(p.g, 0.0, 1.0),
                                                               std::clamp(p.b, 0.0, 1.0)};
      }
    }
    return image;
  }

  static void drawImage(DebugDraw& draw, const std::vector<Rgb>& image, const Vec2f& lowerLeft, float pixel) {
    for (int j = 0; j < imageHeight; ++j) {
      for (int i = 0; i < imageWidth; ++i) {
        const Rgb& p = image[static_cast<std::size_t>(j) * imageWidth + i];
        const Color col{static_cast<float>(p.r), static_cast<float>(p.g), static_cast<float>(p.b), 1.0f};
        const Vec2f a =
            lowerLeft + Vec2f{static_cast<float>(i) * pixel, static_cast<float>(imageHeight - 1 - j) * pixel};
        const Vec2f b = a + Vec2f{pixel, pixel};
        draw.triangle(a, {b.x, a.y}, b, col);
        draw.triangle(a, b, {a.x, b.y}, col);
      }
    }
  }

  AnaglyphMode mode_ = AnaglyphMode::dubois;
  float interaxial_ = 0.35f;
  float convergence_ = 7.0f;
  double t_ = 0.0;
  std::vector<Ball> balls_;
  std::vector<Rgb> left_, right_, mixed_;
  History parallax_;
};

const SampleRegistrar registrar{"Book", "Anaglyph",
                                "A ray-traced stereo pair through off-axis frustums mixed into a red-cyan "
                                "anaglyph (ch. 24): true, gray, color, half-color, optimized or Dubois.",
                                [] { return std::make_unique<AnaglyphSample>(); }};

} // namespace
} // namespace impetus::samples
