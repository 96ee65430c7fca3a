// Forces, integrators and the XPBD distance constraints of the particle world.
#include "particles/particle_world_impl.hpp"

#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::detail {
namespace {

/// The air's velocity at a particle.
Vec3f windAt(const ParticleWorldState& w, const Vec3f& x) {
  return w.settings.windField ? w.settings.windField(x, w.time) : w.settings.wind;
}

/// x + a h for every element: the intermediate states of the multi-stage integrators.
void axpy(std::span<const Vec3f> x, std::span<const Vec3f> a, float h, std::vector<Vec3f>& out) {
  out.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    out[i] = x[i] + a[i] * h;
  }
}

} // namespace

void computeAccelerations(const ParticleWorldState& w, std::span<const Vec3f> x, std::span<const Vec3f> v,
                          std::span<Vec3f> a, float h) {
  const ParticleWorldSettings& s = w.settings;
  const ParticleStore& p = w.particles;
  const bool drag = s.linearDrag > 0.0f || s.dragCoefficient > 0.0f;
  // Quadratic drag 1/2 rho Cd (pi r^2) |v_rel| v_rel: the part that does not depend on r.
  const float quadratic = 0.5f * s.airDensity * s.dragCoefficient * pi<float>;
  const float strongestDrag = 1.0f / h; // 1/s: stops the relative motion in one step, no more
  for (std::size_t i = 0; i < x.size(); ++i) {
    a[i] = s.gravity + p.userForce[i] / p.mass[i];
    if (drag) {
      const Vec3f relative = v[i] - windAt(w, x[i]);
      const float r = p.radius[i];
      // Drag per unit relative velocity, 1/s.
      const float rate = (s.linearDrag + quadratic * r * r * length(relative)) / p.mass[i];
      a[i] -= relative * std::min(rate, strongestDrag);
    }
  }
  for (const Attractor& at : w.attractors) {
    const float eps2 = at.softening * at.softening;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3f d = at.position - x[i];
      const float r2 = lengthSquared(d) + eps2;
      a[i] += d * (at.strength / (r2 * std::sqrt(r2)));
    }
  }
  // Springs: one force per pair, applied equal and opposite (ch. 14's note).
  for (const Spring& sp : w.springs) {
    const std::uint32_t ia = w.slotToDense[sp.a.index];
    const bool anchored = sp.b.isNull();
    const std::uint32_t ib = anchored ? 0 : w.slotToDense[sp.b.index];
    const Vec3f d = (anchored ? sp.anchor : x[ib]) - x[ia];
    const float len = length(d);
    // Coincident ends have no direction: no force (the limit for a zero rest length).
    const Vec3f u = len > 0.0f ? d / len : Vec3f{};
    const Vec3f relative = (anchored ? Vec3f{} : v[ib]) - v[ia];
    const Vec3f f = u * (sp.stiffness * (len - sp.restLength) + sp.damping * dot(relative, u));
    a[ia] += f / p.mass[ia];
    if (!anchored) {
      a[ib] -= f / p.mass[ib];
    }
  }
  // Pinned particles do not move.
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (p.inverseMass[i] == 0.0f) {
      a[i] = {};
    }
  }
}

