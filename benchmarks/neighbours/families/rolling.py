"""A round body rolling without slipping: on the floor, down an incline, inside a
fixed circle (a cylinder in a cylinder, a ball in a bowl) or outside one (off a drum).
The file names the contact; the oracle places the body by the generator's own
geometry: the centre at distance ρ from the surface along its normal, and the turn
from the rolling condition v_C = 0 integrated by hand (a line: α = −s/ρ; inside a
circle: α = −(R − ρ)θ/ρ; outside: α = (R + ρ)θ/ρ)."""

from __future__ import annotations

from benchmarks.neighbours.draw import LARGE, SMALL
from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Support

FAMILY = "rolling"

ROUND = {  # shape -> its dimensions besides the radius (file entry)
    "disk": {}, "ring": {}, "cylinder": {"height": "1"}, "sphere": {}, "spherical_shell": {},
    "cylindrical_shell": {"height": "2"}, "tube": {"inner_radius": "r/2", "height": "1"},
}


def round_body(b: Builder, name: str = "wheel", mass: str = "m", radius: str = "r"):
    """A round body's file entry (no placement: the contact places it) and oracle Body
    without a placement yet."""
    shape = b.draw.choice(list(ROUND))
    dims = dict(ROUND[shape])
    if shape == "tube":
        entry = {"shape": shape, "mass": mass, "inner_radius": f"{radius}/2", "outer_radius": radius, "height": "1"}
        odims = {"inner_radius": f"{radius}/2", "outer_radius": radius, "height": "1"}
    else:
        entry = {"shape": shape, "mass": mass, "radius": radius, **dims}
        odims = {"radius": radius, **dims}
    b.feature(f"body:{shape}")
    return entry, Body(name, mass, shape, odims)


def generate(b: Builder) -> None:
    draw = b.draw
    surface = draw.choice(["floor", "incline", "inside", "outside"], p=[0.15, 0.3, 0.3, 0.25])
    m = b.param("m", "mass", "mass of the rolling body").name
    r = b.param("r", "length", "radius of the rolling body", low=0.2, high=0.8, table=SMALL).name
    entry, body = round_body(b, "wheel", m, r)
    g = b.param("g", "accel", "acceleration of gravity").name
    b.gravity = f"[0, -{g}]"
    b.variant = f"{body.shape}-{surface}"
    b.feature(f"rolling:{surface}", "contact")
    by_angle = surface in ("floor", "incline") and draw.chance(0.25)
    if surface in ("floor", "incline"):
        q = "phi" if by_angle else "x"
        b.coordinate(q, "angle" if by_angle else "length", periodic=False, low="-10", high="10")
        s = f"(-{r}*phi)" if by_angle else "x"
        if surface == "floor":
            d, n, line = "[1, 0]", "[0, 1]", "floor"
        else:
            alpha = b.param("alpha", "angle", "angle of the incline", low=0.2, high=1.0).name
            d, n = f"[cos({alpha}), -sin({alpha})]", f"[sin({alpha}), cos({alpha})]"
            line = {"line": {"through": "[0, 0]", "angle": f"-{alpha}"}}
        b.hide("_C", f"{s}*{d}")
        b.hide("_G", f"_C + {r}*{n}")
        body.origin, body.angle = "_G", (f"-{s}/{r}" if not by_angle else "phi")
        contact = {"body": "wheel", "rolls_on": line, ("angle" if by_angle else "along"): q}
        b.supports.append(Support("C", "wheel", "_C", "rolling", normal=n))
        start = {q: "0"}
    else:
        R = b.param("R", "length", "radius of the fixed circle", low=1.0, high=3.0, table=LARGE).name
        b.assumptions.append(f"{R} > {r}" if surface == "inside" else f"{R} > 0")
        if surface == "inside" and draw.chance(0.5):
            b.file_assumptions.append(f"{R} > {r}")
        b.coordinate("theta", "angle", periodic=True)
        if surface == "inside":
            u = "[sin(theta), -cos(theta)]"
            b.hide("_G", f"({R} - {r})*{u}")
            body.angle = f"-({R} - {r})*theta/{r}"
            normal = "[-sin(theta), cos(theta)]"
        else:
            u = "[-sin(theta), cos(theta)]"
            b.hide("_G", f"({R} + {r})*{u}")
            body.angle = f"({R} + {r})*theta/{r}"
            normal = u
        b.hide("_C", f"{R}*{u}")
        body.origin = "_G"
        contact = {"body": "wheel", "rolls_on": {"circle": {"centre": "[0, 0]", "radius": R, "side": surface}},
                   "along": "theta"}
        b.supports.append(Support("C", "wheel", "_C", "rolling", normal=normal))
        start = {"theta": "0"}
    b.body(entry, body)
    b.contacts_yaml["C"] = contact
    _questions(b, surface, start)


def _questions(b: Builder, surface: str, start: dict) -> None:
    draw = b.draw
    (q,) = start
    pool = ["eom", "reactions", "energy"]
    if surface in ("inside", "outside"):
        pool += ["equilibria", "modes_zero" if surface == "inside" else "modes_each"]
    chosen = [x for x in pool if draw.chance(0.45)] or [draw.choice(pool)]
    if surface in ("inside", "outside"):
        release = draw.choice(["pi/2", "pi/3", "theta0", "pi/6"])
        if release == "theta0" and any(x in chosen for x in ("reactions", "energy", "eom")):
            b.param("theta0", "angle", "angle of release", low=0.1, high=1.4)
        rest, to = {q: release}, {q: "0" if surface == "inside" else f"2*{release}" if release != "pi/2" else "pi"}
    else:
        rest, to = start, {q: draw.choice(["1", "2", "1/2"])}
    for x in chosen:
        if x == "eom":
            b.ask("eom", {"from_rest": rest} if draw.chance(0.4) else None)
        elif x == "equilibria":
            b.ask("equilibria")
        elif x == "modes_zero":
            b.ask("modes", {"about": {q: "0"}})
        elif x == "modes_each":
            b.ask("modes", {"about": "each"})
        elif x == "reactions":
            b.ask("reactions", {"forces": ["C"], "from_rest": rest})
            b.feature("reactions")
        elif x == "energy":
            b.ask("energy", {"from_rest": rest, "to": to})
