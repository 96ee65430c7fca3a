// `impetus run SCENE.json --steps N [--dt H] [--out traj.csv|traj.json] [--every K]`: simulates a
// particle scene file (docs/scene-format.md) or a 2D rigid-body scene file
// (docs/scene-format-2d.md, [--events FILE.csv]) and writes its trajectory and energies.
#pragma once

#include <cstdint>
#include <string>

namespace impetus::cli {

/// The most steps one run takes.
inline constexpr std::int64_t maxSteps = 100'000'000;

struct RunOptions {
  std::string scene;      ///< path of the scene file
  std::int64_t steps = 0; ///< world steps to take, >= 1
  double dt = 1.0 / 60.0; ///< s per step, in (0, 1] (a game frame by default)
  std::string out;        ///< .csv or .json file for the trajectory; empty: none
  std::int64_t every = 1; ///< record every K-th step (and the first and last), >= 1
  std::string events;     ///< .csv file for a rigid2d scene's contact and joint events; empty: none
  int threads = 1;        ///< rigid2d scenes: threads stepping the world (a ThreadPool), 1 to 64
  bool hash = false;      ///< print the final state's hash (World::stateHash) on a line of its own
};

/// Loads the scene, steps it and writes the trajectory; prints a one-paragraph summary.
/// Exit status 0; 2 with one line on stderr for a bad scene or argument; 1 if the simulation
/// produced a non-finite state.
int runScene(const RunOptions& options);

/// The line --hash prints: "state hash: " and 16 hex digits.
void printStateHash(std::uint64_t hash);

} // namespace impetus::cli