void integrate(ParticleWorldState& w, float h) {
  ParticleStore& p = w.particles;
  Scratch& s = w.scratch;
  const std::size_t n = p.size();
  std::vector<Vec3f>& a = s.acceleration;
  a.resize(n);
  computeAccelerations(w, p.position, p.velocity, a, h);
  switch (w.settings.integrator) {
  case ParticleIntegrator::semiImplicitEuler:
    for (std::size_t i = 0; i < n; ++i) {
      p.velocity[i] += a[i] * h;
      p.position[i] += p.velocity[i] * h;
    }
    break;
  case ParticleIntegrator::explicitEuler:
    for (std::size_t i = 0; i < n; ++i) {
      p.position[i] += p.velocity[i] * h;
      p.velocity[i] += a[i] * h;
    }
    break;
  case ParticleIntegrator::velocityVerlet: {
    // x1 = x0 + v0 h + a0 h^2/2; a1 from (x1, v0 + a0 h); v1 = v0 + (a0 + a1) h/2. Exact
    // second order for position-dependent forces; velocity-dependent ones (drag) use the
    // predicted velocity.
    s.v0.assign(p.velocity.begin(), p.velocity.end());
    for (std::size_t i = 0; i < n; ++i) {
      p.position[i] += (p.velocity[i] + a[i] * (0.5f * h)) * h;
    }
    axpy(s.v0, a, h, s.k1v);
    s.k2v.resize(n);
    computeAccelerations(w, p.position, s.k1v, s.k2v, h);
    for (std::size_t i = 0; i < n; ++i) {
      p.velocity[i] = s.v0[i] + (a[i] + s.k2v[i]) * (0.5f * h);
    }
    break;
  }
  case ParticleIntegrator::rk4: {
    // Classic RK4 on the whole state (x, v): forces re-evaluated at every stage.
    s.x0.assign(p.position.begin(), p.position.end());
    s.v0.assign(p.velocity.begin(), p.velocity.end());
    s.k2v.resize(n);
    s.k3v.resize(n);
    s.k4v.resize(n);
    // k1 = (v0, a0)
    axpy(s.x0, s.v0, 0.5f * h, s.k1x); // x at the midpoint with k1
    axpy(s.v0, a, 0.5f * h, s.k1v);
    computeAccelerations(w, s.k1x, s.k1v, s.k2v, 0.5f * h); // k2 = (k1v, k2v)
    axpy(s.x0, s.k1v, 0.5f * h, s.k2x);
    axpy(s.v0, s.k2v, 0.5f * h, s.k3x);                     // reuse k3x as the stage-3 velocity
    computeAccelerations(w, s.k2x, s.k3x, s.k3v, 0.5f * h); // k3 = (k3x, k3v)
    axpy(s.x0, s.k3x, h, s.k4x);
    axpy(s.v0, s.k3v, h, s.x0); // stage-4 velocity (x0 is copied back below first)
    std::vector<Vec3f>& v4 = s.x0;
    computeAccelerations(w, s.k4x, v4, s.k4v, h); // k4 = (v4, k4v)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3f x0 = p.position[i];
      const Vec3f v0 = p.velocity[i];
      p.position[i] = x0 + (v0 + s.k1v[i] * 2.0f + s.k3x[i] * 2.0f + v4[i]) * (h / 6.0f);
      p.velocity[i] = v0 + (a[i] + s.k2v[i] * 2.0f + s.k3v[i] * 2.0f + s.k4v[i]) * (h / 6.0f);
    }
    break;
  }
  }
}

void solveConstraints(ParticleWorldState& w, float h) {
  ParticleStore& p = w.particles;
  std::vector<Vec3f>& before = w.scratch.beforeConstraints;
  before.assign(p.position.begin(), p.position.end());
  const float inverseH2 = 1.0f / (h * h);
  std::vector<float>& lambda = w.scratch.lambda; // accumulated multipliers of this substep
  lambda.assign(w.constraints.size(), 0.0f);
  for (int iteration = 0; iteration < w.settings.constraintIterations; ++iteration) {
    for (std::size_t k = 0; k < w.constraints.size(); ++k) {
      const DistanceConstraint& c = w.constraints[k];
      const std::uint32_t ia = w.slotToDense[c.a.index];
      const bool anchored = c.b.isNull();
      const std::uint32_t ib = anchored ? 0 : w.slotToDense[c.b.index];
      const float wa = p.inverseMass[ia];
      const float wb = anchored ? 0.0f : p.inverseMass[ib];
      // XPBD: dlambda = (-C - alpha~ lambda) / (wa + wb + alpha~), alpha~ = alpha / h^2.
      const float alpha = c.compliance * inverseH2;
      const float denominator = wa + wb + alpha;
      // Rigid between pinned particles (0), or so compliant that alpha overflowed (infinity:
      // no force, where the update would compute infinity * 0 = NaN).
      if (denominator == 0.0f || !std::isfinite(alpha)) {
        continue;
      }
      const Vec3f d = p.position[ia] - (anchored ? c.anchor : p.position[ib]);
      const float len = length(d);
      const float violation = len - c.length;
      if (len == 0.0f || (c.maxOnly && violation <= 0.0f)) {
        continue;
      }
      const float deltaLambda = (-violation - alpha * lambda[k]) / denominator;
      lambda[k] += deltaLambda;
      const Vec3f correction = d * (deltaLambda / len);
      p.position[ia] += correction * wa;
      if (!anchored) {
        p.position[ib] -= correction * wb;
      }
    }
  }
  // The projection moved the particles: their velocities follow (v = dx / h).
  const float inverseH = 1.0f / h;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.velocity[i] += (p.position[i] - before[i]) * inverseH;
  }
}

} // namespace impetus::detail
