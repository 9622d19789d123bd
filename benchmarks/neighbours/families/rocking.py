"""Rocking: a body with a curved edge on the floor (a half disk, a hemisphere, a half
ring, a hemispherical shell, a quarter disk, a cylinder segment: the edge's circle of
radius R rolls, so its centre stays at height R and moves by −R θ), or a flat edge on a
drum (a slab, a rod, a half disk on its chord: tangent at the drum's point at angle θ
from the top, its contact point R θ along the flat from its middle). The contact holds
only over the edge's span, which is the oracle's search box for equilibria."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Support

FAMILY = "rocking"

CURVED = {  # shape -> (extra dimensions, span of θ)
    "half_disk": ({}, "pi/2"), "hemisphere": ({}, "pi/2"), "half_ring": ({}, "pi/2"),
    "hemispherical_shell": ({}, "pi/2"), "quarter_disk": ({}, "pi/4"),
    "cylinder_segment": ({"height": "1", "half_angle": "pi/3"}, "pi/3"),
}


def generate(b: Builder) -> None:
    draw = b.draw
    kind = draw.choice(["curved", "flat"], p=[0.6, 0.4])
    m = b.param("m", "mass", "mass of the rocking body").name
    g = b.param("g", "accel", "acceleration of gravity").name
    b.gravity = f"[0, -{g}]"
    if kind == "curved":
        shape = draw.choice(list(CURVED))
        dims, span = CURVED[shape]
        R = b.param("R", "length", "radius of the curved edge").name
        b.variant = f"{shape}-floor"
        b.coordinate("theta", "angle", periodic=False, low=f"-{span}", high=span)
        entry = {"shape": shape, "mass": m, "radius": R, **dims, "axis": "-y"}
        body = Body("rocker", m, shape, {"radius": R, **dims}, (0, -1, 0), origin=f"[-{R}*theta, {R}]", angle="theta")
        b.hide("_C", f"[-{R}*theta, 0]")
        b.supports.append(Support("C", "rocker", "_C", "rolling", normal="[0, 1]"))
        contact = {"body": "rocker", "edge": "curved", "rolls_on": "floor", "angle": "theta"}
        b.feature(f"body:{shape}", "rocking:curved on floor")
    else:
        R = b.param("R", "length", "radius of the drum", low=1.0, high=3.0).name
        shape = draw.choice(["plate", "rod", "half_disk"])
        u, ex = "[-sin(theta), cos(theta)]", "[cos(theta), sin(theta)]"
        if shape == "plate":
            a = b.param("a", "length", "thickness of the slab", low=0.1, high=0.6).name
            w = b.param("w", "length", "width of the slab", low=0.5, high=1.5).name
            entry = {"shape": "plate", "mass": m, "width": w, "height": a}
            body = Body("slab", m, "plate", {"width": w, "height": a}, angle="theta")
            offset, span, edge = f"{a}/2", f"{w}/(2*{R})", "bottom"
        elif shape == "rod":
            w = b.param("l", "length", "length of the rod", low=0.5, high=1.5).name
            entry = {"shape": "rod", "mass": m, "length": w}
            body = Body("slab", m, "rod", {"length": w}, angle="theta")
            offset, span, edge = "0", f"{w}/(2*{R})", "bottom"
        else:
            a = b.param("a", "length", "radius of the half disk", low=0.2, high=0.8).name
            entry = {"shape": "half_disk", "mass": m, "radius": a, "axis": "y"}
            body = Body("slab", m, "half_disk", {"radius": a}, (0, 1, 0), angle="theta")
            offset, span, edge = "0", f"{a}/{R}", "flat"
        body.name = "slab"
        b.variant = f"{shape}-on-drum"
        b.coordinate("theta", "angle", periodic=False, low=f"-({span})", high=f"{span}")
        b.hide("_G", f"({R} + {offset})*{u} + {R}*theta*{ex}")
        body.origin = "_G"
        b.hide("_C", f"{R}*{u}")
        b.supports.append(Support("C", "slab", "_C", "rolling", normal=u))
        contact = {"body": "slab", "edge": edge, "rolls_on": {"circle": {"centre": "[0, 0]", "radius": R,
                                                                          "side": "outside"}}, "angle": "theta"}
        b.feature(f"body:{shape}", "rocking:flat on drum")
    b.feature("contact")
    b.body(entry, body)
    b.contacts_yaml["C"] = contact
    pool = ["eom", "equilibria", "modes_zero", "reactions", "energy"]
    chosen = [x for x in pool if draw.chance(0.45)] or ["modes_zero"]
    release = draw.choice(["pi/12", "1/10", "theta0"])
    if release == "theta0" and any(x in chosen for x in ("reactions", "energy")):
        b.param("theta0", "angle", "angle of release", low=0.05, high=0.2)
    for x in chosen:
        if x == "eom":
            b.ask("eom")
        elif x == "equilibria":
            b.ask("equilibria")
        elif x == "modes_zero":
            b.ask("modes", {"about": {"theta": "0"}})
        elif x == "reactions":
            b.ask("reactions", {"forces": ["C"], "from_rest": {"theta": release}})
            b.feature("reactions")
        elif x == "energy":
            b.ask("energy", {"from_rest": {"theta": release}, "to": {"theta": "0"}})
