"""One body on a pivot: a particle on a light rod, a rod, a disk or ring on its rim, a
plate by a corner, a rod with a disk at its end (parts), a half disk, a body given by
its radius of gyration; hanging or upside down, with a torsion spring at the pivot or
a linear spring to a fixed point. Questions: eom, equilibria, modes, the pivot's
reaction along the motion from rest, energy, kinematics of its tip, inertia."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Part, Spring, Support

FAMILY = "pendulum"


def _body(b: Builder, kind: str, up: bool):
    """The body's file entry and the oracle's, for G at distance d along u(θ) from O."""
    u = "[sin(theta), cos(theta)]" if up else "[sin(theta), -cos(theta)]"
    angle = "-theta" if up else "theta"
    m = b.param("m", "mass", "mass of the body").name
    if kind == "particle":
        l = b.param("l", "length", "length of the light rod").name
        b.point("P", f"{l} * {u}")
        b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bob", m, "particle", origin="P"))
        return "bob", "P", "P", l
    if kind in ("rod", "rod_offset"):
        l = b.param("l", "length", "length of the rod").name
        d = f"{l}/2" if kind == "rod" else b.draw.choice([f"{l}/4", f"{l}/3", f"{l}/6"])
        b.point("G", f"{d} * {u}")
        b.point("B", f"({d} + {l}/2) * {u}")
        b.body({"shape": "rod", "mass": m, "length": l, "at": "G", "angle": angle, "axis": "y"},
               Body("rod", m, "rod", {"length": l}, (0, 1, 0), origin="G", angle=angle))
        return "rod", "G", "B", d
    if kind in ("disk", "ring"):
        r = b.param("r", "length", "radius").name
        b.point("G", f"{r} * {u}")
        b.point("B", f"2*{r} * {u}")
        b.body({"shape": kind, "mass": m, "radius": r, "at": "G", "angle": angle},
               Body(kind, m, kind, {"radius": r}, origin="G", angle=angle))
        return kind, "G", "B", r
    if kind == "plate":
        a = b.param("a", "length", "side of the square plate").name
        b.point("G", f"{a}/sqrt(2) * {u}")
        b.point("B", f"sqrt(2)*{a} * {u}")
        turn = f"{angle} + pi/4"
        b.body({"shape": "plate", "mass": m, "width": a, "height": a, "at": "G", "angle": turn},
               Body("plate", m, "plate", {"width": a, "height": a}, origin="G", angle=turn))
        return "plate", "G", "B", f"{a}/sqrt(2)"
    if kind == "rod_disk":
        l = b.param("l", "length", "length of the rod").name
        r = b.param("r", "length", "radius of the disk").name
        M = b.param("M", "mass", "mass of the disk").name
        s = "" if up else "-"
        b.point("B", f"({l} + 2*{r}) * {u}")
        parts = {"rod": {"shape": "rod", "mass": m, "length": l, "at": f"[0, {s}{l}/2]", "axis": "y"},
                 "disk": {"shape": "disk", "mass": M, "radius": r, "at": f"[0, {s}({l} + {r})]"}}
        oracle = Body("pendulum", origin="O", angle=angle, parts=(
            Part("rod", m, {"length": l}, ("0", f"{s}{l}/2"), (0, 1, 0)),
            Part("disk", M, {"radius": r}, ("0", f"{s}({l} + {r})"))))
        b.body({"at": "O", "angle": angle, "parts": parts}, oracle)
        b.feature("composite body")
        return "pendulum", "O", "B", f"({m}*{l}/2 + {M}*({l} + {r}))/({m} + {M})"  # m_tot d = this × m_tot
    if kind == "half_disk":
        r = b.param("r", "length", "radius of the half disk").name
        b.point("B", f"{r} * {u}")
        axis = "y" if up else "-y"
        b.body({"shape": "half_disk", "mass": m, "radius": r, "at": "O", "angle": angle, "axis": axis},
               Body("half", m, "half_disk", {"radius": r}, (0, 1 if up else -1, 0), origin="O", angle=angle))
        return "half", "O", "B", f"4*{r}/(3*pi)"
    if kind == "gyration":
        d = b.param("d", "length", "distance from the pivot to G").name
        k = b.param("kG", "length", "radius of gyration about G").name
        b.point("G", f"{d} * {u}")
        b.point("B", f"2*{d} * {u}")
        b.body({"mass": m, "inertia": f"{m}*{k}**2", "at": "G", "angle": angle},
               Body("body", m, inertia=f"{m}*{k}**2", origin="G", angle=angle))
        b.feature("given inertia")
        return "body", "G", "B", d
    raise ValueError(kind)


def generate(b: Builder) -> None:
    draw = b.draw
    kind = draw.choice(["particle", "rod", "rod_offset", "disk", "ring", "plate", "rod_disk", "half_disk", "gyration"])
    spring = draw.choice([None, None, "torsion", "torsion_rest", "linear", "linear_natural"])
    up = spring is not None and draw.chance(0.4)
    b.variant = f"{kind}{'-up' if up else ''}{'-' + spring if spring else ''}"
    b.feature(f"body:{kind}", "pivot")
    b.point("O", "[0, 0]")
    body, centre, tip, d = _body(b, kind, up)
    g = b.param("g", "accel", "acceleration of gravity").name
    b.gravity = f"[0, -{g}]"
    periodic = spring not in ("torsion", "torsion_rest")
    coord = b.coordinate("theta", "angle", periodic)
    sign = -1 if up else 1
    m = "m"
    if spring in ("torsion", "torsion_rest"):
        c = b.param("c", "torsion", "torsional stiffness", low=2.0, high=30.0).name
        entry = {"stiffness": c, "angle": "theta"}
        rest = "0"
        if spring == "torsion_rest":
            rest = draw.choice(["pi/6", "pi/4", "pi/2"])
            entry["rest"] = rest
        b.spring(entry, Spring("s", c, angle="theta", rest=rest, turns={body: float(sign)}))
        # every equilibrium has |θ − rest| ≤ m g d/c (|sin| ≤ 1): the search box
        bound = f"(abs({rest}) + {_moment(kind, d)}*{g}/{c} + 1)"
        coord.low, coord.high = f"-{bound}", bound
        declared = draw.choice(["plain", "kind", "range"])
        if declared == "kind":
            b.coord_yaml = {"theta": {"kind": "angle", "periodic": False}}
        elif declared == "range":
            r = f"{_moment(kind, d)}*{g}/{c}"
            lo, hi = (f"-{r}", r) if rest == "0" else (f"{rest} - {r}", f"{rest} + {r}")
            b.coord_yaml = {"theta": {"kind": "angle", "periodic": False, "range": [lo, hi]}}
            b.feature("declared range")
    elif spring in ("linear", "linear_natural"):
        k = b.param("k", "stiffness", "stiffness of the spring").name
        h = b.param("h", "length", "height of the anchor above the pivot").name
        b.point("A", f"[0, {h}]" if not up else f"[{h}, 0]")
        entry = {"stiffness": k, "between": [tip, "A"]}
        natural = "0"
        if spring == "linear_natural":
            natural = b.param("L0", "length", "natural length of the spring").name
            entry["natural_length"] = natural
        b.spring(entry, Spring("s", k, ends=(tip, "A"), on=(body, None), natural_length=natural))
    b.supports.append(Support("P" if kind == "particle" else "O", body, "P" if kind == "particle" else "O",
                              "guide" if kind == "particle" else "pivot",
                              normal="-P/norm(P)" if kind == "particle" else None))
    zero = spring != "torsion_rest" and not (up and spring in ("linear", "linear_natural"))
    _questions(b, kind, body, tip, up, zero)


def _moment(kind: str, d: str) -> str:
    """m d, the static moment of the body about the pivot (per unit g)."""
    return "(m*l/2 + M*(l + r))" if kind == "rod_disk" else f"m*{d}"


def _questions(b: Builder, kind: str, body: str, tip: str, up: bool, zero: bool) -> None:
    """A few of the questions that fit (at least one); ``zero``: θ = 0 is an equilibrium."""
    draw = b.draw
    pool = ["eom", "eom_rest", "equilibria", "modes", "modes_each", "energy", "kinematics"]
    if zero:
        pool.append("modes_zero")
    if not up:
        pool.append("reactions")
    if kind != "particle":
        pool.append("inertia")
    chosen = [q for q in pool if draw.chance(0.3)] or [draw.choice(pool)]
    release = draw.choice(["pi/2", "pi/3", "theta0"])
    if release == "theta0" and any(q in chosen for q in ("eom_rest", "reactions", "energy")):
        b.param("theta0", "angle", "angle of release")
    for q in chosen:
        if q == "eom":
            b.ask("eom")
        elif q == "eom_rest":
            b.ask("eom", {"from_rest": {"theta": release}})
        elif q == "equilibria":
            b.ask("equilibria")
        elif q == "modes":
            b.ask("modes")
        elif q == "modes_each":
            b.ask("modes", {"about": "each"})
        elif q == "modes_zero":
            b.ask("modes", {"about": {"theta": "0"}})
        elif q == "reactions":
            support = "P" if kind == "particle" else "O"
            b.ask("reactions", {"forces": [support], "from_rest": {"theta": release}})
            b.feature("reactions")
        elif q == "energy":
            b.ask("energy", {"from_rest": {"theta": release}, "to": {"theta": "0"}, "points": [tip]})
        elif q == "kinematics":
            b.ask("kinematics", {"points": [tip], "at": {"theta": "pi/6", "dot(theta)": "2", "ddot(theta)": "-1"}})
        elif q == "inertia":
            b.ask("inertia", {"body": body, "about": "O", "at": {"theta": "0"}})
