"""Turning and moving supports: a bead on a hoop turning about its vertical diameter, a
bead on a straight wire turning about the vertical at an angle, beads on a rod turning
in a horizontal plane held by springs, a pendulum whose pivot oscillates (prescribed).
The oracle needs no frame: the points are written in the scene's axes with t, and a
relative equilibrium is where the generalized force, inertia included, vanishes at
rest in the turning frame."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Spring

FAMILY = "frames"


def generate(b: Builder) -> None:
    kind = b.draw.choice(["hoop", "wire", "rod", "pivot"], p=[0.35, 0.2, 0.3, 0.15])
    {"hoop": _hoop, "wire": _wire, "rod": _rod, "pivot": _pivot}[kind](b)
    b.variant = kind
    b.feature("turning frame" if kind != "pivot" else "prescribed motion")


def _hoop(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the bead").name
    R = b.param("R", "length", "radius of the hoop").name
    g = b.param("g", "accel", "acceleration of gravity").name
    W = b.param("Omega", "rate", "rate of turning of the hoop").name
    b.gravity = f"[0, -{g}, 0]"
    b.planar = False
    b.frames_yaml["hoop"] = {"axis": "y", "rate": W}
    b.coordinate("theta", "angle")
    b.point("P", f"{R}*[sin(theta)*cos({W}*t), -cos(theta), -sin(theta)*sin({W}*t)]")
    b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bead", m, "particle", origin="P"))
    if b.draw.chance(0.3):
        k = b.param("k", "stiffness", "stiffness of the spring to the bottom of the hoop", low=1.0, high=30.0).name
        b.point("B", f"[0, -{R}, 0]")
        b.spring({"stiffness": k, "between": ["P", "B"]}, Spring("s", k, ends=("P", "B"), on=("bead", None)))
    _frame_questions(b, "hoop", {"theta": "0"})


def _wire(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the bead").name
    g = b.param("g", "accel", "acceleration of gravity").name
    al = b.param("alpha", "angle", "angle of the wire from the vertical", low=0.3, high=1.2).name
    W = b.param("Omega", "rate", "rate of turning").name
    b.gravity = f"[0, -{g}, 0]"
    b.planar = False
    b.frames_yaml["wire"] = {"axis": "y", "rate": W}
    b.coordinate("s", "length", periodic=False, low="1/100", high="100")
    b.point("P", f"s*[sin({al})*cos({W}*t), cos({al}), -sin({al})*sin({W}*t)]")
    b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bead", m, "particle", origin="P"))
    _frame_questions(b, "wire", None)


def _rod(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the bead").name
    k = b.param("k", "stiffness", "stiffness of the spring").name
    a = b.param("a", "length", "natural length of the spring").name
    W = b.param("Omega", "rate", "rate of turning of the rod", low=1.0, high=12.0).name
    b.planar = False
    b.frames_yaml["rod"] = {"axis": "z", "rate": W}
    b.coordinate("x", "length", periodic=False, low=f"-{a}/2", high=f"20*{a}")
    b.point("O", "[0, 0, 0]")
    b.point("P", f"({a} + x)*[cos({W}*t), sin({W}*t), 0]")
    b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bead", m, "particle", origin="P"))
    b.spring({"stiffness": k, "between": ["P", "O"], "natural_length": a},
             Spring("s", k, ends=("P", "O"), on=("bead", None), natural_length=a))
    b.feature("linear spring")
    _frame_questions(b, "rod", None)


def _pivot(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the bob").name
    l = b.param("l", "length", "length of the pendulum").name
    g = b.param("g", "accel", "acceleration of gravity").name
    a = b.param("a", "length", "amplitude of the pivot", low=0.01, high=0.2).name
    W = b.param("Omega", "rate", "angular frequency of the pivot").name
    b.gravity = f"[0, -{g}]"
    along = b.draw.choice(["x", "y"])
    b.prescribed["u_O"] = f"{a}*cos({W}*t)"
    b.point("O", f"[{a}*cos({W}*t), 0]" if along == "x" else f"[0, {a}*cos({W}*t)]")
    b.yaml_points["O"] = "[u_O, 0]" if along == "x" else "[0, u_O]"
    b.frames_yaml["pivot"] = {"origin": "O"}
    b.coordinate("phi", "angle")
    b.point("P", f"O + {l}*[sin(phi), -cos(phi)]")
    b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bob", m, "particle", origin="P"))
    b.ask("eom", {"frames": ["pivot"]} if b.draw.chance(0.5) else None)


def _frame_questions(b: Builder, frame: str, zero: dict | None) -> None:
    pool = [("eom", {"frames": [frame]}), ("equilibria", {"frame": frame}), ("modes", {"frame": frame, "about": "each"})]
    if zero:
        pool.append(("modes", {"frame": frame, "about": zero}))
    for kind, opts in [x for x in pool if b.draw.chance(0.5)] or [pool[1]]:
        b.ask(kind, opts)
