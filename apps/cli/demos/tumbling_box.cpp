// The tennis-racket (Dzhanibekov) effect: a box spun about its intermediate principal axis
// flips over and over with no torque on it. Euler's equations in body axes (ch. 1),
//   I w' = -w x (I w),   q' = 1/2 q [0, w],
// integrated with classic RK4 on the whole state. Kinetic energy and the world-frame angular
// momentum are conserved by the physics, so their drift measures the integration error.
#include "demos/demos.hpp"

#include <impetus/core/solid.hpp>
#include <impetus/math/quat.hpp>

#include <fmt/core.h>

#include <vector>

namespace impetus::cli {
namespace {

struct State {
  Quatd q;
  Vec3d w; // body-frame angular velocity, rad/s
};

struct Rate {
  Quatd dq;
  Vec3d dw;
};

Rate rate(const State& s, const Vec3d& inertia) {
  const Vec3d h = hadamard(inertia, s.w);
  const Vec3d torqueFree = -cross(s.w, h);
  return {derivative(s.q, s.w), {torqueFree.x / inertia.x, torqueFree.y / inertia.y, torqueFree.z / inertia.z}};
}

State advance(const State& s, const Rate& r, double h) { return {s.q + r.dq * h, s.w + r.dw * h}; }

State rk4(const State& s, const Vec3d& inertia, double h) {
  const Rate k1 = rate(s, inertia);
  const Rate k2 = rate(advance(s, k1, h / 2), inertia);
  const Rate k3 = rate(advance(s, k2, h / 2), inertia);
  const Rate k4 = rate(advance(s, k3, h), inertia);
  State next{s.q + (k1.dq + k2.dq * 2.0 + k3.dq * 2.0 + k4.dq) * (h / 6),
             s.w + (k1.dw + k2.dw * 2.0 + k3.dw * 2.0 + k4.dw) * (h / 6)};
  next.q = normalize(next.q);
  return next;
}

} // namespace

int demoTumblingBox(const DemoOptions& options) {
  const double mass = 0.5;           // kg
  const Box box{{0.16, 0.08, 0.02}}; // a phone-sized slab, m
  const Mat33d tensor = inertiaTensor(box, mass);
  const Vec3d inertia{tensor(0, 0), tensor(1, 1), tensor(2, 2)}; // principal: Ixx < Iyy < Izz here? see below
  // x is the long edge so Ixx is smallest; z is the thin edge so Izz is largest; y is intermediate.
  State s{Quatd::identity(), {0.01, 4.0 * pi<double>, 0.01}};
  const auto energy = [&](const State& st) { return 0.5 * dot(st.w, hadamard(inertia, st.w)); };
  const auto momentum = [&](const State& st) { return rotate(st.q, hadamard(inertia, st.w)); };
  const double e0 = energy(s);
  const Vec3d l0 = momentum(s);

  const double dt = 1e-3;
  const int steps = 10000;
  fmt::print("box {} x {} x {} m, {} kg: I = ({:.3e}, {:.3e}, {:.3e}) kg m^2\n", box.size.x, box.size.y, box.size.z,
             mass, inertia.x, inertia.y, inertia.z);
  fmt::print("spun at 2 rev/s about y (intermediate axis) with a 0.01 rad/s wobble; RK4, dt = 1 ms\n\n");
  fmt::print("{:>6} {:>10} {:>10} {:>10} {:>14}\n", "t s", "wx", "wy", "wz", "body y . up");
  std::vector<std::vector<double>> rows;
  int flips = 0;
  double previousY = s.w.y;
  double maxEnergyError = 0.0;
  double maxMomentumError = 0.0;
  for (int i = 1; i <= steps; ++i) {
    s = rk4(s, inertia, dt);
    if ((s.w.y > 0) != (previousY > 0)) {
      ++flips;
    }
    previousY = s.w.y;
    maxEnergyError = std::fmax(maxEnergyError, std::abs(energy(s) - e0) / e0);
    maxMomentumError = std::fmax(maxMomentumError, length(momentum(s) - l0) / length(l0));
    if (i % 10 == 0) {
      rows.push_back({i * dt, s.w.x, s.w.y, s.w.z, s.q.w, s.q.x, s.q.y, s.q.z});
    }
    if (i % 500 == 0) {
      fmt::print("{:>6.2f} {:>10.4f} {:>10.4f} {:>10.4f} {:>14.4f}\n", i * dt, s.w.x, s.w.y, s.w.z,
                 rotate(s.q, Vec3d::unitY()).y);
    }
  }
  fmt::print("\nthe spin axis reversed {} times in {} s\n", flips, steps * dt);
  fmt::print("largest relative drift: kinetic energy {:.2e}, angular momentum {:.2e}\n", maxEnergyError,
             maxMomentumError);
  writeCsv(options, "tumbling-box.csv", "t,wx,wy,wz,qw,qx,qy,qz", rows);
  return 0;
}

} // namespace impetus::cli
