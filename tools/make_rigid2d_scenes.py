#!/usr/bin/env python3
"""Writes the 2D rigid-body scenes in scenes/rigid2d/ (docs/scene-format-2d.md).

The scenes are repetitive (a pyramid of 210 boxes, chains of links, ragdolls), so they are
generated; run this after changing it and commit both the script and the JSON files:

    python3 tools/make_rigid2d_scenes.py            # writes scenes/rigid2d/*.json
"""
import json
import math
import pathlib

OUT = pathlib.Path(__file__).resolve().parent.parent / "scenes" / "rigid2d"


def r(x):
    """A coordinate rounded to a readable number of digits."""
    v = round(x, 6)
    return 0 if v == 0 else (int(v) if v == int(v) else v)


def pt(x, y):
    return [r(x), r(y)]


def dump(doc):
    """One key per line at the top, one element per line in the arrays: readable and diffable."""
    lines = ["{"]
    items = list(doc.items())
    for i, (key, value) in enumerate(items):
        comma = "," if i + 1 < len(items) else ""
        if isinstance(value, list) and value:
            lines.append(f"  {json.dumps(key)}: [")
            for k, element in enumerate(value):
                tail = "," if k + 1 < len(value) else ""
                lines.append(f"    {json.dumps(element)}{tail}")
            lines.append(f"  ]{comma}")
        else:
            lines.append(f"  {json.dumps(key)}: {json.dumps(value)}{comma}")
    lines.append("}")
    return "\n".join(lines) + "\n"


def ground(half_width=50.0, y_top=0.0, name="ground", friction=0.6):
    return {"name": name, "type": "static", "position": pt(0, y_top - 1),
            "shapes": [{"type": "box", "half_extents": [r(half_width), 1], "friction": friction}]}


def pyramid():
    rows = 20
    bodies = [ground(40)]
    for i in range(rows):
        n = rows - i
        for j in range(n):
            x = (j - (n - 1) / 2) * 1.0
            bodies.append({"name": f"box{i}_{j}", "position": pt(x, 0.5 + i * 1.0),
                           "shapes": [{"type": "box", "half_extents": [0.5, 0.5], "density": 1}]})
    return {"kind": "rigid2d",
            "description": "a pyramid of 20 rows (210 boxes of 1 m, 1 kg) on static ground: it stands and falls "
                           "asleep (soft step, 4 substeps)",
            "world": {"gravity": [0, -9.81], "substeps": 4},
            "bodies": bodies}


def chain():
    links = 20
    top = 25.0
    bodies = [{"name": "pin", "type": "static", "position": pt(0, top),
               "shapes": [{"type": "circle", "radius": 0.1}]}]
    joints = []
    for i in range(links):
        bodies.append({"name": f"link{i}", "position": pt(0.5 + i, top),
                       "shapes": [{"type": "capsule", "center1": [-0.5, 0], "center2": [0.5, 0], "radius": 0.125,
                                   "density": 20, "friction": 0.2}]})
        joints.append({"type": "revolute", "body_a": "pin" if i == 0 else f"link{i - 1}", "body_b": f"link{i}",
                       "anchor": pt(i, top)})
    bodies.append({"name": "ground", "type": "static", "position": [0, -1],
                   "shapes": [{"type": "box", "half_extents": [40, 1]}]})
    return {"kind": "rigid2d",
            "description": "a chain of 20 capsule links (1 m, 5 kg each) on revolute joints, released horizontally "
                           "from a pin at 25 m: it swings down and hangs 20 m long without stretching",
            "world": {"gravity": [0, -9.81], "substeps": 4},
            "bodies": bodies, "joints": joints}


def bridge():
    planks = 20
    y = 5.0
    left = -10.0
    bodies = [ground(40),
              {"name": "post_left", "type": "static", "position": pt(left - 0.5, y / 2),
               "shapes": [{"type": "box", "half_extents": [0.5, r(y / 2)]}]},
              {"name": "post_right", "type": "static", "position": pt(-left + 0.5, y / 2),
               "shapes": [{"type": "box", "half_extents": [0.5, r(y / 2)]}]}]
    joints = []
    for i in range(planks):
        bodies.append({"name": f"plank{i}", "position": pt(left + 0.5 + i, y),
                       "shapes": [{"type": "box", "half_extents": [0.5, 0.125], "density": 20, "friction": 0.6}]})
        joints.append({"type": "revolute", "body_a": "post_left" if i == 0 else f"plank{i - 1}",
                       "body_b": f"plank{i}", "anchor": pt(left + i, y), "friction_torque": 2})
    joints.append({"type": "revolute", "body_a": f"plank{planks - 1}", "body_b": "post_right",
                   "anchor": pt(-left, y), "friction_torque": 2})
    for k, x in enumerate([-5.0, -1.0, 3.0]):
        bodies.append({"name": f"crate{k}", "position": pt(x, y + 3 + 2 * k), "angle_deg": 15 * k,
                       "shapes": [{"type": "box", "half_extents": [0.5, 0.5], "density": 50}]})
    bodies.append({"name": "boulder", "position": pt(6, y + 8),
                   "shapes": [{"type": "circle", "radius": 0.6, "density": 50}]})
    return {"kind": "rigid2d",
            "description": "a rope bridge of 20 planks on revolute joints (with a little pin friction) between two "
                           "posts; three crates and a boulder drop onto it and it sags under them",
            "world": {"gravity": [0, -9.81], "substeps": 8},
            "bodies": bodies, "joints": joints}


