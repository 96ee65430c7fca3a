// The base of the engine samples that show the benchmark scenes (bench/rigid2d_scenes.hpp): the
// scene is built by the same builder the benchmark and its tests use (bench::buildImpetusScene),
// so what the sample shows is what is timed and checked. The scenes' quality figures (the top
// box's sinking, the deepest overlap, the widest joint gap) are computed by the benchmark's own
// functions and plotted live. Sleeping is off as in the benchmark (so the plots are the
// benchmark's); the panel's "sleeping" switch rebuilds the scene with it on.
#pragma once

#include "rigid2d_sample.hpp"

#include <rigid2d_scenes.hpp>

#include <vector>

namespace impetus::samples {

class BenchSceneSample : public Rigid2dSample {
public:
  [[nodiscard]] CameraView initialView() const override { return view_; }

protected:
  /// Builds `scene` with the benchmark's builder (its WorldDef: 4 substeps), sleeping as switched.
  void buildScene(bench::Rigid2dScene scene);
  [[nodiscard]] const bench::Rigid2dScene& scene() const noexcept { return scene_; }
  [[nodiscard]] const std::vector<rigid2d::BodyId>& sceneBodies() const noexcept { return bodies_; }
  /// Every scene body's transform, in scene order (for the quality figures).
  [[nodiscard]] std::vector<Transform2f> transforms() const;
  /// The scene's dynamic bodies' bounding box, with a margin, as the camera's view.
  [[nodiscard]] CameraView fitView() const;

  /// The common panel lines: the sleeping switch (which calls setup() to rebuild the scene) and
  /// the scene's size.
  void sceneControls();

private:
  bool sleep_ = false;
  bench::Rigid2dScene scene_;
  std::vector<rigid2d::BodyId> bodies_;
  CameraView view_;
};

} // namespace impetus::samples
