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
#include "solver/stage_clock.hpp"

#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <cmath>

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
  for (std::uint32_t i = 0; i < n; ++i) {
    Body& b = w.bodies[w.awakeBodies[i]];
    b.solverIndex = i;
    w.bodyInfo[w.awakeBodies[i]] = {i, b.inverseMass, b.inverseInertia, b.center - b.transform.p};
  }
  w.states.resize(n + 2);
  w.sims.resize(n);
  w.states[n] = BodyState{}; // the static state: at rest, never written
  // states[n + 1]: where the wide contact solve writes its static lanes (never read), so that
  // its stores need no branch.
  const Vec2f gravity = w.def.gravity;
  w.parallelFor(n, 256, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t i = begin; i < end; ++i) {
      const Body& b = w.bodies[w.awakeBodies[i]];
      w.states[i] = BodyState{b.linearVelocity, b.angularVelocity, 0.0f, {}, Rot2f::identity()};
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

void integratePositions(WorldState& w, const StepContext& context) {
  const float h = context.h;
  w.parallelFor(static_cast<std::uint32_t>(w.sims.size()), 256, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t i = begin; i < end; ++i) {
      BodyState& s = w.states[i];
      const BodySim& sim = w.sims[i];
      if (sim.dynamic) {
        capVelocity(s, context, sim.allowFastRotation);
      }
      s.dp += s.v * h;
      const float angle = s.w * h;
      s.dq = normalize(Rot2f{s.dq.c - angle * s.dq.s, s.dq.s + angle * s.dq.c});
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
