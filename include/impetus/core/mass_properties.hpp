// Mass properties of composite bodies (chapter 1): centre of mass, the inertia tensor with its
// products of inertia, the parallel-axis transfer, rotated parts and principal axes.
//
// Sign convention (the book's): the tensor stores the products of inertia negated,
//   I = [[Ixx, -Ixy, -Ixz], [-Ixy, Iyy, -Iyz], [-Ixz, -Iyz, Izz]],  Ixy = integral of x y dm,
// so that the angular momentum is H = I w.
#pragma once

#include <impetus/math/mat33.hpp>
#include <impetus/math/symmetric_eigen.hpp>

#include <span>

namespace impetus {

/// Mass (kg), centre of mass (m, body frame) and inertia tensor about the centre of mass in
/// body axes (kg m^2).
struct MassProperties3 {
  double mass = 0.0;
  Vec3d centerOfMass{};
  Mat33d inertia{};
};

/// The book's PointMass: a mass at a design position with a diagonal local inertia
/// (Ixx, Iyy, Izz about its own centre, axes parallel to the body axes).
struct PointMass {
  double mass = 0.0;
  Vec3d position{};
  Vec3d localInertia{};
};

/// A part of a composite body: its mass, its centroid in the body frame, its inertia about
/// its own centroid in its own axes, and the rotation from its axes to the body axes.
struct MassPart {
  double mass = 0.0;
  Vec3d position{};
  Mat33d inertia{};
  Mat33d orientation = Mat33d::identity();
};

/// Principal moments (ascending, kg m^2) and the principal axes as the columns of a rotation
/// matrix (right-handed): inertia = axes diag(moments) axes^T.
struct PrincipalInertia {
  Vec3d moments{};
  Mat33d axes = Mat33d::identity();
};

/// Parallel-axis theorem for a scalar moment: I = I_cm + m d^2.
[[nodiscard]] double parallelAxis(double inertiaAboutCenterOfMass, double mass, double distance);

/// Tensor transfer of axes: the inertia about a point from which the centre of mass is at
/// `offset`: I = I_cm + m (|d|^2 E - d d^T). It moves the products too (Ixy += m dx dy, ...).
[[nodiscard]] Mat33d parallelAxis(const Mat33d& inertiaAboutCenterOfMass, double mass, const Vec3d& offset);

/// The tensor of a part rotated by R, in the parent axes: R I R^T.
[[nodiscard]] Mat33d rotateInertia(const Mat33d& inertia, const Mat33d& rotation);

/// Centre of mass of point masses: sum(m_i r_i) / sum(m_i). Throws impetus::Error for an empty
/// set, a negative or non-finite mass, or a zero total mass.
[[nodiscard]] Vec3d centerOfMass(std::span<const PointMass> points);

/// The book's composite procedure: total mass, centre of mass, and the tensor about it,
/// summing each point's local inertia and its transfer term. Positions stay in the caller's
/// frame; subtract the returned centre of mass to get the book's "corrected" positions.
[[nodiscard]] MassProperties3 combine(std::span<const PointMass> points);

/// The general composite: rotated parts with full tensors (R I R^T), transferred to the
/// common centre of mass. Throws impetus::Error naming the part index and the field.
[[nodiscard]] MassProperties3 combine(std::span<const MassPart> parts);

/// Principal moments and axes of a symmetric inertia tensor. Throws impetus::Error when the
/// tensor is not finite.
[[nodiscard]] PrincipalInertia principalAxes(const Mat33d& inertia);

/// Throws impetus::Error (naming `field`) unless `inertia` could belong to a real body:
/// finite, symmetric, principal moments non-negative and obeying the triangle inequality
/// I1 + I2 >= I3 (true of every mass distribution), each to `relativeTolerance` of the trace
/// (the default suits tensors computed in double; one computed in float misses by its rounding).
void requirePhysicalInertia(const Mat33d& inertia, std::string_view field, double relativeTolerance = 1e-9);

} // namespace impetus
