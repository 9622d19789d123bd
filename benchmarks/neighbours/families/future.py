"""Exam problems the format cannot state yet (issue 40), written as a student would
write them once it can, in the syntax the issue suggests: applied forces and couples
(`forces:`), a rolling body given by its radius of gyration, a composite body that
rolls, a spring on a rolling body's centre, a rod hinged to a turning shaft (a solid
body in a turning frame), a body's point that sticks in an impact. Until the format
has them they are refused (exit 2, or a question not answered), and the report counts
the refusals by reason; the oracle already models each, so they are judged the day
they are answered."""

from __future__ import annotations

from fractions import Fraction

from benchmarks.neighbours.draw import LARGE, SMALL
from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Force, Part, Spring, Support

FAMILY = "future"


def generate(b: Builder) -> None:
    kind = b.draw.choice(["pull", "couple", "gyration", "eccentric", "spring_centre", "shaft", "ledge"])
    {"pull": _pull, "couple": _couple, "gyration": _gyration, "eccentric": _eccentric,
     "spring_centre": _spring_centre, "shaft": _shaft, "ledge": _ledge}[kind](b)
    b.variant = kind
    b.future = kind


def _g(b: Builder) -> str:
    g = b.param("g", "accel", "acceleration of gravity").name
    b.gravity = f"[0, -{g}]"
    return g


def _pull(b: Builder) -> None:
    """A cylinder rolling on the floor pulled at its centre: a = 2F/(3m) (at an angle α)."""
    m = b.param("m", "mass", "mass of the cylinder").name
    r = b.param("r", "length", "radius of the cylinder").name
    F = b.param("F", "mass", "pull", low=1.0, high=10.0).name
    F_unit = b.params[-1]
    F_unit.kind = "force"
    F_unit.value, F_unit.si = (("10 N", "10") if F_unit.value else (None, None))
    al = b.param("alpha", "angle", "angle of the pull above the horizontal").name
    _g(b)
    b.coordinate("x", "length", periodic=False)
    b.point("G", f"[x, {r}]")
    b.body({"shape": "cylinder", "mass": m, "radius": r, "height": "1", "at": "G", "angle": f"-x/{r}"},
           Body("cylinder", m, "cylinder", {"radius": r, "height": "1"}, origin="G", angle=f"-x/{r}"))
    force = f"[{F}*cos({al}), {F}*sin({al})]"
    b.forces_yaml["pull"] = {"on": "cylinder", "at": "G", "force": force}
    b.forces.append(Force("pull", "cylinder", at="G", force=force))
    b.feature("applied force")
    b.ask("eom", {"from_rest": {"x": "0"}})


def _couple(b: Builder) -> None:
    """A rod on a pivot turned by a motor's couple M0: sin θ = 2 M0/(m g l)."""
    m = b.param("m", "mass", "mass of the rod").name
    l = b.param("l", "length", "length of the rod").name
    g = _g(b)
    M0 = _moment_below(b, "M0", "the motor's couple", {m: 1, g: 1, l: 1}, 2)
    b.assumptions.append(f"2*{M0} < {m}*{g}*{l}")
    b.coordinate("theta", "angle")
    b.point("O", "[0, 0]")
    b.point("G", f"{l}/2*[sin(theta), -cos(theta)]")
    b.body({"shape": "rod", "mass": m, "length": l, "at": "G", "angle": "theta", "axis": "y"},
           Body("rod", m, "rod", {"length": l}, (0, 1, 0), origin="G", angle="theta"))
    b.couples_yaml["motor"] = {"on": "rod", "moment": M0}
    b.forces.append(Force("motor", "rod", couple=M0))
    b.feature("applied couple")
    b.ask("equilibria")
    b.ask("eom")


MOMENTS = [("2 N*m", "2"), ("1", "1"), ("1/2 N*m", "1/2"), ("0.2 N*m", "1/5"), ("1/10", "1/10")]


def _moment_below(b: Builder, name: str, description: str, product: dict[str, int], factor: int) -> str:
    """A couple's parameter M with factor·M below the product of the named parameters
    (its existence condition, such as 2 M0 < m g l): a value from the table that keeps
    it where every factor has a value, else symbolic (the condition an assumption)."""
    given = {p.name: p.si for p in b.params}
    if all(given.get(n) for n in product):
        bound = 1.0
        for n, power in product.items():
            bound *= float(Fraction(given[n])) ** power
        table = [(t, si) for t, si in MOMENTS if factor * float(Fraction(si)) < 0.8 * bound]
        if table:
            return b.param(name, "moment", description, symbolic=False, table=table, low=0.1, high=0.4).name
    return b.param(name, "moment", description, symbolic=True, low=0.1, high=0.4).name


def _rolling_inside(b: Builder, body: Body, entry: dict, r: str, extra: dict | None = None) -> None:
    R = b.param("R", "length", "radius of the fixed cylinder", low=1.0, high=3.0, table=[x for x in LARGE if x[1] != "4/5"]).name
    b.assumptions.append(f"{R} > 2*{r}")
    b.coordinate("theta", "angle")
    b.hide("_G", f"({R} - {r})*[sin(theta), -cos(theta)]")
    body.origin = "_G"
    body.angle = f"-({R} - {r})*theta/{r}" if body.angle is None else body.angle
    b.body(entry, body)
    b.contacts_yaml["C"] = {"body": body.name, **(extra or {}),
                            "rolls_on": {"circle": {"centre": "[0, 0]", "radius": R, "side": "inside"}}, "along": "theta"}
    b.feature("contact", "rolling:inside")


