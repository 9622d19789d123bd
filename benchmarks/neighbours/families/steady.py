"""Steady motions in 3D: a heavy symmetric top precessing steadily about the vertical
(its spin, or its two precession rates, solved for), and a disk or ring rolling in a
steady circle on a table (ω₀² solved for, the spin from rolling). The oracle places the
body by its turns with t and judges the motion by Newton–Euler about the centre of mass
with one unknown force at the support (the pivot, or the contact)."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Param

FAMILY = "steady"


def generate(b: Builder) -> None:
    b.planar = False
    kind = b.draw.choice(["top_spin", "top_rates", "coin"], p=[0.35, 0.25, 0.4])
    {"top_spin": _top_spin, "top_rates": _top_rates, "coin": _coin}[kind](b)
    b.variant = kind
    b.feature("steady motion")


def _top(b: Builder, rate: str, spin: str):
    m = b.param("m", "mass", "mass of the top").name
    h = b.param("h", "length", "distance from O to G", low=0.05, high=0.3,
                table=[("10 cm", "1/10"), ("15 cm", "3/20"), ("0.2", "1/5")]).name
    g = b.param("g", "accel", "acceleration of gravity").name
    b.gravity = f"[0, 0, -{g}]"
    th = b.param("theta", "angle", "angle of the axis from the vertical", low=0.2, high=1.2).name
    shape = b.draw.choice(["given", "disk", "cone"])
    b.extra["triads"] = {"T": {"turns": [["z", f"{rate}*t"], ["x", th]], "vectors": ["e1", "e2", "e3"]}}
    b.point("O", "[0, 0, 0]")
    b.yaml_points["G"] = f"{h}*e3"
    b.point("G", f"{h}*[sin({th})*sin({rate}*t), -sin({th})*cos({rate}*t), cos({th})]")
    turns = (("z", f"{rate}*t"), ("x", th), ("z", f"{spin}*t"))
    if shape == "given":
        J1 = b.param("J1", "inertia", "transverse moment about G").name
        J3 = b.param("J3", "inertia", "axial moment").name
        b.body({"mass": m, "inertia": [J1, J1, J3], "at": "G", "orientation": ["T", ["z", f"{spin}*t"]]},
               Body("top", m, inertia=(J1, J1, J3), origin="G", turns=turns))
    else:
        r = b.param("r", "length", "radius of the disk", low=0.02, high=0.05,
                    table=[("4 cm", "1/25"), ("5 cm", "1/20"), ("3 cm", "3/100")]).name
        dims = {"radius": r} if shape == "disk" else {"radius": r, "height": f"2*{r}"}
        b.body({"shape": shape, "mass": m, **dims, "at": "G", "orientation": ["T", ["z", f"{spin}*t"]]},
               Body("top", m, shape, dims, origin="G", turns=turns))
    b.feature(f"body:{shape}", "pivot")
    b.hide("_P", "[0, 0, 0]")
    return th


def _top_spin(b: Builder) -> None:
    W = b.param("Omega", "rate", "rate of precession").name
    b.extra["unknowns"] = ["spin"]
    _top(b, W, "spin")
    b.ask("steady_motion", {"about": "O", "solve_for": "spin"})


def _top_rates(b: Builder) -> None:
    b.param("spin", "rate", "spin rate relative to the precessing triad", low=20.0, high=60.0,
            table=[("300 rev/min", "10*pi"), ("50 rad/s", "50"), ("40", "40")])
    b.extra["unknowns"] = ["Omega"]
    _top(b, "Omega", "spin")
    b.ask("steady_motion", {"about": "O", "solve_for": "Omega"})


def _coin(b: Builder) -> None:
    m = b.param("m", "mass", "mass").name
    r = b.param("r", "length", "radius of the coin", low=0.02, high=0.1).name
    R = b.param("R", "length", "radius of the circle of the centre", low=0.2, high=1.0).name
    g = b.param("g", "accel", "acceleration of gravity").name
    th = b.param("theta", "angle", "tilt", low=0.1, high=1.2).name
    b.gravity = f"[0, 0, -{g}]"
    w = "omega0"
    b.params.append(Param(w, "rate", None, None, 1.0, 5.0, True, "angular speed of the centre about the vertical"))
    b.extra["unknowns"] = ["spin"]
    b.extra["triads"] = {"T": {"turns": [["z", f"{w}*t"], ["y", f"-{th}"]], "vectors": ["e1", "e2", "e3"]}}
    b.point("G", f"{R}*[cos({w}*t), sin({w}*t), 0]")
    shape = b.draw.choice(["disk", "ring"])
    b.body({"shape": shape, "mass": m, "radius": r, "at": "G", "axis": "x", "orientation": ["T", ["x", "spin*t"]]},
           Body("coin", m, shape, {"radius": r}, (1, 0, 0), origin="G",
                turns=(("z", f"{w}*t"), ("y", f"-{th}"), ("x", "spin*t"))))
    b.hide("_P", f"G - {r}*[-sin({th})*cos({w}*t), -sin({th})*sin({w}*t), cos({th})]")
    b.contacts_yaml["C"] = {"body": "coin", "rolls_on": {"plane": {"normal": "z"}}}
    b.feature(f"body:{shape}", "rolling on a plane")
    b.ask("steady_motion", {"about": "C", "solve_for": f"{w}**2"})
