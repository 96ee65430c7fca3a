#!/usr/bin/env python3
"""Writes the seed corpora of the 3D harnesses: tests/fuzz/corpus/hull3d/ and corpus/manifold3d/.

Each seed is the bytes the harness's Reader (fuzz_support.hpp) decodes: single bytes for choices,
and 4-byte big-endian floats (read by Reader::u32 / bounded(): a finite float within the bound is
taken as it is). Run from anywhere: python3 tests/fuzz/make_seeds_3d.py
Every seed must pass its harness (the replay test feeds them): the inputs that show open findings
are under regressions/<harness>/open-* instead.
"""
import os
import random
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def f(*values):
    return b"".join(struct.pack(">f", v) for v in values)


def b(*values):
    return bytes(values)


def write(harness, name, data):
    folder = os.path.join(HERE, "corpus", harness)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as out:
        out.write(data)


def noise(seed, count):
    rng = random.Random(seed)
    return bytes(rng.randrange(256) for _ in range(count))


# hull3d: byte 0 the count (4 + b % 77), byte 1 the mode (bits 0-3 the scale 10^(k - 4), bits
# 4-6 the pattern, bit 7 a far offset), byte 2 the cap (4 + b % 61, or from 240 one out of range).
def hull(count, pattern, k, cap, far=False):
    return b(count - 4, k | (pattern << 4) | (0x80 if far else 0), cap - 4 if cap >= 4 else 240 + cap)


UNIT = 4  # scale 10^0 = 1 m
cube = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
write("hull3d", "tetrahedron", hull(4, 0, UNIT, 64) + f(0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1))
write("hull3d", "cube_with_inner_and_face_points",
      hull(15, 0, UNIT, 64) + b"".join(f(*p) for p in cube) + f(0, 0, 0, 0.5, 0.5, 0.5, 1, 0, 0, 0, -1, 0, 0, 0, 1,
                                                                  -1, 0.25, -0.5, 0.3, 1, 0.2))
# Pattern 1: byte per point, odd = a copy of an earlier point.
dup = b""
for i, p in enumerate(cube):
    dup += b(0) + f(*p)
    dup += b(1 + 2 * i)  # a copy of point (2i+1)>>1 % (index) -> an earlier corner
write("hull3d", "cube_with_duplicates", hull(16, 1, UNIT, 64) + dup)
# Pattern 2: axis, level, off byte, then the points (the axis coordinate replaced).
write("hull3d", "coplanar_axis_plane", hull(10, 2, UNIT, 64) + b(1) + f(0.25) + b(0) + noise(1, 120))
write("hull3d", "thin_slab_one_point_off", hull(10, 2, UNIT, 64) + b(2) + f(0.0) + b(1 + 2 * 2) + noise(2, 120))
# Pattern 3: rotation (4 floats), origin, thickness byte, which byte, then u, v (and h).
write("hull3d", "turned_plane_rounding", hull(20, 3, UNIT, 64) + f(0.9, 0.3, 0.2, 0.1) + f(0.5, -0.5, 2) + b(13) +
      b(1) + noise(3, 240))
write("hull3d", "turned_plane_thick", hull(20, 3, UNIT, 64) + f(0.9, 0.3, 0.2, 0.1) + f(0, 0, 0) + b(1) + b(1) +
      noise(4, 240))
# Pattern 4: centre, then per point a direction and a depth byte; the cap below the count.
write("hull3d", "sphere_80_points_cap_16", hull(80, 4, UNIT, 16) + f(0, 0, 0) + noise(5, 80 * 13))
write("hull3d", "sphere_40_points_cap_64", hull(40, 4, UNIT, 64) + f(0.1, 0.2, 0.3) + noise(60, 40 * 13))
# Pattern 5: form byte (bit 0 turned, bit 1 moved, span 2 + (form >> 2) % 4), then 3 bytes a point.
write("hull3d", "lattice_3x3x3", hull(60, 5, UNIT, 64) + b(1 << 2) + noise(12, 180))
write("hull3d", "lattice_turned", hull(60, 5, UNIT, 64) + b(1 | 2 | (2 << 2)) + f(0.7, 0.1, -0.5, 0.3) +
      f(0.1, 0.2, 0.3) + noise(7, 180))
# Pattern 6: rotation, half height, radius, then an angle a point.
write("hull3d", "prism_12", hull(12, 6, UNIT, 64) + f(1, 0, 0, 0) + f(0.5, 1.0) +
      f(*[i * 0.5235988 for i in range(12)]))