def _gyration(b: Builder) -> None:
    """A spool of radius of gyration k rolling inside a cylinder: ω² = g/((R − r)(1 + k²/r²))."""
    m = b.param("m", "mass", "mass of the spool").name
    r = b.param("r", "length", "radius of the spool", low=0.2, high=0.5, table=SMALL).name
    k = b.param("k", "length", "radius of gyration", low=0.1, high=0.4, table=[("5 cm", "1/20"), ("0.1", "1/10")]).name
    _g(b)
    body = Body("spool", m, inertia=f"{m}*{k}**2")
    _rolling_inside(b, body, {"mass": m, "inertia": f"{m}*{k}**2"}, r, {"radius": r})  # the radius it rolls on
    b.feature("given inertia rolling")
    b.ask("modes", {"about": {"theta": "0"}})


def _eccentric(b: Builder) -> None:
    """A disk with a particle fixed on its rim rolls inside a cylinder."""
    m = b.param("m", "mass", "mass of the disk").name
    mp = b.param("mp", "mass", "mass of the particle", low=0.1, high=0.5).name
    r = b.param("r", "length", "radius of the disk", low=0.2, high=0.5, table=SMALL).name
    _g(b)
    parts = {"disk": {"shape": "disk", "mass": m, "radius": r},
             "bob": {"shape": "particle", "mass": mp, "at": f"[0, -{r}/2]"}}
    body = Body("wheel", parts=(Part("disk", m, {"radius": r}), Part("particle", mp, {}, ("0", f"-{r}/2"))))
    _rolling_inside(b, body, {"parts": parts}, r)
    b.feature("composite rolling")
    b.ask("equilibria")
    b.ask("eom")


def _spring_centre(b: Builder) -> None:
    """A disk rolling on the floor tied to a wall by a spring at its centre: ω² = 2k/(3m)."""
    m = b.param("m", "mass", "mass of the disk").name
    r = b.param("r", "length", "radius of the disk").name
    k = b.param("k", "stiffness", "stiffness of the spring").name
    L = b.param("L", "length", "natural length of the spring").name
    _g(b)
    b.coordinate("x", "length", periodic=False, low=f"-{L}/2", high=f"{L}/2")
    b.hide("_G", f"[x, {r}]")
    b.point("W", f"[-{L}, {r}]")
    b.body({"shape": "disk", "mass": m, "radius": r}, Body("wheel", m, "disk", {"radius": r}, origin="_G",
                                                          angle=f"-x/{r}"))
    b.contacts_yaml["C"] = {"body": "wheel", "rolls_on": "floor", "along": "x"}
    b.springs_yaml["s"] = {"stiffness": k, "between": ["wheel", "W"], "natural_length": L}
    b.springs.append(Spring("s", k, ends=("_G", "W"), on=("wheel", None), natural_length=L))
    b.feature("spring on a rolling body", "contact")
    b.ask("modes", {"about": {"x": "0"}})


def _shaft(b: Builder) -> None:
    """A rod hinged to a vertical shaft turning at Ω: θ = 0 stable below √(3g/(2l))."""
    m = b.param("m", "mass", "mass of the rod").name
    l = b.param("l", "length", "length of the rod").name
    W = b.param("Omega", "rate", "rate of the shaft").name
    g = b.param("g", "accel", "acceleration of gravity").name
    b.gravity = f"[0, -{g}, 0]"
    b.planar = False
    b.frames_yaml["shaft"] = {"axis": "y", "rate": W}
    b.coordinate("theta", "angle")
    b.point("G", f"{l}/2*[sin(theta)*cos({W}*t), -cos(theta), -sin(theta)*sin({W}*t)]")
    turns = (("y", f"{W}*t"), ("z", "theta"))
    b.body({"shape": "rod", "mass": m, "length": l, "at": "G", "axis": "y",
            "orientation": [["y", f"{W}*t"], ["z", "theta"]]},
           Body("rod", m, "rod", {"length": l}, (0, 1, 0), origin="G", turns=turns))
    b.feature("solid body in a turning frame")
    b.ask("equilibria", {"frame": "shaft"})
    b.ask("modes", {"frame": "shaft", "about": "each"})


def _ledge(b: Builder) -> None:
    """A rod falling flat catches a ledge with one end: ω after = 3v₀/(2l)."""
    m = b.param("m", "mass", "mass of the rod").name
    l = b.param("l", "length", "length of the rod").name
    v = b.param("v0", "speed", "speed before the impact").name
    b.coordinate("x", "length", periodic=False)
    b.coordinate("y", "length", periodic=False)
    b.coordinate("theta", "angle")
    b.point("G", "[x, y]")
    b.point("A", f"G + {l}/2*[cos(theta), sin(theta)]")
    b.body({"shape": "rod", "mass": m, "length": l, "at": "G", "angle": "theta"},
           Body("rod", m, "rod", {"length": l}, origin="G", angle="theta"))
    b.feature("body point sticks", "impact")
    b.ask("impact", {"at": {"theta": "0"}, "before": {"y": f"-{v}"}, "collisions": {"A": {"sticks": True}}})
