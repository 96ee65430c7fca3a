// `impetus calc` entries for the display layer (ch. 24): stereo frustums and matrices per eye,
// parallax and where a viewer sees it, separation and interaxial distance, anaglyph pixels.
#include "calc/calc.hpp"
#include "calc/values.hpp"

#include <impetus/display/display.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <cmath>
#include <string>

namespace impetus::cli {
namespace {

using namespace impetus::display;

constexpr const char* topic = "stereo 3D display (ch. 24)";

Vector frustumVector(const Frustum& f) { return {f.left, f.right, f.bottom, f.top, f.nearPlane, f.farPlane}; }

Matrix rows(const Matrix4& m) {
  Matrix out;
  for (int r = 0; r < 4; ++r) {
    out.push_back({m(r, 0) + 0.0, m(r, 1) + 0.0, m(r, 2) + 0.0, m(r, 3) + 0.0}); // no -0
  }
  return out;
}

StereoCamera camera(const Args& a) {
  StereoCamera c;
  c.interaxial = a.number("interaxial");
  c.convergence = a.number("convergence");
  c.nearPlane = requirePositive(a.number("near"), "near");
  c.farPlane = requireFinite(a.number("far"), "far");
  c.verticalFov = degToRad(requireFinite(a.number("fov"), "fov"));
  c.aspect = a.number("aspect");
  validate(c);
  return c;
}

Result frustumModel(const Args& a) {
  const StereoCamera c = camera(a);
  const CameraPose pose{}; // at the origin, looking down -z, y up
  Result r;
  r.add("left_frustum", frustumVector(offAxisFrustum(c, Eye::left)), "m",
        "glFrustum l, r, b, t, n, f: [-w + s, w + s], s = (e/2) n / C");
  r.add("right_frustum", frustumVector(offAxisFrustum(c, Eye::right)), "m", "[-w - s, w - s]");
  r.add("mono_frustum", frustumVector(monoFrustum(c)), "m", "t = n tan(fov/2), w = aspect t");
  r.add("left_projection", rows(frustumMatrix(offAxisFrustum(c, Eye::left))), "", "row by row (OpenGL stores columns)");
  r.add("left_view", rows(offAxisView(pose, c, Eye::left)), "", "translate by +e/2 along x");
  r.add("right_projection", rows(frustumMatrix(offAxisFrustum(c, Eye::right))), "");
  r.add("right_view", rows(offAxisView(pose, c, Eye::right)), "");
  r.add("toe_in_angle", radToDeg(toeInAngle(c)), "deg", "atan((e/2)/C): the toe-in method's turn (not recommended)");
  const double hfov = horizontalFov(c.verticalFov, c.aspect);
  r.add("horizontal_fov", radToDeg(hfov), "deg");
  r.add("separation", separationFromInteraxial(c.interaxial, c.convergence, hfov), "",
        "e / W: the parallax of infinity as a fraction of the screen width");
  return r;
}

Result parallaxModel(const Args& a) {
  const double e = a.number("interaxial");
  const double convergence = a.number("convergence");
  const double depth = a.number("depth");
  const double hfov = degToRad(requireFinite(a.number("horizontal-fov"), "horizontalFov"));
  const double p = screenParallax(e, convergence, depth);
  const double width = convergencePlaneWidth(convergence, hfov);
  const double screenWidth = requirePositive(a.number("screen-width"), "screenWidth");
  const double physical = p / width * screenWidth;
  Result r;
  r.add("parallax", p, "m", "e (1 - C/Z) on the convergence plane (+ behind the screen)");
  r.add("screen_fraction", p / width, "", "of the screen's width");
  r.add("screen_parallax", physical, "m", "on the physical screen");
  r.add("pixels", p / width * requirePositive(a.number("screen-pixels"), "screenPixels"), "px");
  r.add("zone", std::string(toString(depthZone(depth, convergence))), "", "the book's budget: action in [C, 10C]");
  const auto seen = perceivedDistance(physical, a.number("viewing-distance"), a.number("eye-separation"));
  r.add("diverges", !seen.has_value(), "", "parallax at or past the eye separation: cannot be fused");
  if (seen) {
    r.add("perceived_distance", *seen, "m", "D i / (i - p) from the viewer");
  }
  return r;
}

Result separationModel(const Args& a) {
  const double hfov = degToRad(requireFinite(a.number("horizontal-fov"), "horizontalFov"));
  const double convergence = a.number("convergence");
  Result r;
  r.add("plane_width", convergencePlaneWidth(convergence, hfov), "m", "W = 2 C tan(hfov/2)");
  r.add("interaxial", interaxialFromSeparation(a.number("separation"), convergence, hfov), "m", "e = separation W");
  r.add("real_separation",
        requirePositive(a.number("eye-separation"), "eyeSeparation") /
            requirePositive(a.number("screen-width"), "screenWidth"),
        "", "eyes / screen width: the most a scene should use (NVIDIA's real eye separation)");
  return r;
}

Rgb pixel(const Args& a, const std::string& name) {
  const Vec3d v = vector3(a, name);
  return {v.x, v.y, v.z};
}

Result anaglyphModel(const Args& a) {
  const Rgb l = pixel(a, "left");
  const Rgb r = pixel(a, "right");
  const std::string& mode = a.text("mode");
  Result out;
  const auto add = [&](AnaglyphMode m) {
    const Rgb c = anaglyph(l, r, m);
    out.add(std::string(toString(m)), Vector{c.r, c.g, c.b}, "", "r, g, b in [0, 1]");
  };
  if (mode == "all") {
    for (const AnaglyphMode m : {AnaglyphMode::trueAnaglyph, AnaglyphMode::gray, AnaglyphMode::color,
                                 AnaglyphMode::halfColor, AnaglyphMode::optimized, AnaglyphMode::dubois}) {
      add(m);
    }
  } else {
    add(anaglyphModeFromString(mode));
  }
  out.notes.emplace_back("left eye behind the red filter; dubois works in linear light (sRGB converted)");
  return out;
}

} // namespace

void registerDisplayModels(Registry& registry) {
  const std::vector<Param> cameraParams{
      {"interaxial", "m", "e: distance between the two cameras", std::string("0.065")},
      {"convergence", "m", "C: distance of the zero-parallax (screen) plane", std::string("10")},
      {"near", "m", "near clip plane", std::string("0.1")},
      {"far", "m", "far clip plane", std::string("1000")},
      {"fov", "deg", "vertical field of view", std::string("60")},
      {"aspect", "", "width / height", std::string("1.7777777777777777")}};
  registry.add({"stereo-frustum", topic,
                "off-axis (asymmetric) frustums, projection and view matrices per eye for OpenGL", cameraParams,
                frustumModel});
  registry.add({"stereo-parallax",
                topic,
                "screen parallax of a point at depth Z, e (1 - C/Z), and where a viewer sees it",
                {{"interaxial", "m", "e", std::string("0.065")},
                 {"convergence", "m", "C", std::string("10")},
                 {"depth", "m", "Z of the point", std::string("20")},
                 {"horizontal-fov", "deg", "of the mono camera", std::string("90")},
                 {"screen-width", "m", "physical width of the display", std::string("0.531")},
                 {"screen-pixels", "px", "its width in pixels", std::string("1920")},
                 {"viewing-distance", "m", "from the viewer's eyes to the screen", std::string("0.6")},
                 {"eye-separation", "m", "the viewer's", std::string("0.065")}},
                parallaxModel});
  registry.add({"stereo-separation",
                topic,
                "interaxial distance from NVIDIA's separation (the parallax of infinity per screen width)",
                {{"separation", "", "fraction of the screen width", std::string("0.05")},
                 {"convergence", "m", "C", std::string("10")},
                 {"horizontal-fov", "deg", "", std::string("90")},
                 {"eye-separation", "m", "the viewer's", std::string("0.065")},
                 {"screen-width", "m", "the display's", std::string("0.531")}},
                separationModel});
  registry.add(
      {"anaglyph",
       topic,
       "red-cyan anaglyph of a left and a right pixel (true, gray, color, half-color, optimized, dubois)",
       {vectorParam("left", "", "left-eye pixel r,g,b in [0, 1]", "0.2,0.4,0.6"),
        vectorParam("right", "", "right-eye pixel r,g,b in [0, 1]", "0.9,0.5,0.1"),
        {"mode", "", "true, gray, color, half-color, optimized, dubois or all", std::string("all"), ParamKind::text}},
       anaglyphModel});
}

} // namespace impetus::cli
