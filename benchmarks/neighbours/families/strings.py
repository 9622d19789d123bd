"""Bodies on strings and on moving bodies: a yo-yo (a round body on a string from a
fixed point, wound at its rim or at an inner radius), a drum rolling on the floor with
a block hanging over a light pulley from it, a cylinder rolling on a plank that slides
on a smooth floor (held by a spring), a disk rolling on the rim of a disk that turns on
its axle. The oracle's placements: a string is a line the body rolls on (centre at the
winding radius from it, turn −s/ρ); the hanging block goes down twice the drum's
travel (its top point moves at 2ẋ); on the plank, rolling relative to it; on the
turning disk, r (φ̇ − ψ̇) = (R + r)(θ̇ − ψ̇)."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.families.rolling import round_body
from benchmarks.neighbours.scene import Body, Spring, Support

FAMILY = "strings"


def generate(b: Builder) -> None:
    kind = b.draw.choice(["yoyo", "pulley", "plank", "turning"], p=[0.35, 0.2, 0.25, 0.2])
    {"yoyo": _yoyo, "pulley": _pulley, "plank": _plank, "turning": _turning}[kind](b)


def _gravity(b: Builder) -> str:
    g = b.param("g", "accel", "acceleration of gravity").name
    b.gravity = f"[0, -{g}]"
    return g


def _yoyo(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the yo-yo").name
    r = b.param("r", "length", "radius of the yo-yo", low=0.1, high=0.5).name
    entry, body = round_body(b, "yoyo", m, r)
    _gravity(b)
    b.point("A", "[0, 0]")
    inner = b.draw.chance(0.4)
    rho = f"{r}/2" if inner else r
    string = {"fixed_at": "A", "direction": "[0, -1]"}
    if inner:
        string["radius"] = rho
        b.feature("string at an inner radius")
    b.coordinate("y", "length", periodic=False, low="-10", high="10")
    b.hide("_C", "[0, -y]")
    b.hide("_G", f"[{rho}, -y]")
    body.origin, body.angle = "_G", f"-y/({rho})"
    b.body(entry, body)
    b.contacts_yaml["S"] = {"body": "yoyo", "string": string, "along": "y"}
    b.supports.append(Support("S", "yoyo", "_C", "string", normal="[0, 1]"))
    b.variant = f"yoyo-{body.shape}{'-inner' if inner else ''}"
    b.feature("string", "contact")
    for x in _some(b, ["eom", "reactions", "energy"]):
        if x == "eom":
            b.ask("eom")
        elif x == "reactions":
            b.ask("reactions", {"forces": ["S"], "from_rest": {"y": "0"}})
            b.feature("reactions")
        else:
            b.ask("energy", {"from_rest": {"y": "0"}, "to": {"y": b.draw.choice(["1", "2", "1/2"])}})


def _pulley(b: Builder) -> None:
    M = b.param("M", "mass", "mass of the drum").name
    r = b.param("r", "length", "radius of the drum", low=0.1, high=0.5).name
    m = b.param("m", "mass", "mass of the block").name
    a = b.param("a", "length", "side of the block", low=0.05, high=0.2).name
    d = b.param("d", "length", "distance from the drum's top to the pulley", low=2.0, high=4.0).name
    _gravity(b)
    entry, body = round_body(b, "drum", M, r)
    b.point("P", f"[{d}, 2*{r}]")
    b.coordinate("x", "length", periodic=False, low="-1", high="1")
    b.hide("_G", f"[x, {r}]")
    body.origin, body.angle = "_G", f"-x/{r}"
    b.body(entry, body)
    b.body({"shape": "plate", "mass": m, "width": a, "height": a},
           Body("block", m, "plate", {"width": a, "height": a}, origin=f"[{d}, 2*{r} - {d} - 2*x]"))
    b.contacts_yaml["C"] = {"body": "drum", "rolls_on": "floor", "along": "x"}
    b.contacts_yaml["S"] = {"body": "block", "hangs_from": {"drum": "drum", "direction": "[1, 0]", "over": "P"}}
    b.variant = f"pulley-{body.shape}"
    b.feature("string over a pulley", "contact", "rolling:floor")
    for x in _some(b, ["eom", "energy", "eom_rest"]):
        if x == "eom":
            b.ask("eom")
        elif x == "eom_rest":
            b.ask("eom", {"from_rest": {"x": "0"}})
        else:
            b.ask("energy", {"from_rest": {"x": "0"}, "to": {"x": b.draw.choice(["1/2", "1/4"])}})


def _plank(b: Builder) -> None:
    M = b.param("M", "mass", "mass of the plank").name
    L = b.param("L", "length", "length of the plank", low=2.0, high=4.0).name
    h = b.param("h", "length", "thickness of the plank", low=0.05, high=0.2).name
    m = b.param("m", "mass", "mass of the cylinder").name
    r = b.param("r", "length", "radius of the cylinder", low=0.1, high=0.5).name
    k = b.param("k", "stiffness", "stiffness of the spring").name
    _gravity(b)
    b.point("P", f"[x, {h}/2]")
    b.point("W", f"[-{L}, {h}/2]")
    b.body({"shape": "plate", "mass": M, "width": L, "height": h, "at": "P"},
           Body("plank", M, "plate", {"width": L, "height": h}, origin="P"))
    entry, body = round_body(b, "cylinder", m, r)
    b.coordinate("x", "length", periodic=False, low=f"-9*{L}/10", high="2")
    b.coordinate("s", "length", periodic=False, low="-2", high="2")
    b.hide("_C", f"[x + s, {h}]")
    b.hide("_G", f"[x + s, {h} + {r}]")
    body.origin, body.angle = "_G", f"-s/{r}"
    b.body(entry, body)
    b.contacts_yaml["C"] = {"body": "cylinder", "rolls_on": {"body": "plank", "edge": "top"}, "along": "s"}
    b.spring({"stiffness": k, "between": ["P", "W"], "natural_length": L},
             Spring("wall", k, ends=("P", "W"), on=("plank", None), natural_length=L))
    b.variant = f"plank-{body.shape}"
    b.feature("rolling on a moving body", "contact")
    for x in _some(b, ["eom", "modes"]):
        if x == "eom":
            b.ask("eom", {"from_rest": {"x": "1/10", "s": "0"}} if b.draw.chance(0.4) else None)
        else:
            b.ask("modes", {"about": {"x": "0", "s": "0"}})


def _turning(b: Builder) -> None:
    M = b.param("M", "mass", "mass of the turning disk").name
    R = b.param("R", "length", "radius of the turning disk", low=0.5, high=1.5).name
    m = b.param("m", "mass", "mass of the rolling disk").name
    r = b.param("r", "length", "radius of the rolling disk", low=0.1, high=0.5).name
    _gravity(b)
    b.body({"shape": "disk", "mass": M, "radius": R, "at": "[0, 0]", "angle": "psi"},
           Body("wheel", M, "disk", {"radius": R}, origin="[0, 0]", angle="psi"))
    b.coordinate("psi", "angle", periodic=True)
    b.coordinate("theta", "angle", periodic=True)
    u = "[-sin(theta), cos(theta)]"
    b.body({"shape": "disk", "mass": m, "radius": r},
           Body("disk", m, "disk", {"radius": r}, origin=f"({R} + {r})*{u}", angle=f"psi + ({R} + {r})*(theta - psi)/{r}"))
    b.contacts_yaml["C"] = {"body": "disk", "rolls_on": {"body": "wheel", "edge": "rim"}, "along": "theta"}
    b.variant = "disk-on-turning-disk"
    b.feature("rolling on a moving body", "contact")
    for x in _some(b, ["eom", "eom_rest"]):
        if x == "eom":
            b.ask("eom")
        else:
            b.ask("eom", {"from_rest": {"psi": "0", "theta": "pi/6"}})


def _some(b: Builder, pool: list[str]) -> list[str]:
    return [x for x in pool if b.draw.chance(0.5)] or [b.draw.choice(pool)]