def newtons_cradle():
    balls = 5
    radius = 0.5
    length = 5.0
    top = 8.0
    release_deg = 40.0
    # The balls hang 10 cm apart. Touching balls would be one simultaneous contact problem, which
    # the soft step (like any simultaneous solver) answers by spreading the impulse over the row;
    # with gaps each collision is a separate equal-mass elastic impact that swaps velocities, so
    # the momentum passes along the row and the last ball leaves alone.
    gap = 0.1
    bodies = [{"name": "frame", "type": "static", "position": pt(0, top),
               "shapes": [{"type": "box", "half_extents": [3.5, 0.1]}]},
              ground(10)]
    joints = []
    for i in range(balls):
        ax = (i - (balls - 1) / 2) * (2 * radius + gap)
        if i == 0:
            a = math.radians(release_deg)
            p = (ax - length * math.sin(a), top - length * math.cos(a))
        else:
            p = (ax, top - length)
        bodies.append({"name": f"ball{i}", "position": pt(*p), "bullet": True,
                       "shapes": [{"type": "circle", "radius": radius, "density": 10, "friction": 0,
                                   "restitution": 1}]})
        joints.append({"type": "distance", "body_a": "frame", "body_b": f"ball{i}",
                       "local_anchor_a": pt(ax, 0), "local_anchor_b": [0, 0], "length": length})
    return {"kind": "rigid2d",
            "description": "Newton's cradle: 5 balls 10 cm apart (restitution 1, no friction) on 5 m distance joints; "
                           "the first is released from 40 degrees and the last one swings out while the first stops",
            "world": {"gravity": [0, -9.81], "substeps": 4, "restitution_threshold": 0.01, "enable_sleep": False},
            "bodies": bodies, "joints": joints}


def ragdoll_parts(prefix, x0, y0, group):
    """One ragdoll standing with its feet at (x0, y0): (bodies, joints). Its parts share a negative
    collision group, so it does not collide with itself; it collides with everything else."""
    flt = {"group": group}

    def part(name, x, y, shape):
        shape = dict(shape, density=1000, friction=0.6, filter=flt)
        return {"name": f"{prefix}{name}", "position": pt(x0 + x, y0 + y), "shapes": [shape]}

    def cap(half, radius):
        return {"type": "capsule", "center1": [0, r(-half)], "center2": [0, r(half)], "radius": radius}

    bodies = [part("torso", 0, 1.2, cap(0.25, 0.15)),
              part("head", 0, 1.75, {"type": "circle", "radius": 0.12})]
    joints = []

    def joint(a, b, x, y, lo, hi):
        joints.append({"type": "revolute", "body_a": f"{prefix}{a}", "body_b": f"{prefix}{b}",
                       "anchor": pt(x0 + x, y0 + y), "enable_limit": True, "lower_angle_deg": lo,
                       "upper_angle_deg": hi, "friction_torque": 5})

    joint("torso", "head", 0, 1.6, -40, 40)
    for side, sx in (("left", -1), ("right", 1)):
        bodies += [part(f"{side}_upper_arm", 0.25 * sx, 1.35, cap(0.15, 0.05)),
                   part(f"{side}_lower_arm", 0.25 * sx, 0.97, cap(0.15, 0.045)),
                   part(f"{side}_upper_leg", 0.1 * sx, 0.7, cap(0.2, 0.07)),
                   part(f"{side}_lower_leg", 0.1 * sx, 0.25, cap(0.2, 0.06))]
        joint("torso", f"{side}_upper_arm", 0.25 * sx, 1.5, -120, 120)
        joint(f"{side}_upper_arm", f"{side}_lower_arm", 0.25 * sx, 1.16, -140, 0)
        joint("torso", f"{side}_upper_leg", 0.1 * sx, 0.9, -30, 100)
        joint(f"{side}_upper_leg", f"{side}_lower_leg", 0.1 * sx, 0.47, -130, 0)
    return bodies, joints


