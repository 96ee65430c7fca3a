// Quat<T>: a quaternion q = w + xi + yj + zk (appendix C's [n, v], n = w, v = (x, y, z)).
// Unit quaternions represent rotations: rotate(q, v) = q [0, v] q*. q and -q are the same
// rotation.
#pragma once

#include <impetus/error.hpp>
#include <impetus/math/mat33.hpp>

namespace impetus {

/// Euler angles in the z-y-x (yaw, pitch, roll) aerospace order, radians: the body is yawed
/// about z, then pitched about the new y, then rolled about the newest x; R = Rz(yaw) Ry(pitch) Rx(roll).
template <Real T> struct EulerAngles {
  T yaw{};
  T pitch{};
  T roll{};
};

template <Real T> struct Quat {
  T w{};
  T x{};
  T y{};
  T z{};

  /// The zero quaternion (the book's default too; use identity() for "no rotation").
  constexpr Quat() noexcept = default;
  constexpr Quat(T w_, T x_, T y_, T z_) noexcept : w(w_), x(x_), y(y_), z(z_) {}
  constexpr Quat(T scalar_, const Vec3<T>& vector_) noexcept : w(scalar_), x(vector_.x), y(vector_.y), z(vector_.z) {}

  [[nodiscard]] static constexpr Quat identity() noexcept { return {T(1), T(0), T(0), T(0)}; }

  /// A rotation of `angle` radians about `axis` (any length but zero). Throws impetus::Error
  /// for a zero or non-finite axis.
  [[nodiscard]] static Quat fromAxisAngle(const Vec3<T>& axis, T angle);

  /// The rotation R = Rz(yaw) Ry(pitch) Rx(roll), radians (the book's MakeQFromEulerAngles,
  /// which takes degrees in the order roll, pitch, yaw).
  [[nodiscard]] static Quat fromEuler(T yaw, T pitch, T roll) noexcept;

  /// The unit quaternion of a rotation matrix (Shepperd's method: stable for every rotation).
  /// Throws impetus::Error when `m` is not finite.
  [[nodiscard]] static Quat fromMat33(const Mat33<T>& m);

  [[nodiscard]] constexpr T scalar() const noexcept { return w; }
  [[nodiscard]] constexpr Vec3<T> vector() const noexcept { return {x, y, z}; }

  constexpr Quat& operator+=(const Quat& q) noexcept {
    w += q.w;
    x += q.x;
    y += q.y;
    z += q.z;
    return *this;
  }
  constexpr Quat& operator-=(const Quat& q) noexcept {
    w -= q.w;
    x -= q.x;
    y -= q.y;
    z -= q.z;
    return *this;
  }
  constexpr Quat& operator*=(T s) noexcept {
    w *= s;
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr Quat& operator/=(T s) noexcept {
    w /= s;
    x /= s;
    y /= s;
    z /= s;
    return *this;
  }

  friend constexpr bool operator==(const Quat&, const Quat&) noexcept = default;
};

template <Real T> [[nodiscard]] constexpr Quat<T> operator-(const Quat<T>& q) noexcept {
  return {-q.w, -q.x, -q.y, -q.z};
}
template <Real T> [[nodiscard]] constexpr Quat<T> operator+(Quat<T> a, const Quat<T>& b) noexcept { return a += b; }
template <Real T> [[nodiscard]] constexpr Quat<T> operator-(Quat<T> a, const Quat<T>& b) noexcept { return a -= b; }
template <Real T> [[nodiscard]] constexpr Quat<T> operator*(Quat<T> q, T s) noexcept { return q *= s; }
template <Real T> [[nodiscard]] constexpr Quat<T> operator*(T s, Quat<T> q) noexcept { return q *= s; }
template <Real T> [[nodiscard]] constexpr Quat<T> operator/(Quat<T> q, T s) noexcept { return q /= s; }

/// Hamilton product [w1 w2 - v1.v2, w1 v2 + w2 v1 + v1 x v2]. Not commutative.
template <Real T> [[nodiscard]] constexpr Quat<T> operator*(const Quat<T>& a, const Quat<T>& b) noexcept {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

/// q [0, v]: the book's Quaternion * Vector.
template <Real T> [[nodiscard]] constexpr Quat<T> operator*(const Quat<T>& q, const Vec3<T>& v) noexcept {
  return q * Quat<T>(T(0), v);
}

/// [0, v] q: the book's Vector * Quaternion.
template <Real T> [[nodiscard]] constexpr Quat<T> operator*(const Vec3<T>& v, const Quat<T>& q) noexcept {
  return Quat<T>(T(0), v) * q;
}

template <Real T> [[nodiscard]] constexpr T dot(const Quat<T>& a, const Quat<T>& b) noexcept {
  return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}
template <Real T> [[nodiscard]] constexpr T lengthSquared(const Quat<T>& q) noexcept { return dot(q, q); }
template <Real T> [[nodiscard]] T length(const Quat<T>& q) noexcept { return std::sqrt(lengthSquared(q)); }

/// q / |q|; the zero quaternion has no direction and normalizes to the identity.
template <Real T> [[nodiscard]] Quat<T> normalize(const Quat<T>& q) noexcept {
  T len = length(q);
  if (std::isinf(len)) { // |q|^2 overflowed: rescale by the largest component first
    const T big = std::fmax(std::fmax(std::abs(q.w), std::abs(q.x)), std::fmax(std::abs(q.y), std::abs(q.z)));
    len = big * length(q / big);
  }
  if (len <= normalizeTolerance<T>) {
    return Quat<T>::identity();
  }
  return q / len;
}

/// [w, -v] (the book's operator~). For a unit quaternion this is the inverse rotation.
template <Real T> [[nodiscard]] constexpr Quat<T> conjugate(const Quat<T>& q) noexcept {
  return {q.w, -q.x, -q.y, -q.z};
}

/// q^-1 = q* / |q|^2, so that q q^-1 = 1. Throws impetus::Error for the zero quaternion.
template <Real T> [[nodiscard]] Quat<T> inverse(const Quat<T>& q) {
  const T n2 = lengthSquared(q);
  if (n2 == T(0) || !std::isfinite(n2)) {
    throwInvalid("quaternion norm squared", static_cast<double>(n2), "quaternion has no inverse");
  }
  return conjugate(q) / n2;
}

/// v rotated by the unit quaternion q: the vector part of q [0, v] q* (the book's QVRotate).
/// Computed as v + 2w (u x v) + 2 u x (u x v), u = q's vector part: 15 multiplies, not 32.
template <Real T> [[nodiscard]] constexpr Vec3<T> rotate(const Quat<T>& q, const Vec3<T>& v) noexcept {
  const Vec3<T> u = q.vector();
  const Vec3<T> t = T(2) * cross(u, v);
  return v + q.w * t + cross(u, t);
}

/// v rotated by the inverse of the unit quaternion q (world to body when q is body to world).
template <Real T> [[nodiscard]] constexpr Vec3<T> inverseRotate(const Quat<T>& q, const Vec3<T>& v) noexcept {
  return rotate(conjugate(q), v);
}

/// The rotation angle of a unit quaternion in [0, 2 pi] (the book's QGetAngle, with w clamped
/// to [-1, 1] so rounding never makes acos return NaN).
template <Real T> [[nodiscard]] T angle(const Quat<T>& q) noexcept {
  return T(2) * std::acos(std::fmax(T(-1), std::fmin(T(1), q.w)));
}

/// The unit rotation axis (the book's QGetAxis); the zero vector for the identity rotation.
template <Real T> [[nodiscard]] Vec3<T> axis(const Quat<T>& q) noexcept { return normalize(q.vector()); }

/// The rotation matrix of a unit quaternion.
template <Real T> [[nodiscard]] constexpr Mat33<T> toMat33(const Quat<T>& q) noexcept {
  const T xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  const T xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  const T wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  return {T(1) - T(2) * (yy + zz), T(2) * (xy - wz), T(2) * (xz + wy), T(2) * (xy + wz),       T(1) - T(2) * (xx + zz),
          T(2) * (yz - wx),        T(2) * (xz - wy), T(2) * (yz + wx), T(1) - T(2) * (xx + yy)};
}

/// Yaw, pitch and roll (z-y-x) of a unit quaternion, radians; pitch in [-pi/2, pi/2], yaw and
/// roll in (-pi, pi]. At pitch = +-90 degrees (gimbal lock) only yaw -/+ roll is defined: roll
/// is set to 0 and yaw carries the whole heading, so fromEuler(toEuler(q)) is q's rotation.
template <Real T> [[nodiscard]] EulerAngles<T> toEuler(const Quat<T>& q) noexcept {
  const Mat33<T> r = toMat33(q);
  const T r11 = r(0, 0), r21 = r(1, 0), r31 = r(2, 0);
  const T cosPitch = std::hypot(r11, r21);
  EulerAngles<T> e;
  e.pitch = std::atan2(-r31, cosPitch);
  // Below this cos(pitch) the yaw and roll atan2 arguments are mostly rounding noise; the
  // sqrt(epsilon) threshold balances that noise against the error of assuming cos(pitch) = 0.
  if (cosPitch > std::sqrt(std::numeric_limits<T>::epsilon())) {
    e.yaw = std::atan2(r21, r11);
    e.roll = std::atan2(r(2, 1), r(2, 2));
  } else {
    e.roll = T(0);
    e.yaw = std::atan2(-r(0, 1), -r31 * r(0, 2));
  }
  return e;
}

/// Spherical linear interpolation between unit quaternions along the shorter arc, t in [0, 1].
/// Falls back to normalized linear interpolation when the two are nearly parallel.
template <Real T> [[nodiscard]] Quat<T> slerp(const Quat<T>& a, Quat<T> b, T t) noexcept {
  T cosTheta = dot(a, b);
  if (cosTheta < T(0)) {
    b = -b;
    cosTheta = -cosTheta;
  }
  if (cosTheta > T(1) - T(64) * std::numeric_limits<T>::epsilon()) {
    return normalize(a + (b - a) * t);
  }
  const T theta = std::acos(std::fmin(cosTheta, T(1)));
  const T sinTheta = std::sin(theta);
  return a * (std::sin((T(1) - t) * theta) / sinTheta) + b * (std::sin(t * theta) / sinTheta);
}

/// dq/dt for an angular velocity given in the body frame: q' = 1/2 q [0, w_body]. This is the
/// form the rigid-body integrators use, since they keep w in body axes (ch. 11-12).
template <Real T> [[nodiscard]] constexpr Quat<T> derivative(const Quat<T>& q, const Vec3<T>& omegaBody) noexcept {
  return (q * omegaBody) * T(0.5);
}

/// dq/dt for an angular velocity given in the world frame: q' = 1/2 [0, w_world] q.
template <Real T>
[[nodiscard]] constexpr Quat<T> derivativeWorld(const Quat<T>& q, const Vec3<T>& omegaWorld) noexcept {
  return (omegaWorld * q) * T(0.5);
}

/// One explicit step q + q' dt with a body-frame angular velocity, renormalized.
template <Real T> [[nodiscard]] Quat<T> integrate(const Quat<T>& q, const Vec3<T>& omegaBody, T dt) noexcept {
  return normalize(q + derivative(q, omegaBody) * dt);
}

template <Real T> [[nodiscard]] bool isFinite(const Quat<T>& q) noexcept {
  return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

template <Real T> Quat<T> Quat<T>::fromAxisAngle(const Vec3<T>& axis, T angle) {
  const T len = std::hypot(axis.x, axis.y, axis.z);
  if (!(len > normalizeTolerance<T>) || !std::isfinite(len)) {
    throwInvalid("rotation axis length", static_cast<double>(len), "axis must be finite and non-zero");
  }
  if (!std::isfinite(angle)) {
    throwInvalid("rotation angle", static_cast<double>(angle), "must be finite");
  }
  const T half = angle * T(0.5);
  return {std::cos(half), axis * (std::sin(half) / len)};
}

template <Real T> Quat<T> Quat<T>::fromEuler(T yaw, T pitch, T roll) noexcept {
  const T cy = std::cos(yaw * T(0.5)), sy = std::sin(yaw * T(0.5));
  const T cp = std::cos(pitch * T(0.5)), sp = std::sin(pitch * T(0.5));
  const T cr = std::cos(roll * T(0.5)), sr = std::sin(roll * T(0.5));
  return {cy * cp * cr + sy * sp * sr, cy * cp * sr - sy * sp * cr, cy * sp * cr + sy * cp * sr,
          sy * cp * cr - cy * sp * sr};
}

template <Real T> Quat<T> Quat<T>::fromMat33(const Mat33<T>& m) {
  if (!isFinite(m)) {
    throwInvalid("rotation matrix", std::nan(""), "elements must be finite");
  }
  // Shepperd: pivot on the largest of w^2, x^2, y^2, z^2 so the square root is never of a
  // small, cancellation-prone number.
  const T tr = trace(m);
  Quat q;
  if (tr >= m(0, 0) && tr >= m(1, 1) && tr >= m(2, 2)) {
    const T s = std::sqrt(T(1) + tr) * T(2); // 4w
    q = {s * T(0.25), (m(2, 1) - m(1, 2)) / s, (m(0, 2) - m(2, 0)) / s, (m(1, 0) - m(0, 1)) / s};
  } else if (m(0, 0) >= m(1, 1) && m(0, 0) >= m(2, 2)) {
    const T s = std::sqrt(T(1) + m(0, 0) - m(1, 1) - m(2, 2)) * T(2); // 4x
    q = {(m(2, 1) - m(1, 2)) / s, s * T(0.25), (m(0, 1) + m(1, 0)) / s, (m(0, 2) + m(2, 0)) / s};
  } else if (m(1, 1) >= m(2, 2)) {
    const T s = std::sqrt(T(1) + m(1, 1) - m(0, 0) - m(2, 2)) * T(2); // 4y
    q = {(m(0, 2) - m(2, 0)) / s, (m(0, 1) + m(1, 0)) / s, s * T(0.25), (m(1, 2) + m(2, 1)) / s};
  } else {
    const T s = std::sqrt(T(1) + m(2, 2) - m(0, 0) - m(1, 1)) * T(2); // 4z
    q = {(m(1, 0) - m(0, 1)) / s, (m(0, 2) + m(2, 0)) / s, (m(1, 2) + m(2, 1)) / s, s * T(0.25)};
  }
  return normalize(q);
}

using Quatf = Quat<float>;
using Quatd = Quat<double>;
using EulerAnglesf = EulerAngles<float>;
using EulerAnglesd = EulerAngles<double>;

} // namespace impetus
