"""A free body's steady spins (Euler's equations) and the torque-free precession of
an axisymmetric one: boxes, cylinders, cones, disks, given principal moments,
composites."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Param

FAMILY = "spin"


def generate(b: Builder) -> None:
    draw = b.draw
    b.planar = False
    kind = draw.choice(["box", "cylinder", "cone", "disk", "given", "sphere_rod"])
    m = b.param("m", "mass", "mass").name
    symmetric = kind in ("cylinder", "cone", "disk")
    if kind == "given":
        J = [b.param(f"J{i}", "inertia", f"principal moment {i}").name for i in (1, 2, 3)]
        if draw.chance(0.4):
            J[1] = J[0]
            b.params = [p for p in b.params if p.name != "J2"]
            symmetric = True
        entry = {"mass": m, "inertia": list(J), "at": "[0, 0, 0]"}
        body = Body("body", m, inertia=tuple(J), origin="[0, 0, 0]")
    else:
        a = b.param("a", "length", "a length of the body").name
        dims = {"box": {"width": a, "depth": f"2*{a}", "height": f"3*{a}"},
                "cylinder": {"radius": a, "height": draw.choice([f"3*{a}", f"{a}/2", f"2*{a}"])},
                "cone": {"radius": a, "height": draw.choice([f"3*{a}", a])}, "disk": {"radius": a},
                "sphere_rod": {"length": f"4*{a}"}}[kind]
        shape = "rod" if kind == "sphere_rod" else kind
        entry = {"shape": shape, "mass": m, **dims, "at": "[0, 0, 0]"}
        body = Body("body", m, shape, dims, origin="[0, 0, 0]")
        if kind == "sphere_rod":
            return _skip_rod(b)
    b.body(entry, body)
    b.variant = kind
    b.feature(f"body:{kind}", "steady spin")
    if symmetric and draw.chance(0.6):
        b.params.append(Param("Omega", "rate", None if draw.chance(0.5) else "3 rad/s", None, 1.0, 4.0, True, "spin"))
        if b.params[-1].value is not None:
            b.params[-1].si = "3"
        across = draw.choice(["transverse", "angle"])
        if across == "transverse":
            w = b.param("w", "rate", "rate across the axis").name
            b.ask("steady_spin", {"precession": {"spin": "Omega", "transverse": w}})
        else:
            b.ask("steady_spin", {"precession": {"spin": "Omega", "angle": draw.choice(["pi/6", "pi/4", "pi/3"])}})
        b.feature("precession")
    else:
        b.ask("steady_spin")


def _skip_rod(b: Builder) -> None:
    """A slender rod has a zero principal moment: rbdsolve does not answer; a box instead."""
    a = b.params[-1].name
    b.body({"shape": "box", "mass": "m", "width": a, "depth": a, "height": f"2*{a}", "at": "[0, 0, 0]"},
           Body("body", "m", "box", {"width": a, "depth": a, "height": f"2*{a}"}, origin="[0, 0, 0]"))
    b.variant = "square-box"
    b.feature("body:box", "steady spin")
    b.ask("steady_spin")
