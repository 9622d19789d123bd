"""Inertia of one body in space: a shape of the library turned by its own axis and
placed at a point, or a composite (a plate with a hole, a dumbbell of a rod and two
spheres, a T of two rods, a box with a cylinder taken out), about its centre, about a
point, in turned axes, about an axis."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Part

FAMILY = "inertia"

SHAPES = {
    "rod": {"length": "2*a"}, "ring": {"radius": "a"}, "disk": {"radius": "a"},
    "cylindrical_shell": {"radius": "a", "height": "2*a"}, "cylinder": {"radius": "a", "height": "3*a"},
    "tube": {"inner_radius": "a/2", "outer_radius": "a", "height": "a"}, "spherical_shell": {"radius": "a"},
    "sphere": {"radius": "a"}, "hemisphere": {"radius": "a"}, "hemispherical_shell": {"radius": "a"},
    "half_disk": {"radius": "a"}, "half_ring": {"radius": "a"}, "quarter_disk": {"radius": "a"},
    "cylinder_segment": {"radius": "a", "height": "2*a", "half_angle": "pi/3"}, "cone": {"radius": "a", "height": "2*a"},
    "box": {"width": "a", "depth": "2*a", "height": "3*a"}, "plate": {"width": "2*a", "height": "a"},
    "triangle": {"base": "2*a", "height": "a", "apex": "a/2"},
}
AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1), "-y": (0, -1, 0), "[1, 1, 0]": (1, 1, 0), "[0, 1, 1]": (0, 1, 1)}
FRAMES = [
    [["1/sqrt(2)", "1/sqrt(2)", "0"], ["-1/sqrt(2)", "1/sqrt(2)", "0"], ["0", "0", "1"]],
    [["0", "0", "1"], ["1", "0", "0"], ["0", "1", "0"]],
    [["3/5", "4/5", "0"], ["-4/5", "3/5", "0"], ["0", "0", "1"]],
]


def generate(b: Builder) -> None:
    draw = b.draw
    m = b.param("m", "mass", "mass of the body").name
    a = b.param("a", "length", "a length of the body").name
    b.planar = False
    at = draw.choice(["[0, 0, 0]", f"[{a}, 0, 0]", f"[{a}, {a}, 0]", f"[0, {a}, 2*{a}]"])
    b.point("O", "[0, 0, 0]")
    if draw.chance(0.25):
        _composite(b, m, a, at)
    else:
        shape = draw.choice(list(SHAPES))
        dims = {k: v.replace("a", a) if a != "a" else v for k, v in SHAPES[shape].items()}
        axis = draw.choice([None, None] + list(AXES))
        entry = {"shape": shape, "mass": m, **dims, "at": at}
        if axis:
            entry["axis"] = axis
        b.body(entry, Body("body", m, shape, dims, AXES[axis] if axis else None, origin=at))
        b.variant = shape + (f"-axis-{axis}" if axis else "")
        b.feature(f"body:{shape}")
    opts: dict = {}
    if draw.chance(0.6):
        opts["about"] = draw.choice(["O", f"[{a}, 0, {a}]"])
    if draw.chance(0.3):
        opts["axes"] = draw.choice(FRAMES)
    if draw.chance(0.3):
        opts["axis"] = draw.choice(["[1, 0, 0]", "[1, 1, 1]", "[0, 1, 2]"])
    b.ask("inertia", opts or None)
    b.feature("inertia")


def _composite(b: Builder, m: str, a: str, at: str) -> None:
    kind = b.draw.choice(["holed_plate", "dumbbell", "tee", "holed_box"])
    M = b.param("M", "mass", "mass of the second part", low=0.1, high=1.0).name if kind in ("dumbbell", "tee") else None
    if kind == "holed_plate":
        M = f"{m}/8"
        parts = {"plate": {"shape": "plate", "mass": m, "width": f"4*{a}", "height": f"2*{a}"},
                 "hole": {"shape": "disk", "mass": M, "radius": f"{a}/2", "at": f"[{a}, 0]", "hole": True}}
        oparts = (Part("plate", m, {"width": f"4*{a}", "height": f"2*{a}"}),
                  Part("disk", M, {"radius": f"{a}/2"}, (a, "0"), hole=True))
    elif kind == "dumbbell":
        parts = {"rod": {"shape": "rod", "mass": m, "length": f"4*{a}"},
                 "left": {"shape": "sphere", "mass": M, "radius": f"{a}/2", "at": f"[-2*{a} - {a}/2, 0, 0]"},
                 "right": {"shape": "sphere", "mass": M, "radius": f"{a}/2", "at": f"[2*{a} + {a}/2, 0, 0]"}}
        oparts = (Part("rod", m, {"length": f"4*{a}"}),
                  Part("sphere", M, {"radius": f"{a}/2"}, (f"-2*{a} - {a}/2", "0", "0")),
                  Part("sphere", M, {"radius": f"{a}/2"}, (f"2*{a} + {a}/2", "0", "0")))
    elif kind == "tee":
        parts = {"bar": {"shape": "rod", "mass": m, "length": f"2*{a}"},
                 "stem": {"shape": "rod", "mass": M, "length": f"2*{a}", "at": f"[0, -{a}, 0]", "axis": "y"}}
        oparts = (Part("rod", m, {"length": f"2*{a}"}),
                  Part("rod", M, {"length": f"2*{a}"}, ("0", f"-{a}", "0"), (0, 1, 0)))
    else:
        M = f"{m}/5"
        parts = {"box": {"shape": "box", "mass": m, "width": f"2*{a}", "depth": f"2*{a}", "height": f"2*{a}"},
                 "hole": {"shape": "cylinder", "mass": M, "radius": f"{a}/2", "height": f"2*{a}", "axis": "x",
                          "hole": True}}
        oparts = (Part("box", m, {"width": f"2*{a}", "depth": f"2*{a}", "height": f"2*{a}"}),
                  Part("cylinder", M, {"radius": f"{a}/2", "height": f"2*{a}"}, axis=(1, 0, 0), hole=True))
    b.body({"at": at, "parts": parts}, Body("body", origin=at, parts=oparts))
    b.variant = kind
    b.feature("composite body")
