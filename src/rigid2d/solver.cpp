// The soft step (after Erin Catto's Solver2D and Box2D v3): the order of one step's solve.
//
// The awake bodies get compact solver indices; then, `substeps` times: integrate velocities
// (gravity, applied forces, damping), warm start the contacts and joints with their accumulated
// impulses, solve them with bias (soft constraints that push overlap apart at a bounded speed),
// integrate positions (as deltas, at speeds held within the world's limits: capVelocity), and
// relax (solve again without bias, taking back the velocity the bias added); restitution acts
// within the solve and relax, as impacts (contact_solver.cpp). The impulses are stored for the
// next step.
#include "rigid2d/joints.hpp"
#include "rigid2d/world_impl.hpp"
#include "solver/simd.hpp"
#include "solver/stage_clock.hpp"

#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace impetus::rigid2d::detail {

void WorldState::parallelFor(std::uint32_t count, std::uint32_t minRange, const TaskRunner::RangeTask& task) const {
  if (count == 0) {
    return;
  }
  if (def.taskRunner != nullptr && count > minRange) {
    def.taskRunner->parallelFor(count, minRange, task);
  } else {
    task(0, count);
  }
}

namespace {

/// The most a body may turn in one substep, rad: faster spin is clamped so the rotation
/// deltas (and the anchors that follow them) stay meaningful.
constexpr float maxRotationPerSubstep = 0.25f * pi<float>;

} // namespace

void buildSolverBodies(WorldState& w) {
  // The awake set, compacted, is this step's solver order.
  w.awakeBodySet.compact();
  const std::span<const std::uint32_t> awake = w.awakeBodySet.items();
  w.awakeBodies.assign(awake.begin(), awake.end());
  const auto n = static_cast<std::uint32_t>(w.awakeBodies.size());
  w.states.resize(n + 2);
  w.sims.resize(n);
  w.jointPoses.resize(n);
  w.states[n] = BodyState{}; // the static state: at rest, never written
  // states[n + 1]: where the wide contact solve writes its static lanes (never read), so that
  // its stores need no branch.
  const Vec2f gravity = w.def.gravity;
  w.parallelFor(n, 256, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t i = begin; i < end; ++i) {
      // Each body writes only its own record and entries: the bodies run on threads.
      Body& b = w.bodies[w.awakeBodies[i]];
      b.solverIndex = i;
      w.bodyInfo[w.awakeBodies[i]] = {i, b.inverseMass, b.inverseInertia, b.center - b.transform.p};
      w.states[i] = BodyState{b.linearVelocity, b.angularVelocity, 0.0f, {}, Rot2f::identity()};
      w.jointPoses[i] = jointBodyPose(b);
      BodySim& sim = w.sims[i];
      sim.dynamic = b.type == BodyType::dynamicBody;
      sim.acceleration = sim.dynamic ? gravity * b.gravityScale + b.force * b.inverseMass : Vec2f{};
      sim.angularAcceleration = sim.dynamic ? b.inverseInertia * b.torque : 0.0f;
      sim.allowFastRotation = b.allowFastRotation;
      sim.linearDamping = b.linearDamping;
      sim.angularDamping = b.angularDamping;
    }
  });
}

void integrateVelocities(WorldState& w, const StepContext& context) {
  const float h = context.h;
  w.parallelFor(static_cast<std::uint32_t>(w.sims.size()), 256, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t i = begin; i < end; ++i) {
      const BodySim& sim = w.sims[i];
      if (!sim.dynamic) {
        continue; // kinematic: moves at its set velocity
      }
      BodyState& s = w.states[i];
      // Implicit damping: stable for any coefficient.
      s.v = (s.v + sim.acceleration * h) * (1.0f / (1.0f + h * sim.linearDamping));
      s.w = (s.w + sim.angularAcceleration * h) * (1.0f / (1.0f + h * sim.angularDamping));
    }
  });
}