def ragdoll():
    bodies = [ground(30)]
    joints = []
    for k, (x, y) in enumerate([(-3.0, 1.0), (0.0, 4.0), (3.0, 7.0)]):
        b, j = ragdoll_parts(f"doll{k}_", x, y, -(k + 1))
        if k > 0:
            b[0]["angular_velocity"] = 2.0 * (1 if k == 1 else -1)
            b[0]["linear_velocity"] = [r(-1.5 * (k - 1.5)), 0]
        bodies += b
        joints += j
    bodies.append({"name": "step", "type": "static", "position": [1.5, 0.5],
                   "shapes": [{"type": "box", "half_extents": [1, 0.5]}]})
    return {"kind": "rigid2d",
            "description": "three ragdolls (10 capsules and circles each, 9 revolute joints with limits and pin "
                           "friction) dropped from 1, 4 and 7 m onto the ground and a step; they crumple and settle",
            "world": {"gravity": [0, -9.81], "substeps": 4},
            "bodies": bodies, "joints": joints}


def car():
    # Terrain heights every 5 m from x = -20 (Box2D's car sample's hills), then a ramp, then flat
    # ground to a wall. A ground chain is listed right to left: the free side is then up.
    heights = [0, 0, 0, 0.25, 1.0, 2.0, 0, 0, -1.0, -2.0, -2.0, -1.25, 0, 0, 0.5, 1.0, 1.5, 1.0, 0.5, 0, 0, 0,
               0.4, 0, 0.4, 0, 0.4, 0, 0, 1.0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]
    pts = [(-20.0 + 5.0 * i, h) for i, h in enumerate(heights)]
    end = pts[-1][0]
    pts = [(-40.0, 10.0), (-40.0, 0.0)] + pts + [(end, 10.0)]
    terrain = {"name": "terrain", "type": "static",
               "shapes": [{"type": "chain", "points": [pt(x, y) for x, y in reversed(pts)], "friction": 0.9}]}
    chassis = {"name": "chassis", "position": [0, 1.2],
               "shapes": [{"type": "polygon", "points": [[-1.5, -0.5], [1.5, -0.5], [1.5, 0], [0, 0.9], [-1.15, 0.9],
                                                         [-1.5, 0.2]], "density": 50, "friction": 0.3}]}
    wheel = {"type": "circle", "radius": 0.4, "density": 100, "friction": 0.9, "rolling_resistance": 0.01}
    bodies = [terrain, chassis,
              {"name": "rear_wheel", "position": [-1, 0.65], "shapes": [wheel]},
              {"name": "front_wheel", "position": [1, 0.65], "shapes": [wheel]}]
    for k, x in enumerate([45.0, 46.0, 45.5]):
        bodies.append({"name": f"crate{k}", "position": pt(x, 0.5 + (1.0 if k == 2 else 0.0)),
                       "shapes": [{"type": "box", "half_extents": [0.5, 0.5], "density": 5}]})
    joints = []
    for name, x in (("rear_wheel", -1.0), ("front_wheel", 1.0)):
        joints.append({"type": "wheel", "name": f"{name}_axle", "body_a": "chassis", "body_b": name,
                       "anchor": pt(x, 0.65), "axis": [0, 1], "hertz": 5, "damping_ratio": 0.7,
                       "enable_limit": True, "lower_translation": -0.25, "upper_translation": 0.25,
                       "enable_motor": True, "motor_speed": -25, "max_motor_torque": 500})
    return {"kind": "rigid2d",
            "description": "a car: a polygon chassis on two wheel joints (suspension 5 Hz, motors driving the "
                           "wheels at 25 rad/s, at most 500 N m), over chain terrain with hills, a dip and "
                           "bumps, into three loose crates",
            "world": {"gravity": [0, -9.81], "substeps": 4},
            "bodies": bodies, "joints": joints}


