"""Impacts: a particle hits a pivoted rod, disk or plate (restitution, or it sticks, or
it is brought to a stop), a blow on a pendulum (the centre of percussion), a free rod
struck at its end or hit by clay that sticks, a falling rod whose end hits the floor, a
double pendulum of rods hit at its lower end."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Param, Support

FAMILY = "impact"


def generate(b: Builder) -> None:
    kind = b.draw.choice(["pinned", "percussion", "free", "falling", "double"], p=[0.35, 0.15, 0.2, 0.15, 0.15])
    {"pinned": _pinned, "percussion": _percussion, "free": _free, "falling": _falling, "double": _double}[kind](b)
    b.feature("impact")


def _pinned_body(b: Builder, m: str):
    """A body hanging from O at θ: a rod, a disk by its rim or a square plate by a corner;
    its lowest point's distance L from O."""
    kind = b.draw.choice(["rod", "disk", "plate"])
    u = "[sin(theta), -cos(theta)]"
    if kind == "rod":
        l = b.param("l", "length", "length of the rod").name
        b.point("G", f"{l}/2*{u}")
        b.body({"shape": "rod", "mass": m, "length": l, "at": "G", "angle": "theta", "axis": "y"},
               Body("rod", m, "rod", {"length": l}, (0, 1, 0), origin="G", angle="theta"))
        return "rod", l
    if kind == "disk":
        r = b.param("r", "length", "radius of the disk").name
        b.point("G", f"{r}*{u}")
        b.body({"shape": "disk", "mass": m, "radius": r, "at": "G", "angle": "theta"},
               Body("disk", m, "disk", {"radius": r}, origin="G", angle="theta"))
        return "disk", f"2*{r}"
    a = b.param("a", "length", "side of the square plate").name
    b.point("G", f"{a}/sqrt(2)*{u}")
    b.body({"shape": "plate", "mass": m, "width": a, "height": a, "at": "G", "angle": "theta + pi/4"},
           Body("plate", m, "plate", {"width": a, "height": a}, origin="G", angle="theta + pi/4"))
    return "plate", f"sqrt(2)*{a}"


def _pinned(b: Builder) -> None:
    M = b.param("M", "mass", "mass of the pendulum").name
    body, L = _pinned_body(b, M)
    m = b.param("m", "mass", "mass of the particle", low=0.1, high=1.0).name
    v = b.param("v0", "speed", "speed of the particle").name
    b.coordinate("theta", "angle")
    b.point("O", "[0, 0]")
    b.point("A", f"{L}*[sin(theta), -cos(theta)]")
    b.supports.append(Support("O", body, "O", "pivot"))
    how = b.draw.choice(["restitution", "sticks", "stops"])
    particle = {"mass": m, "velocity": f"[{v}, 0]"}
    if how == "restitution":
        e = b.param("e", "ratio", "coefficient of restitution", low=0.1, high=0.9).name
        coll = {"normal": "x", "restitution": e, "particle": particle}
    elif how == "sticks":
        coll = {"particle": {"mass": m, "velocity": f"[{v}, -{v}/2]"}, "sticks": True}
        b.feature("sticking")
    else:
        coll = {"particle": {**particle, "after": "[0, 0]"}}
    b.variant = f"pinned-{body}-{how}"
    b.feature(f"body:{body}", "pivot")
    b.ask("impact", {"at": {"theta": "0"}, "collisions": {"A": coll}, "points": ["A"]})


def _percussion(b: Builder) -> None:
    M = b.param("m", "mass", "mass of the pendulum").name
    body, L = _pinned_body(b, M)
    P = b.param("P", "impulse", "size of the blow").name
    b.params.append(Param("d", "length", None, None, 0.1, 0.9, True, "distance from the pivot to the struck point"))
    b.coordinate("theta", "angle")
    b.point("O", "[0, 0]")
    b.point("Q", "d*[sin(theta), -cos(theta)]")
    b.supports.append(Support("O", body, "O", "pivot"))
    b.variant = f"percussion-{body}"
    b.feature(f"body:{body}", "pivot", "centre of percussion")
    b.ask("impact", {"at": {"theta": "0"}, "impulses": {"Q": f"[{P}, 0]"}, "centre_of_percussion": "d"})