namespace {

/// One body's positions over a substep: its speeds held within the world's limits (capVelocity;
/// kinematic bodies keep theirs), then the position and rotation deltas advanced.
void integrateBody(BodyState& s, const BodySim& sim, const StepContext& context) {
  if (sim.dynamic) {
    capVelocity(s, context, sim.allowFastRotation);
  }
  s.dp += s.v * context.h;
  const float angle = s.w * context.h;
  s.dq = normalize(Rot2f{s.dq.c - angle * s.dq.s, s.dq.s + angle * s.dq.c});
}

/// integrateBody for solver::simdWidth dynamic bodies from `first` at once (the baseline's
/// lanes), operation for operation, so each lane is the scalar result to the bit; false (nothing
/// written) when a body is kinematic or may spin fast, or needs one of normalize's or
/// capVelocity's rare branches (a speed over the cap, a rotation that overflowed or vanished):
/// the caller then takes those bodies one by one.
bool integrateBodiesWide(WorldState& w, std::uint32_t first, const StepContext& context) {
  using namespace solver;
  constexpr auto lanes = static_cast<std::size_t>(simdWidth);
  float* rows[lanes];
  const float* in[lanes];
  for (std::size_t i = 0; i < lanes; ++i) {
    const BodySim& sim = w.sims[first + i];
    if (!sim.dynamic || sim.allowFastRotation) {
      return false;
    }
    rows[i] = &w.states[first + i].v.x;
    in[i] = rows[i];
  }
  FloatW c[8]; // v.x, v.y, w, unused, dp.x, dp.y, dq.c, dq.s
  loadRowsW(in, c);
  // std::clamp(x, lo, hi): lo where x < lo, else hi where hi < x, else x (a NaN stays).
  const auto clampW = [](FloatW x, FloatW lo, FloatW hi) {
    return selectW(greaterW(lo, x), lo, selectW(greaterW(x, hi), hi, x));
  };
  const FloatW maxSpeed = splatW(context.maxLinearSpeed);
  const FloatW maxSpin = splatW(context.maxAngularSpeed);
  const FloatW vx = clampW(c[0], negateW(maxSpeed), maxSpeed);
  const FloatW vy = clampW(c[1], negateW(maxSpeed), maxSpeed);
  const FloatW spin = clampW(c[2], negateW(maxSpin), maxSpin);
  const FloatW overCap = greaterW(vx * vx + vy * vy, maxSpeed * maxSpeed);
  const FloatW h = splatW(context.h);
  const FloatW angle = spin * h;
  const FloatW qc = c[6] - angle * c[7];
  const FloatW qs = c[7] + angle * c[6];
  const FloatW len = sqrtW(qc * qc + qs * qs);
  // normalize's rare lanes: an infinite length (its hypot) or one at most the tolerance (the
  // identity). A NaN is neither: it divides, as in the scalar code.
  const FloatW tolerance = splatW(normalizeTolerance<float>);
  const FloatW rare = orW(orW(greaterW(len, splatW(std::numeric_limits<float>::max())), greaterW(tolerance, len)),
                          equalW(len, tolerance));
  if (anyNonZeroW(orW(rare, overCap))) {
    return false;
  }
  float* tails[lanes];
  for (std::size_t i = 0; i < lanes; ++i) {
    tails[i] = rows[i] + 4;
  }
  storeRowHeadsW(rows, vx, vy, spin, c[3]);
  storeRowHeadsW(tails, c[4] + vx * h, c[5] + vy * h, qc / len, qs / len);
  return true;
}

} // namespace

void integratePositions(WorldState& w, const StepContext& context) {
  w.parallelFor(static_cast<std::uint32_t>(w.sims.size()), 256, [&](std::uint32_t begin, std::uint32_t end) {
    constexpr auto lanes = static_cast<std::uint32_t>(solver::simdWidth);
    std::uint32_t i = begin;
    for (; i + lanes <= end; i += lanes) {
      if (!integrateBodiesWide(w, i, context)) {
        for (std::uint32_t k = i; k < i + lanes; ++k) {
          integrateBody(w.states[k], w.sims[k], context);
        }
      }
    }
    for (; i < end; ++i) {
      integrateBody(w.states[i], w.sims[i], context);
    }
  });
}

StepContext makeStepContext(const WorldState& w, float dt, int substeps) {
  StepContext context;
  context.dt = dt;
  context.substeps = substeps;
  context.h = dt / static_cast<float>(substeps);
  context.inverseH = 1.0f / context.h;
  context.maxLinearSpeed = w.def.maxLinearSpeed;
  context.maxAngularSpeed = maxRotationPerSubstep * context.inverseH;
  // Joints are held at the world's stiffness unless they have their own (joint.cpp).
  context.jointSoftness = jointSoftnessFor(w.def.jointHertz, w.def.jointDampingRatio, context);
  context.jointSoftness.maxBias = w.def.maxJointPushSpeed;
  context.warmStarting = w.def.enableWarmStarting;
  return context;
}

namespace {

/// The soft step's stages, in the order they run: reading the list is reading the algorithm
/// (Box2D v3's solver stages are the model). Each stage runs its blocks of work on the task
/// runner (parallelFor); the stages of the substep loop run once a substep.
struct StageStep {
  const char* name;
  void (*run)(WorldState& w, const StepContext& context);
  float StepProfile::*time; ///< where the profile adds its wall time
};

constexpr StageStep beforeSubsteps[] = {
    {"prepare",
     [](WorldState& w, const StepContext& c) {
       buildSolverBodies(w);
       prepareConstraints(w, c); // colours the joints with the contacts and prepares both
     },
     &StepProfile::prepare},
};

constexpr StageStep eachSubstep[] = {
    {"integrate velocities", integrateVelocities, &StepProfile::integrateVelocities},
    {"warm start", [](WorldState& w, const StepContext&) { warmStartConstraints(w); }, &StepProfile::warmStart},
    {"solve", [](WorldState& w, const StepContext& c) { solveConstraints(w, c, true); },
     &StepProfile::solveConstraints},
    {"integrate positions", integratePositions, &StepProfile::integratePositions},
    {"relax", [](WorldState& w, const StepContext& c) { solveConstraints(w, c, false); }, &StepProfile::relax},
};

constexpr StageStep afterSubsteps[] = {
    {"store impulses",
     [](WorldState& w, const StepContext& c) {
       storeImpulses(w);
       finishJointSims(w, c);
     },
     &StepProfile::storeImpulses},
};

template <std::size_t N>
void runStages(const StageStep (&stages)[N], WorldState& w, const StepContext& context, solver::StageClock& clock) {
  for (const StageStep& s : stages) {
    s.run(w, context);
    w.profile.*s.time += clock.lap();
  }
}

} // namespace

void solve(WorldState& w, float dt) {
  const StepContext context = makeStepContext(w, dt, w.def.substeps);
  solver::StageClock clock;
  runStages(beforeSubsteps, w, context, clock);
  for (int substep = 0; substep < context.substeps; ++substep) {
    runStages(eachSubstep, w, context, clock);
  }
  runStages(afterSubsteps, w, context, clock);
}

} // namespace impetus::rigid2d::detail