def buoyancy():
    width = 10.0
    depth = 6.0
    # Listed clockwise (right wall down, floor right to left, left wall up): the free side of a
    # chain is on the right of each segment, so the inside of the tank is free.
    bodies = [{"name": "tank", "type": "static",
               "shapes": [{"type": "chain", "loop": False,
                           "points": [pt(width, 4), pt(width, -depth), pt(-width, -depth), pt(-width, 4)]}]}]
    for k, (density, x) in enumerate([(250, -7.5), (500, -4.5), (750, -1.5), (1500, 1.5)]):
        bodies.append({"name": f"box{density}", "position": pt(x, 2 + 0.5 * k), "angle_deg": 10 * k,
                       "shapes": [{"type": "box", "half_extents": [1, 0.5], "density": density}]})
    bodies.append({"name": "log", "position": [5, 3], "angle_deg": 30,
                   "shapes": [{"type": "capsule", "center1": [-1.2, 0], "center2": [1.2, 0], "radius": 0.3,
                               "density": 600}]})
    bodies.append({"name": "ball", "position": [8, 2.5], "shapes": [{"type": "circle", "radius": 0.6, "density": 400}]})
    return {"kind": "rigid2d",
            "description": "buoyancy: boxes of density 250, 500, 750 and 1500 kg/m^2, a log and a ball dropped into "
                           "water (1000 kg/m^2, surface at y = 0) in a tank: each floats with the fraction of its "
                           "area its density gives (a quarter, a half, three quarters submerged); the heavy box sinks",
            "world": {"gravity": [0, -9.81], "substeps": 4},
            "bodies": bodies,
            "effectors": [{"type": "buoyancy", "surface_height": 0, "x_min": -width, "x_max": width,
                           "fluid_density": 1000, "linear_drag": 2, "angular_drag": 1}]}


def craft(name, position, angle_deg, velocity):
    # The book's craft: 20 m x 10 m, 100 kg (areal density 0.5 kg/m^2) and its inertia, 500 kg m^2
    # (not a uniform box's 4167 kg m^2); restitution 0.5, no friction.
    return {"name": name, "position": pt(*position), "angle_deg": angle_deg, "linear_velocity": pt(*velocity),
            "shapes": [{"type": "box", "half_extents": [10, 5], "density": 0.5, "restitution": 0.5,
                        "friction": 0}],
            "mass_properties": {"mass": 100, "inertia": 500}}


def bumper_cars(solver):
    name = {"book": "the book's single-impulse response (\"solver\": \"book\")",
            "soft": "the default soft-step solver"}[solver]
    return {"kind": "rigid2d",
            "description": "the book's ch. 10 bumper cars: craft 1 (8 m/s along +x) rams craft 2 (heading down at "
                           "2 m/s) in the middle of its side at t = 3.125 s, restitution 0.5, no friction, no gravity, "
                           f"with {name}. Equal masses: craft 1 leaves at 2 m/s, craft 2 at 6 m/s along x (and still "
                           "2 m/s down); momentum is kept, 1200 J of kinetic energy lost. Compare "
                           "ch10_bumper_cars.json (book) with ch10_bumper_cars_soft.json (soft step)",
            "world": {"gravity": [0, 0], "solver": solver, "enable_sleep": False},
            "bodies": [craft("craft1", (-40, 4), 0, (8, 0)), craft("craft2", (0, 10.25), -90, (0, -2))]}


def hovercraft():
    # ch. 9: propeller thrust through the centre of mass, drag at 5 m aft, bow thrusters at the
    # bow corners (body frame +x forward, +y to port).
    body = craft("craft", (0, 0), 0, (0, 0))
    body["shapes"][0].pop("restitution")
    air = {"type": "wind_drag", "body": "craft", "air_density": 0.0023769, "drag_area": 93.75,
           "local_center_of_pressure": [-5, 0]}
    return {"kind": "rigid2d",
            "description": "the book's ch. 9 hovercraft (100 kg, 20 m x 10 m, inertia 500 kg m^2): 10 N of propeller "
                           "thrust from rest, drag (Cd A = 93.75 m^2) acting 5 m aft of the centre of mass; the port "
                           "bow thruster (3 N) fires from 60 to 80 s (a right turn), the starboard one from 80 to 100 s "
                           "(a left turn), as in `impetus demo hovercraft`. Run 100 s: --steps 6000",
            "world": {"gravity": [0, 0], "enable_sleep": False},
            "bodies": [body],
            "effectors": [{"type": "thruster", "body": "craft", "local_point": [0, 0], "local_direction": [1, 0],
                           "thrust": 10},
                          air,
                          {"type": "thruster", "body": "craft", "local_point": [10, 5], "local_direction": [0, -1],
                           "thrust": 3, "start": 60, "stop": 80},
                          {"type": "thruster", "body": "craft", "local_point": [10, -5], "local_direction": [0, 1],
                           "thrust": 3, "start": 80, "stop": 100}]}


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    scenes = {"pyramid": pyramid(), "chain": chain(), "bridge": bridge(), "newtons_cradle": newtons_cradle(),
              "ragdoll": ragdoll(), "car": car(), "buoyancy": buoyancy(),
              "ch10_bumper_cars": bumper_cars("book"), "ch10_bumper_cars_soft": bumper_cars("soft"),
              "ch09_hovercraft": hovercraft()}
    for name, doc in scenes.items():
        (OUT / f"{name}.json").write_text(dump(doc))
        print(f"wrote {OUT / name}.json")


if __name__ == "__main__":
    main()
