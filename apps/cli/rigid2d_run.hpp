// `impetus run` for a 2D rigid-body scene ("kind": "rigid2d", docs/scene-format-2d.md): steps the
// world (its effectors applied before each step) and records the bodies' trajectories, the
// energies and the contact and joint events.
#pragma once

#include "run_command.hpp"

#include <nlohmann/json.hpp>

namespace impetus::cli {

/// Builds the scene from the parsed document `doc`, steps it and writes the files `options` asks
/// for; prints a one-line summary. Returns 0, or 1 (after a line on stderr) if the state ever
/// became non-finite. Throws impetus::Error for a bad scene or argument (the caller prints it
/// and exits 2): nothing is written then.
int runRigid2dScene(const RunOptions& options, const nlohmann::json& doc);

} // namespace impetus::cli
