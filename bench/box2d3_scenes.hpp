// The 2D benchmark scenes (rigid2d_scenes.hpp) built in Box2D v3, the engine Impetus' 2D world is
// modelled on: the same bodies, boxes and circles, joints, gravity, density and friction, stepped
// with Box2D v3's own defaults (4 substeps, 30 Hz contacts, continuous collision on) and
// sleeping as the scene says, as in Impetus. Box2D v3 is built outside the repository from its public source
// and found through the CMake option IMPETUS_BOX2D3_DIR (bench/CMakeLists.txt); CI does not
// need it. Its C headers share their names with Box2D 2.4.1's (<box2d/box2d.h>), so only
// box2d3_scenes.cpp includes them, and this header shows none of their types.
#pragma once

#include "rigid2d_scenes.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace impetus::bench {

/// Box2D v3's defaults that impetus-bench uses: substeps per step.
inline constexpr int box2d3Substeps = 4;

/// A scene built in a Box2D v3 world; body i is the scene's body i. Its script's groups are
/// spawned and destroyed through it.
class Box2D3Scene final : public SceneSpawner {
public:
  /// `workers`: Box2D v3's worker threads (1: single-threaded; more: its own scheduler).
  /// `continuous`: its continuous collision (its default: on).
  Box2D3Scene(const Rigid2dScene& scene, int workers, bool continuous = true);
  ~Box2D3Scene() override;
  Box2D3Scene(const Box2D3Scene&) = delete;
  Box2D3Scene& operator=(const Box2D3Scene&) = delete;

  std::uint32_t spawn(const SceneContent& group) override;
  void destroy(std::uint32_t group) override;
  /// One step of sceneTimeStep with box2d3Substeps substeps.
  void step();
  /// Height of body i's origin, m.
  [[nodiscard]] float height(std::uint32_t body) const;
  /// Every body's transform (of its origin), in scene order.
  [[nodiscard]] std::vector<Transform2f> transforms() const;
  /// The last step's time by stage, ms (b2World_GetProfile), in Impetus' stage names: prepare is
  /// v3's solver setup and constraint preparation; finalize its transforms, islands, events,
  /// refit and continuous collision.
  [[nodiscard]] rigid2d::StepProfile profile() const;
  /// Contacts touching now (Box2D v3's constraint graph and overflow).
  [[nodiscard]] std::size_t touchingContacts() const;
  /// "box2d 3.x.y", from the library's own version.
  [[nodiscard]] static std::string version();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace impetus::bench
