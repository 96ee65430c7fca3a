// A pendulum bob on a rod: mass properties and a rotation with Impetus.
#include <impetus/impetus.hpp>

#include <cstdio>

int main() {
  using namespace impetus;

  // A 2 kg solid ball (radius 5 cm) at the end of a 0.3 kg, 0.5 m rod hanging along -z
  // from a pivot at the origin.
  const MassPart parts[] = {
      {.mass = 2.0, .position = {0.0, 0.0, -0.55}, .inertia = inertiaTensor(SolidSphere{0.05}, 2.0)},
      {.mass = 0.3, .position = {0.0, 0.0, -0.25}, .inertia = inertiaTensor(Rod{0.5}, 0.3)},
  };
  const MassProperties3 pendulum = combine(parts);

  // Moment of inertia about the pivot's x axis: parallel-axis transfer from the centre of mass.
  const Mat33d aboutPivot = parallelAxis(pendulum.inertia, pendulum.mass, pendulum.centerOfMass);
  const double period =
      2.0 * pi<double> *
      std::sqrt(aboutPivot(0, 0) / (pendulum.mass * constants::standardGravity * length(pendulum.centerOfMass)));

  // Swing it 30 degrees about x and see where the centre of mass goes.
  const Quatd swing = Quatd::fromAxisAngle(Vec3d::unitX(), degToRad(30.0));
  const Vec3d swung = rotate(swing, pendulum.centerOfMass);

  std::printf("mass %.3f kg, centre of mass z = %.4f m\n", pendulum.mass, pendulum.centerOfMass.z);
  std::printf("I about the pivot %.5f kg m^2, small-swing period %.4f s\n", aboutPivot(0, 0), period);
  std::printf("swung 30 degrees: centre of mass at (%.4f, %.4f, %.4f) m\n", swung.x, swung.y, swung.z);
  return 0;
}