# Pattern 7: a kind byte a point (below 24 raw bits, below 48 a special value in one coordinate).
# Pattern 7: a kind byte a point (below 24 raw bits; 24 to 47 the special value (kind - 24) % 10
# of fuzz_hull3d.cpp's list in coordinate kind % 3; above, an ordinary point).
write("hull3d", "nan_point", hull(5, 7, UNIT, 64) + b(60) + f(0, 0, 0) + b(60) + f(1, 0, 0) + b(60) + f(0, 1, 0) +
      b(60) + f(0, 0, 1) + b(24) + f(1, 1, 1))
write("hull3d", "huge_coordinates", hull(6, 7, 14, 64) + b"".join(b(kind) + f(*p) for kind, p in
                                                                    zip((27, 29, 30, 60, 60, 60), cube)))
write("hull3d", "cap_out_of_range", hull(8, 0, UNIT, 3) + b"".join(f(*p) for p in cube))
write("hull3d", "far_from_origin", hull(8, 0, 2, 64, far=True) + b"".join(f(*p) for p in cube) + f(1.5, -0.7, 0.2))
write("hull3d", "tiny_scale", hull(8, 0, 0, 64) + noise(8, 96))
write("hull3d", "large_scale", hull(30, 0, 12, 8) + noise(9, 360))


# manifold3d: byte 0 the kinds (low nibble A, high B: 0 sphere, 1 capsule, 2 hull), byte 1 the
# scale (bits 0-1: 0.05, 0.5, 2, 0.5 m) and B's pose (bits 2-3: near A, A's pose, nearly
# coincident, anywhere). Then A's and B's shapes, A's pose, B's pose, the ray.
def pair(kind_a, kind_b, scale, pose):
    return b(kind_a | (kind_b << 4), scale | (pose << 2))


IDENTITY = f(1, 0, 0, 0)


def sphere(center, radius):
    return f(*center, radius)


def capsule(c1, c2, radius):
    return f(*c1, *c2, radius)


def box(half, center=None, rotation=None):
    form = 1 | (2 if center else 0) | (4 if rotation else 0)
    return b(form) + f(*half) + (f(*center) if center else b"") + (f(*rotation) if rotation else b"")


def cloud(points):
    return b((len(points) - 4) << 1) + b"".join(f(*p) for p in points)


def ray(origin_offset, target_offset, k, max_fraction_form=0):
    # Aimed form (bit 0 clear); (form >> 1) % 8: 0 maxFraction 1, 2 maxFraction 0, 4 no translation.
    return b(max_fraction_form << 1) + f(*origin_offset) + f(*target_offset) + f(k)


NEAR, SAME, COINCIDENT, ANYWHERE = 0, 1, 2, 3
write("manifold3d", "box_on_box", pair(2, 2, 1, NEAR) + box((0.5, 0.5, 0.5)) + box((0.5, 0.5, 0.5)) +
      f(0, 0, 0) + IDENTITY + f(0, 0.99, 0) + IDENTITY + ray((0, 2.5, 0), (0, 0, 0), 1))
write("manifold3d", "box_on_turned_box", pair(2, 2, 1, NEAR) + box((1, 0.25, 1)) +
      box((0.3, 0.3, 0.3), None, (0.92388, 0, 0.382683, 0)) + f(1, -2, 3) + IDENTITY + f(0.2, 0.54, -0.1) +
      f(0.9, 0.1, 0.3, 0.2) + ray((1.5, 1.5, -1), (0, 0, 0), 1.5))
write("manifold3d", "box_edge_on_box_edge", pair(2, 2, 1, NEAR) + box((0.5, 0.5, 0.5)) + box((0.5, 0.5, 0.5)) +
      f(0, 0, 0) + f(0.92388, 0.382683, 0, 0) + f(0, 1.2, 0) + f(0.92388, 0, 0, 0.382683) +
      ray((2, 0.1, 0.1), (0, 0, 0), 1))
tetra = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (0.25, 0.25, 0.25)]
write("manifold3d", "computed_hull_on_box", pair(2, 2, 1, NEAR) + cloud(tetra) + box((0.5, 0.5, 0.5)) +
      f(0, 0, 0) + IDENTITY + f(0.2, -0.48, 0.2) + f(0.99, 0.1, 0, 0) + ray((-1, -1, -1), (0.1, 0.1, 0.1), 2))
write("manifold3d", "sphere_on_box", pair(2, 0, 1, NEAR) + box((1, 0.5, 1)) + sphere((0, 0, 0), 0.5) +
      f(0, 0, 0) + IDENTITY + f(0.3, 1.005, 0) + IDENTITY + ray((0, 3, 0), (0, 0, 0), 1))