def _free_rod(b: Builder, m: str, l: str) -> None:
    b.coordinate("x", "length", periodic=False)
    b.coordinate("y", "length", periodic=False)
    b.coordinate("theta", "angle")
    b.point("G", "[x, y]")
    b.point("A", f"G + {l}/2*[cos(theta), sin(theta)]")
    b.point("B", f"G - {l}/2*[cos(theta), sin(theta)]")
    b.body({"shape": "rod", "mass": m, "length": l, "at": "G", "angle": "theta"},
           Body("rod", m, "rod", {"length": l}, origin="G", angle="theta"))


def _free(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the rod").name
    l = b.param("l", "length", "length of the rod").name
    _free_rod(b, m, l)
    at = {"theta": b.draw.choice(["0", "pi/6", "pi/4"])}
    if b.draw.chance(0.5):
        P = b.param("P", "impulse", "size of the blow").name
        b.ask("impact", {"at": at, "impulses": {"A": f"[0, {P}]"}, "points": ["A", "B"]})
        b.variant = "free-struck"
    else:
        mc = b.param("mc", "mass", "mass of the clay", low=0.1, high=1.0).name
        v = b.param("v0", "speed", "speed of the clay").name
        b.ask("impact", {"at": at, "collisions": {"A": {"particle": {"mass": mc, "velocity": f"[0, {v}]"}, "sticks": True}}})
        b.variant = "free-clay"
        b.feature("sticking")
    b.feature("body:rod", "free body")


def _falling(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the rod").name
    l = b.param("l", "length", "length of the rod").name
    al = b.param("alpha", "angle", "angle of the rod to the horizontal", low=0.2, high=1.2).name
    v = b.param("v0", "speed", "speed before the impact").name
    e = b.param("e", "ratio", "coefficient of restitution", low=0.0, high=0.9).name
    _free_rod(b, m, l)
    b.points["A"] = f"G - {l}/2*[cos(theta), sin(theta)]"
    b.ask("impact", {"at": {"theta": al}, "before": {"y": f"-{v}"}, "collisions": {"A": {"normal": "y", "restitution": e}},
                     "points": ["A"]})
    b.variant = "falling-rod"
    b.feature("body:rod", "free body")


def _double(b: Builder) -> None:
    m = b.param("m", "mass", "mass of each rod").name
    l = b.param("l", "length", "length of each rod").name
    mp = b.param("mp", "mass", "mass of the particle", low=0.1, high=1.0).name
    v = b.param("v0", "speed", "speed of the particle").name
    b.coordinate("theta", "angle")
    b.coordinate("phi", "angle")
    b.point("O", "[0, 0]")
    b.point("A", f"{l}*[sin(theta), -cos(theta)]")
    b.point("G1", f"{l}/2*[sin(theta), -cos(theta)]")
    b.point("G2", f"A + {l}/2*[sin(phi), -cos(phi)]")
    b.point("B", f"A + {l}*[sin(phi), -cos(phi)]")
    for i in (1, 2):
        q = "theta" if i == 1 else "phi"
        b.body({"shape": "rod", "mass": m, "length": l, "at": f"G{i}", "angle": q, "axis": "y"},
               Body(f"rod{i}", m, "rod", {"length": l}, (0, 1, 0), origin=f"G{i}", angle=q))
    b.supports.append(Support("O", "rod1", "O", "pivot"))
    b.supports.append(Support("A", "rod2", "A", "pivot", by="rod1"))
    e = b.param("e", "ratio", "coefficient of restitution", low=0.1, high=0.9).name
    b.ask("impact", {"at": {"theta": "0", "phi": "0"},
                     "collisions": {"B": {"normal": "x", "restitution": e, "particle": {"mass": mp, "velocity": f"[{v}, 0]"}}},
                     "points": ["A", "B"]})
    b.variant = "double-rods"
    b.feature("body:rod", "pivot", "joint")
