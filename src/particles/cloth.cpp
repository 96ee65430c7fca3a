// The cloth builder: a grid of particles with structural, shear and bend connections.
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/particles/cloth.hpp>

#include <string>

namespace impetus {

void ClothDef::pinRow(int row) {
  for (int c = 0; c < columns; ++c) {
    pinned.push_back({row, c});
  }
}

ParticleId Cloth::at(int row, int column) const {
  if (row < 0 || row >= rows) {
    throwInvalid("row", row, "must be in [0, rows)");
  }
  if (column < 0 || column >= columns) {
    throwInvalid("column", column, "must be in [0, columns)");
  }
  return particles[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                   static_cast<std::size_t>(column)];
}

namespace {

void validate(const ClothDef& def) {
  requireFinite(def.origin, "origin");
  requireFinite(def.across, "across");
  requireFinite(def.down, "down");
  if (def.rows < 2 || def.rows > 10'000) {
    throwInvalid("rows", def.rows, "must be between 2 and 10000");
  }
  if (def.columns < 2 || def.columns > 10'000) {
    throwInvalid("columns", def.columns, "must be between 2 and 10000");
  }
  // Distinct particles need edges that span a parallelogram (constraints between coincident
  // particles have no direction).
  if (!(lengthSquared(cross(def.across, def.down)) > 0.0f)) {
    throwInvalid("down", 0.0, "must be non-zero and not parallel to across");
  }
  // Finite edges can still put the far corners beyond a float: the world would refuse the cloth
  // half built.
  if (const Vec3f corner = def.origin + def.across; !isFinite(corner)) {
    throwInvalid("across", static_cast<double>(length(corner)), "puts a corner beyond single precision");
  }
  if (const Vec3f corner = def.origin + def.across + def.down; !isFinite(corner) || !isFinite(def.origin + def.down)) {
    throwInvalid("down", static_cast<double>(length(corner)), "puts a corner beyond single precision");
  }
  requirePositive(def.totalMass, "totalMass");
  if (!(def.totalMass / (static_cast<float>(def.rows) * static_cast<float>(def.columns)) > 0.0f)) {
    throwInvalid("totalMass", def.totalMass, "too small to share among rows * columns particles");
  }
  requirePositive(def.particleRadius, "particleRadius");
  requireNonNegative(def.structuralCompliance, "structuralCompliance");
  requireNonNegative(def.shearCompliance, "shearCompliance");
  requireNonNegative(def.bendCompliance, "bendCompliance");
  requirePositive(def.structuralStiffness, "structuralStiffness");
  requirePositive(def.shearStiffness, "shearStiffness");
  requirePositive(def.bendStiffness, "bendStiffness");
  requireNonNegative(def.damping, "damping");
  for (std::size_t i = 0; i < def.pinned.size(); ++i) {
    const GridIndex& g = def.pinned[i];
    const std::string field = "pinned[" + std::to_string(i) + "]";
    if (g.row < 0 || g.row >= def.rows) {
      throwInvalid(field + ".row", g.row, "must be in [0, rows)");
    }
    if (g.column < 0 || g.column >= def.columns) {
      throwInvalid(field + ".column", g.column, "must be in [0, columns)");
    }
  }
}

/// Adds one connection of a kind (its compliance or stiffness) between two grid particles.
class Connector {
public:
  Connector(ParticleWorld& world, const ClothDef& def, Cloth& cloth) : world_(world), def_(def), cloth_(cloth) {}

  void connect(int r0, int c0, int r1, int c1, float compliance, float stiffness) {
    const ParticleId a = cloth_.at(r0, c0);
    const ParticleId b = cloth_.at(r1, c1);
    if (def_.model == ClothModel::xpbd) {
      DistanceConstraintDef c;
      c.a = a;
      c.b = b;
      c.compliance = compliance; // length: the distance at creation, the cloth's rest shape
      cloth_.constraints.push_back(world_.addDistanceConstraint(c));
    } else {
      SpringDef s;
      s.a = a;
      s.b = b;
      s.stiffness = stiffness;
      s.damping = def_.damping;
      cloth_.springs.push_back(world_.addSpring(s));
    }
  }

  [[nodiscard]] std::size_t count() const {
    return def_.model == ClothModel::xpbd ? cloth_.constraints.size() : cloth_.springs.size();
  }

private:
  ParticleWorld& world_;
  const ClothDef& def_;
  Cloth& cloth_;
};

} // namespace

Cloth createCloth(ParticleWorld& world, const ClothDef& def) {
  validate(def);
  const int rows = def.rows;
  const int columns = def.columns;
  Cloth cloth;
  cloth.rows = rows;
  cloth.columns = columns;
  const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
  cloth.particles.reserve(n);
  std::vector<bool> pin(n, false);
  for (const GridIndex& g : def.pinned) {
    pin[static_cast<std::size_t>(g.row) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(g.column)] =
        true;
  }
  const float mass = def.totalMass / static_cast<float>(n);
  for (int r = 0; r < rows; ++r) {
    const float v = static_cast<float>(r) / static_cast<float>(rows - 1);
    for (int c = 0; c < columns; ++c) {
      const float u = static_cast<float>(c) / static_cast<float>(columns - 1);
      ParticleDef p;
      p.position = def.origin + def.across * u + def.down * v;
      p.mass = mass;
      p.radius = def.particleRadius;
      p.pinned = pin[cloth.particles.size()];
      cloth.particles.push_back(world.createParticle(p));
    }
  }

  Connector link(world, def, cloth);
  // Structural, row by row from the top: Gauss-Seidel then carries the pinned edge's correction
  // down the cloth within one pass.
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      if (c + 1 < columns) {
        link.connect(r, c, r, c + 1, def.structuralCompliance, def.structuralStiffness);
      }
      if (r + 1 < rows) {
        link.connect(r, c, r + 1, c, def.structuralCompliance, def.structuralStiffness);
      }
    }
  }
  cloth.structuralCount = link.count();
  if (def.shear) {
    for (int r = 0; r + 1 < rows; ++r) {
      for (int c = 0; c + 1 < columns; ++c) {
        link.connect(r, c, r + 1, c + 1, def.shearCompliance, def.shearStiffness);
        link.connect(r, c + 1, r + 1, c, def.shearCompliance, def.shearStiffness);
      }
    }
  }
  cloth.shearCount = link.count() - cloth.structuralCount;
  if (def.bend) {
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < columns; ++c) {
        if (c + 2 < columns) {
          link.connect(r, c, r, c + 2, def.bendCompliance, def.bendStiffness);
        }
        if (r + 2 < rows) {
          link.connect(r, c, r + 2, c, def.bendCompliance, def.bendStiffness);
        }
      }
    }
  }
  cloth.bendCount = link.count() - cloth.structuralCount - cloth.shearCount;
  return cloth;
}

} // namespace impetus