write("manifold3d", "sphere_inside_box", pair(2, 0, 1, NEAR) + box((1, 1, 1)) + sphere((0, 0, 0), 0.25) +
      f(0, 0, 0) + IDENTITY + f(0.6, 0.1, 0) + IDENTITY + ray((0, 0, 0), (0, 0, 0), 1, 1))
write("manifold3d", "capsule_lying_on_box", pair(2, 1, 1, NEAR) + box((1, 0.5, 1)) +
      capsule((-0.5, 0, 0), (0.5, 0, 0), 0.2) + f(0, 0, 0) + IDENTITY + f(0, 0.71, 0.3) + IDENTITY +
      ray((0, 2, 0.3), (0, 0, 0.3), 1))
write("manifold3d", "capsule_across_box_edge", pair(2, 1, 1, NEAR) + box((0.5, 0.5, 0.5)) +
      capsule((0, -0.5, 0), (0, 0.5, 0), 0.1) + f(0, 0, 0) + IDENTITY + f(0.61, 0.2, 0.61) +
      f(0.92388, 0.382683, 0, 0) + ray((2, 0, 2), (0, 0, 0), 1))
write("manifold3d", "capsules_side_by_side", pair(1, 1, 1, NEAR) + capsule((-1, 0, 0), (1, 0, 0), 0.25) +
      capsule((-0.5, 0, 0), (1, 0, 0), 0.25) + f(0, 0, 0) + IDENTITY + f(0, 0.51, 0) + IDENTITY +
      ray((0, 2, 0), (0, 0, 0), 1))
write("manifold3d", "capsules_crossed", pair(1, 1, 1, NEAR) + capsule((-1, 0, 0), (1, 0, 0), 0.25) +
      capsule((0, 0, -1), (0, 0, 1), 0.25) + f(0, 0, 0) + IDENTITY + f(0, 0.49, 0) + IDENTITY +
      ray((0, -2, 0), (0, 0, 0), 1))
write("manifold3d", "capsule_and_sphere", pair(1, 0, 1, NEAR) + capsule((-1, 0, 0), (1, 0, 0), 0.25) +
      sphere((0, 0, 0), 0.5) + f(0, 0, 0) + f(0.7071, 0, 0.7071, 0) + f(1.2, 0.5, 0.1) + IDENTITY +
      ray((2, 2, 2), (0, 0, 0), 1))
write("manifold3d", "spheres_apart", pair(0, 0, 1, NEAR) + sphere((0, 0, 0), 0.5) + sphere((0, 0, 0), 0.5) +
      f(0, 0, 0) + IDENTITY + f(1.01, 0, 0) + IDENTITY + ray((-2, 0, 0), (0, 0, 0), 1))
write("manifold3d", "concentric_spheres", pair(0, 0, 1, SAME) + sphere((0, 0, 0), 0.5) + sphere((0, 0, 0), 0.3) +
      f(3, 4, 5) + IDENTITY + ray((0, 0, 0), (0, 0, 0), 1))
write("manifold3d", "boxes_nearly_coincident", pair(2, 2, 1, COINCIDENT) + box((0.5, 0.5, 0.5)) +
      box((0.5, 0.5, 0.5)) + f(-4, 2, 7) + f(0.9, 0.2, 0.3, 0.1) + b(2) + f(1e-6, -1e-6, 0, 0) +
      f(1e-6, 2e-6, -1e-6) + ray((1, 1, 1), (0, 0, 0), 1))
write("manifold3d", "small_hull_and_capsule_anywhere", pair(2, 1, 0, ANYWHERE) +
      cloud([(0, 0, 0), (0.1, 0, 0), (0, 0.1, 0), (0, 0, 0.1), (0.1, 0.1, 0.1)]) +
      capsule((0, 0, 0), (0.05, 0.05, 0), 0.01) + f(9, -9, 9) + IDENTITY + f(-9, 9, -9) + f(0.5, 0.5, 0.5, 0.5) +
      ray((0.1, 0.1, 0.1), (0, 0, 0), 1))
write("manifold3d", "large_boxes_nan_ray", pair(2, 2, 2, NEAR) + box((2, 2, 2)) + box((3, 1, 2)) + f(0, 0, 0) +
      IDENTITY + f(1, 3.5, 0) + IDENTITY + b(3 << 1) + f(0, 10, 0) + f(0, 0, 0) + f(1) + b(1) +
      struct.pack(">I", 0x7FC00000))
