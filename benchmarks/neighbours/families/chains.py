"""Bodies joined in chains: a double pendulum of rods or particles (mixed, with a
torsion spring between the links), a chain of three to five rods, a pendulum hanging
from a block that slides on a smooth floor against a spring, two pendulums coupled by
a spring between their bobs."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Spring, Support

FAMILY = "chains"


def _u(q: str) -> str:
    return f"[sin({q}), -cos({q})]"


def generate(b: Builder) -> None:
    kind = b.draw.choice(["double", "chain", "cart", "coupled"], p=[0.4, 0.2, 0.25, 0.15])
    g = b.param("g", "accel", "acceleration of gravity").name
    b.gravity = f"[0, -{g}]"
    {"double": _double, "chain": _chain, "cart": _cart, "coupled": _coupled}[kind](b)


def _link(b: Builder, i: int, top: str, q: str, kind: str, m: str, l: str) -> str:
    """Link i from point ``top`` along u(q): a rod (centre halfway) or a particle at its end."""
    end = b.point(f"P{i}", f"{top} + {l}*{_u(q)}" if top != "O" else f"{l}*{_u(q)}")
    if kind == "rod":
        b.point(f"G{i}", f"{top} + {l}/2*{_u(q)}" if top != "O" else f"{l}/2*{_u(q)}")
        b.body({"shape": "rod", "mass": m, "length": l, "at": f"G{i}", "angle": q, "axis": "y"},
               Body(f"rod{i}", m, "rod", {"length": l}, (0, 1, 0), origin=f"G{i}", angle=q))
    else:
        b.body({"shape": "particle", "mass": m, "at": end}, Body(f"bob{i}", m, "particle", origin=end))
    return end


def _double(b: Builder) -> None:
    draw = b.draw
    kinds = [draw.choice(["rod", "particle"]), draw.choice(["rod", "particle"])]
    same = draw.chance(0.5)
    m1 = b.param("m", "mass", "mass of the upper link").name
    m2 = m1 if same else b.param("m2", "mass", "mass of the lower link").name
    l1 = b.param("l", "length", "length of the upper link").name
    l2 = l1 if same else b.param("l2", "length", "length of the lower link").name
    b.point("O", "[0, 0]")
    b.coordinate("theta", "angle")
    b.coordinate("phi", "angle")
    a = _link(b, 1, "O", "theta", kinds[0], m1, l1)
    _link(b, 2, a, "phi", kinds[1], m2, l2)
    b.variant = f"double-{kinds[0]}-{kinds[1]}"
    b.feature(*(f"body:{k}" for k in kinds), "pivot", "joint")
    if draw.chance(0.3) and kinds == ["rod", "rod"]:
        c = b.param("c", "torsion", "stiffness of the torsion spring at the joint").name
        b.spring({"stiffness": c, "angle": "phi - theta"}, Spring("s", c, angle="phi - theta",
                                                                   turns={"rod1": -1.0, "rod2": 1.0}))
    if kinds == ["rod", "rod"]:
        b.supports.append(Support("O", "rod1", "O", "pivot"))
        b.supports.append(Support("P1", "rod2", "P1", "pivot", by="rod1"))
    pool = ["eom", "eom_rest", "equilibria", "modes_zero", "kinematics"]
    if kinds == ["rod", "rod"]:
        pool.append("reactions")
    for x in [x for x in pool if draw.chance(0.4)] or ["modes_zero"]:
        if x == "eom":
            b.ask("eom")
        elif x == "eom_rest":
            b.ask("eom", {"from_rest": {"theta": "pi/2", "phi": draw.choice(["pi/2", "0", "pi"])}})
        elif x == "equilibria":
            b.ask("equilibria")
        elif x == "modes_zero":
            b.ask("modes", {"about": {"theta": "0", "phi": "0"}})
        elif x == "kinematics":
            b.ask("kinematics", {"points": ["P2"], "at": {"theta": "pi/2", "phi": "0", "dot(theta)": "1",
                                                           "dot(phi)": "-2", "ddot(theta)": "0", "ddot(phi)": "0"},
                                 "distance": ["O", "P2"]})
        elif x == "reactions":
            b.ask("reactions", {"forces": [{"at": "O", "on": "rod1"}, {"at": "P1", "on": "rod2", "by": "rod1"}],
                                "from_rest": {"theta": "pi/2", "phi": "pi/2"}})
            b.feature("reactions")


def _chain(b: Builder) -> None:
    n = b.draw.integer(3, 5)
    m = b.param("m", "mass", "mass of each rod").name
    l = b.param("l", "length", "length of each rod").name
    b.point("O", "[0, 0]")
    top = "O"
    for i in range(1, n + 1):
        q = f"th{i}"
        b.coordinate(q, "angle")
        top = _link(b, i, top, q, "rod", m, l)
    b.variant = f"chain-{n}"
    b.feature("body:rod", "pivot", "joint", f"{n} degrees of freedom")
    zero = {f"th{i}": "0" for i in range(1, n + 1)}
    b.ask("modes", {"about": zero})
    if b.draw.chance(0.3):
        b.ask("eom", {"from_rest": {f"th{i}": ("pi/2" if i == 1 else "0") for i in range(1, n + 1)}})


def _cart(b: Builder) -> None:
    draw = b.draw
    M = b.param("M", "mass", "mass of the block").name
    w = b.param("w", "length", "width of the block", low=0.1, high=0.4).name
    k = b.param("k", "stiffness", "stiffness of the spring").name
    m = b.param("m", "mass", "mass of the pendulum").name
    l = b.param("l", "length", "length of the pendulum").name
    rod = draw.chance(0.5)
    # the spring's length |x + l| stays positive: the block does not pass its anchor
    b.coordinate("x", "length", periodic=False, low=f"-9*{l}/10", high="5")
    b.coordinate("theta", "angle")
    b.point("A", "[x, 0]")
    b.point("W", f"[-{l}, 0]")
    b.body({"shape": "box", "mass": M, "width": w, "depth": w, "height": w, "at": "A"},
           Body("block", M, "box", {"width": w, "depth": w, "height": w}, origin="A"))
    b.spring({"stiffness": k, "between": ["A", "W"], "natural_length": l},
             Spring("s", k, ends=("A", "W"), on=("block", None), natural_length=l))
    if rod:
        b.point("G", f"A + {l}/2*{_u('theta')}")
        b.body({"shape": "rod", "mass": m, "length": l, "at": "G", "angle": "theta", "axis": "y"},
               Body("rod", m, "rod", {"length": l}, (0, 1, 0), origin="G", angle="theta"))
    else:
        b.point("P", f"A + {l}*{_u('theta')}")
        b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bob", m, "particle", origin="P"))
    b.variant = f"cart-{'rod' if rod else 'particle'}"
    b.feature("sliding block", "pivot on a moving body", "body:rod" if rod else "body:particle")
    for x in [x for x in ["eom", "equilibria", "modes_zero", "eom_rest"] if draw.chance(0.45)] or ["modes_zero"]:
        if x == "eom":
            b.ask("eom")
        elif x == "eom_rest":
            b.ask("eom", {"from_rest": {"x": "0", "theta": "pi/3"}})
        elif x == "equilibria":
            b.ask("equilibria")
        else:
            b.ask("modes", {"about": {"x": "0", "theta": "0"}})


def _coupled(b: Builder) -> None:
    m = b.param("m", "mass", "mass of each bob").name
    l = b.param("l", "length", "length of each pendulum").name
    d = b.param("d", "length", "distance between the pivots").name
    k = b.param("k", "stiffness", "stiffness of the spring").name
    b.coordinate("theta", "angle")
    b.coordinate("phi", "angle")
    b.point("P", f"{l}*{_u('theta')}")
    b.point("Q", f"[{d}, 0] + {l}*{_u('phi')}")
    b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bob1", m, "particle", origin="P"))
    b.body({"shape": "particle", "mass": m, "at": "Q"}, Body("bob2", m, "particle", origin="Q"))
    b.spring({"stiffness": k, "between": ["P", "Q"], "natural_length": d},
             Spring("s", k, ends=("P", "Q"), on=("bob1", "bob2"), natural_length=d))
    b.variant = "coupled"
    b.feature("body:particle", "linear spring between bodies")
    b.ask("modes", {"about": {"theta": "0", "phi": "0"}})
    if b.draw.chance(0.4):
        b.ask("eom")
