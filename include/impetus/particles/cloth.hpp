// Cloth (ch. 13, the 1st edition's flag): a rows x columns grid of particles joined by
// structural, shear and bend connections, built in a ParticleWorld through its public API.
//
//   structural: (r, c)-(r, c+1) and (r, c)-(r+1, c)      resist stretching along the weave
//   shear:      (r, c)-(r+1, c+1) and (r, c+1)-(r+1, c)  resist the cells' shearing into rhombi
//                                                       (without them a cloth hung from two
//                                                       corners sags far more: spec Demo 13-D)
//   bend:       (r, c)-(r, c+2) and (r, c)-(r+2, c)      resist folding (two apart)
//
// ClothModel::xpbd (default) makes each a distance constraint with its own compliance (m/N;
// 0 = rigid): stable at a 1/60 s frame. ClothModel::bookSprings makes each a spring-damper with
// its own stiffness, the book's model, which needs small substeps when stiff.
//
// Wind: the cloth catches it through the world's drag, which acts on each particle's velocity
// relative to the air (ParticleWorldSettings::wind or windField, with linearDrag or
// dragCoefficient over the particles' frontal area pi r^2). Choose particleRadius about half
// the grid spacing so the particles' areas roughly tile the cloth.
#pragma once

#include <impetus/particles/particle_world.hpp>

#include <vector>

namespace impetus {

enum class ClothModel {
  xpbd,        ///< distance constraints with compliance (default)
  bookSprings, ///< spring-dampers
};

/// A particle of the grid: row 0 .. rows-1 (along `down`), column 0 .. columns-1 (along `across`).
struct GridIndex {
  int row = 0;
  int column = 0;
};

struct ClothDef {
  Vec3f origin;                   ///< particle (0, 0), m
  Vec3f across{1.0f, 0.0f, 0.0f}; ///< from (0, 0) to (0, columns-1): the width, m
  Vec3f down{0.0f, -1.0f, 0.0f};  ///< from (0, 0) to (rows-1, 0): the height, m
  int rows = 10;                  ///< >= 2
  int columns = 10;               ///< >= 2
  float totalMass = 1.0f;         ///< kg, > 0, shared evenly by the particles
  float particleRadius = 0.05f;   ///< m, > 0
  ClothModel model = ClothModel::xpbd;

  bool shear = true; ///< add the diagonal (shear) connections
  bool bend = true;  ///< add the two-apart (bend) connections

  // xpbd: compliance, m/N, >= 0.
  float structuralCompliance = 0.0f;
  float shearCompliance = 1e-4f;
  float bendCompliance = 1e-2f;

  // bookSprings: stiffness k (N/m, > 0) per kind and one damping d (N s/m, >= 0). Explicit
  // springs are stable only while the substep h is short enough for the fastest mode: roughly
  // sum(k) < 2 m / h^2 over a particle's springs, and n d h / m < 1 for its n springs. The
  // defaults keep the default cloth (10 g particles) stable in the default world (h = 1/240 s);
  // stiffer or lighter cloth needs more substeps, or the xpbd model.
  float structuralStiffness = 100.0f;
  float shearStiffness = 100.0f;
  float bendStiffness = 20.0f;
  float damping = 0.1f;

  /// Particles held in place (infinite mass), e.g. the top edge or two corners.
  std::vector<GridIndex> pinned;

  /// Pins every particle of `row` (pinRow(0): the top edge of a hanging flag).
  void pinRow(int row);
};

/// What createCloth made. Particles are stored row by row: (r, c) is particles[r * columns + c].
/// Connections are stored structural first, then shear, then bend, with the counts of each
/// (constraints for xpbd, springs for bookSprings; the other list is empty).
struct Cloth {
  int rows = 0;
  int columns = 0;
  std::vector<ParticleId> particles;
  std::vector<ConstraintId> constraints;
  std::vector<SpringId> springs;
  std::size_t structuralCount = 0;
  std::size_t shearCount = 0;
  std::size_t bendCount = 0;

  /// The particle at (row, column); throws impetus::Error when outside the grid.
  [[nodiscard]] ParticleId at(int row, int column) const;
};

/// Creates the cloth's particles and connections in `world`. Throws impetus::Error naming the
/// field of `def` that is invalid (the world is unchanged then).
[[nodiscard]] Cloth createCloth(ParticleWorld& world, const ClothDef& def);

} // namespace impetus
