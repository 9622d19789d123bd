"""Masses on springs: a block on a smooth floor between two springs, two blocks and
three springs, a particle on a spring hanging from a pivot (the elastic pendulum), a
particle held in the plane by two springs under gravity, a bead on a vertical ring
with a spring to a fixed point, a particle on an incline against a spring."""

from __future__ import annotations

from benchmarks.neighbours.families.base import Builder
from benchmarks.neighbours.scene import Body, Spring, Support

FAMILY = "springs"


def generate(b: Builder) -> None:
    kind = b.draw.choice(["block", "two_blocks", "elastic", "two_springs", "ring", "incline"])
    {"block": _block, "two_blocks": _two_blocks, "elastic": _elastic, "two_springs": _two_springs,
     "ring": _ring, "incline": _incline}[kind](b)
    b.variant = kind
    b.feature("linear spring")


def _g(b: Builder) -> str:
    g = b.param("g", "accel", "acceleration of gravity").name
    b.gravity = f"[0, -{g}]"
    return g


def _ask(b: Builder, pool: list[tuple[str, dict | None]]) -> None:
    chosen = [x for x in pool if b.draw.chance(0.45)] or [b.draw.choice(pool)]
    for kind, opts in chosen:
        b.ask(kind, opts)


def _block(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the block").name
    a = b.param("a", "length", "side of the block", low=0.1, high=0.3).name
    k1 = b.param("k1", "stiffness", "stiffness of the left spring").name
    k2 = b.param("k2", "stiffness", "stiffness of the right spring").name
    L = b.param("L", "length", "natural length of each spring", low=0.5, high=1.5).name
    _g(b)
    b.coordinate("x", "length", periodic=False, low=f"-{L}/2", high=f"{L}/2")
    b.point("C", "[x, 0]")
    b.point("G", f"[x, {a}/2]")
    b.point("W1", f"[-{L}, {a}/2]")
    b.point("W2", f"[{L}, {a}/2]")
    b.body({"shape": "plate", "mass": m, "width": a, "height": a, "at": "G"},
           Body("block", m, "plate", {"width": a, "height": a}, origin="G"))
    for name, k, w in (("left", k1, "W1"), ("right", k2, "W2")):
        b.spring({"stiffness": k, "between": ["G", w], "natural_length": L},
                 Spring(name, k, ends=("G", w), on=("block", None), natural_length=L))
    b.supports.append(Support("C", "block", "C", "guide", normal="[0, 1]", moment=True))
    b.feature("sliding block")
    _ask(b, [("eom", None), ("equilibria", None), ("modes", {"about": {"x": "0"}}),
             ("reactions", {"forces": ["C"], "at": {"x": "1/10", "dot(x)": "1"}}),
             ("energy", {"at": {"x": "0", "dot(x)": "1"}, "to": {"x": "1/10"}})])


def _two_blocks(b: Builder) -> None:
    m = b.param("m", "mass", "mass of each block").name
    k = b.param("k", "stiffness", "stiffness of the outer springs").name
    kc = b.param("kc", "stiffness", "stiffness of the middle spring").name
    L = b.param("L", "length", "natural length of each spring", low=0.5, high=1.5).name
    b.coordinate("x1", "length", periodic=False, low=f"-{L}/2", high=f"{L}/2")
    b.coordinate("x2", "length", periodic=False, low=f"-{L}/2", high=f"{L}/2")
    b.point("P1", f"[{L} + x1, 0]")
    b.point("P2", f"[2*{L} + x2, 0]")
    b.point("W1", "[0, 0]")
    b.point("W2", f"[3*{L}, 0]")
    for i in (1, 2):
        b.body({"shape": "particle", "mass": m, "at": f"P{i}"}, Body(f"block{i}", m, "particle", origin=f"P{i}"))
    for name, kk, a, c, on in (("s1", k, "W1", "P1", ("block1", None)), ("s2", kc, "P1", "P2", ("block1", "block2")),
                               ("s3", k, "P2", "W2", ("block2", None))):
        b.spring({"stiffness": kk, "between": [a, c], "natural_length": L},
                 Spring(name, kk, ends=(c, a) if on[1] is None else (a, c), on=on, natural_length=L))
    _ask(b, [("eom", None), ("equilibria", None), ("modes", {"about": {"x1": "0", "x2": "0"}})])


def _elastic(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the particle").name
    k = b.param("k", "stiffness", "stiffness of the spring", low=50.0, high=200.0).name
    L = b.param("L", "length", "natural length of the spring").name
    _g(b)
    b.coordinate("r", "length", periodic=False, low=f"{L}/100", high=f"10*{L}")
    b.coordinate("theta", "angle")
    b.point("O", "[0, 0]")
    b.point("P", "r*[sin(theta), -cos(theta)]")
    b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bob", m, "particle", origin="P"))
    b.spring({"stiffness": k, "between": ["O", "P"], "natural_length": L},
             Spring("s", k, ends=("P", "O"), on=("bob", None), natural_length=L))
    req = f"{L} + {m}*{b.gravity.split('-')[1][:-1]}/{k}"
    _ask(b, [("eom", None), ("equilibria", None), ("modes", {"about": {"r": req, "theta": "0"}}),
             ("energy", {"at": {"r": req, "theta": "0", "dot(r)": "0", "dot(theta)": "1"}})])


def _two_springs(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the particle").name
    k = b.param("k", "stiffness", "stiffness of each spring", low=50.0, high=200.0).name
    a = b.param("a", "length", "half the distance between the anchors").name
    natural = b.draw.chance(0.6)
    L = b.draw.choice([f"{a}/2", f"{a}/3", f"2*{a}/3"]) if natural else "0"  # shorter than the anchors' half distance
    _g(b)
    b.coordinate("x", "length", periodic=False, low=f"-{a}/2", high=f"{a}/2")
    b.coordinate("y", "length", periodic=False, low=f"-3*{a}", high=f"-{a}/100")
    b.point("P", "[x, y]")
    b.point("A", f"[-{a}, 0]")
    b.point("B", f"[{a}, 0]")
    b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bob", m, "particle", origin="P"))
    for name, w in (("left", "A"), ("right", "B")):
        entry = {"stiffness": k, "between": ["P", w]}
        if natural:
            entry["natural_length"] = L
        b.spring(entry, Spring(name, k, ends=("P", w), on=("bob", None), natural_length=L))
    _ask(b, [("eom", None), ("equilibria", None), ("modes", None)])


def _ring(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the bead").name
    R = b.param("R", "length", "radius of the ring").name
    k = b.param("k", "stiffness", "stiffness of the spring", low=5.0, high=60.0).name
    _g(b)
    b.coordinate("theta", "angle")
    b.point("P", f"{R}*[sin(theta), -cos(theta)]")
    b.point("A", f"[0, {R}]")
    b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bead", m, "particle", origin="P"))
    b.spring({"stiffness": k, "between": ["P", "A"]}, Spring("s", k, ends=("P", "A"), on=("bead", None)))
    b.supports.append(Support("P", "bead", "P", "guide", normal="-P/norm(P)", two_sided=True))
    _ask(b, [("eom", None), ("equilibria", None), ("modes", {"about": "each"}),
             ("reactions", {"forces": [{"at": "P", "two_sided": True}], "from_rest": {"theta": "pi/2"}})])


def _incline(b: Builder) -> None:
    m = b.param("m", "mass", "mass of the particle").name
    alpha = b.param("alpha", "angle", "angle of the incline", low=0.2, high=1.0).name
    k = b.param("k", "stiffness", "stiffness of the spring").name
    L = b.param("L", "length", "natural length of the spring").name
    _g(b)
    b.coordinate("s", "length", periodic=False, low=f"-{L}/2", high=f"10*{L}")
    d = f"[cos({alpha}), -sin({alpha})]"
    b.point("P", f"({L} + s)*{d}")
    b.point("O", "[0, 0]")
    b.body({"shape": "particle", "mass": m, "at": "P"}, Body("bob", m, "particle", origin="P"))
    b.spring({"stiffness": k, "between": ["P", "O"], "natural_length": L},
             Spring("s1", k, ends=("P", "O"), on=("bob", None), natural_length=L))
    b.supports.append(Support("P", "bob", "P", "guide", normal=f"[sin({alpha}), cos({alpha})]"))
    _ask(b, [("eom", None), ("equilibria", None), ("modes", None),
             ("reactions", {"forces": ["P"], "from_rest": {"s": "0"}})])
