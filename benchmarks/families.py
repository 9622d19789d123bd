"""Scalable problem families for the benchmarks, generated as rbdsolve YAML text.

Each family is a function ``size -> Case``: the problem text (every parameter with a
rational value, so both routes can run) and, where a hand formula gives them, the exact
mass and stiffness matrices at the equilibrium for the 50-digit reference.

Families (and the rbdsolve question each uses):

- ``chain_points``: an n-link planar pendulum of point masses m on massless links l,
  angles th1..thn from the downward vertical; ``modes`` about the hanging state.
- ``chain_rods``: the same with uniform rods (mass m, length l); ``modes``.
- ``springs``: n masses m on a line joined by springs k, the first one to a wall;
  ``modes`` about the rest state.
- ``composite``: one body made of k parts (boxes and spheres placed off centre);
  ``inertia`` about the origin.
- ``impact``: an n-link chain of rods hanging at rest, struck at its lowest end by a
  horizontal impulse P; ``impact``.
- ``eom_chain``: the ``chain_points`` scene asked for Lagrange's equations (``eom``).
- ``spin``: a free body with a random (seeded) full 3×3 inertia tensor whose entries
  have ``size`` decimal digits; ``steady_spin``.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from fractions import Fraction
from typing import Callable

# Rational values for every parameter: both routes run, the reference is exact.
G_VALUE = Fraction(981, 100)


@dataclass(frozen=True)
class Case:
    """One benchmark problem: its family, size and YAML text, and (for modes) the exact
    M and K at the equilibrium as rational matrices, or None where no hand formula is
    used (the reference then comes from rbdsolve's exact M and K)."""

    family: str
    size: int
    text: str
    question: str
    M: tuple[tuple[Fraction, ...], ...] | None = None
    K: tuple[tuple[Fraction, ...], ...] | None = None


def _values(**values: Fraction | int) -> str:
    return "values: {" + ", ".join(f"{k}: {v}" for k, v in values.items()) + "}\n"


def _chain_points_text(n: int, rods: bool) -> str:
    """The points P1..Pn (link ends) and, for rods, their midpoints G1..Gn."""
    lines = ["points:", "  P0: [0, 0]"]
    for i in range(1, n + 1):
        lines.append(f"  P{i}: P{i - 1} + l * [sin(th{i}), -cos(th{i})]")
        if rods:
            lines.append(f"  G{i}: P{i - 1} + l/2 * [sin(th{i}), -cos(th{i})]")
    return "\n".join(lines) + "\n"


def _chain_bodies_text(n: int, rods: bool) -> str:
    lines = ["bodies:"]
    for i in range(1, n + 1):
        if rods:
            lines.append(f"  rod{i}: {{shape: rod, mass: m, length: l, at: G{i}, angle: th{i}, axis: y}}")
        else:
            lines.append(f"  bob{i}: {{shape: particle, mass: m, at: P{i}}}")
    return "\n".join(lines) + "\n"


def _at_rest(n: int, name: str = "th") -> str:
    return "{" + ", ".join(f"{name}{i}: 0" for i in range(1, n + 1)) + "}"


def _chain_scene(n: int, rods: bool, title: str) -> str:
    coords = ", ".join(f"th{i}" for i in range(1, n + 1))
    return (f"title: {title}\n"
            "parameters: {m: mass, l: length, g: acceleration}\n"
            + _values(m=1, l=1, g=G_VALUE)
            + f"coordinates: [{coords}]\n"
            "gravity: [0, -g]\n"
            + _chain_points_text(n, rods) + _chain_bodies_text(n, rods))


def chain_points(n: int) -> Case:
    """n-link chain of point masses; M_ij = m l² (n − max(i,j) + 1), K = diag(m g l (n − i + 1))
    (i, j from 1), with m = l = 1 and g = 981/100."""
    text = _chain_scene(n, False, f"{n}-link chain of point masses") + \
        f"questions:\n  - modes: {{about: {_at_rest(n)}}}\n"
    M = tuple(tuple(Fraction(n - max(i, j) + 1) for j in range(1, n + 1)) for i in range(1, n + 1))
    K = tuple(tuple(G_VALUE * (n - i + 1) if i == j else Fraction(0) for j in range(1, n + 1))
              for i in range(1, n + 1))
    return Case("chain_points", n, text, "modes", M, K)


def eom_chain(n: int) -> Case:
    """The n-link chain of point masses asked for its equations of motion (``eom``): no
    reference numbers (the answer is a set of equations); the numeric route measures its
    own error against 50 digits."""
    text = _chain_scene(n, False, f"{n}-link chain of point masses") + "questions: [eom]\n"
    return Case("eom_chain", n, text, "eom")


def chain_rods(n: int) -> Case:
    """n-link chain of uniform rods (m = l = 1, g = 981/100); the reference uses
    rbdsolve's exact M and K."""
    text = _chain_scene(n, True, f"{n}-link chain of rods") + \
        f"questions:\n  - modes: {{about: {_at_rest(n)}}}\n"
    return Case("chain_rods", n, text, "modes")


def springs(n: int) -> Case:
    """n masses m sliding on parallel horizontal rails a apart (x1..xn their
    displacements), each joined to the next, and the first to a wall point, by a spring k
    of zero natural length: V = ½ k Σ ((x_i − x_{i−1})² + a²), so M = m 1 and
    K = k tridiag(−1, 2, −1) with K_nn = k, about the rest state x = 0.

    (Zero natural length keeps V smooth: a spring with natural length along the line
    gives |x_i − x_{i−1} + a|, whose Abs the numeric route cannot compile.)"""
    coords = ", ".join(f"x{i}" for i in range(1, n + 1))
    points = "\n".join(f"  P{i}: [x{i}, {i}*a]" for i in range(1, n + 1))
    bodies = "\n".join(f"  mass{i}: {{shape: particle, mass: m, at: P{i}}}" for i in range(1, n + 1))
    springs_ = "\n".join(f"  s{i}: {{stiffness: k, between: [P{i - 1}, P{i}]}}" for i in range(1, n + 1))
    text = (f"title: {n} masses and springs\n"
            "parameters: {m: mass, k: stiffness, a: spacing}\n"
            + _values(m=1, k=3, a=1)
            + f"coordinates: [{coords}]\n"
            f"points:\n  P0: [0, 0]\n{points}\n"
            f"bodies:\n{bodies}\nsprings:\n{springs_}\n"
            f"questions:\n  - modes: {{about: {_at_rest(n, 'x')}}}\n")
    k = Fraction(3)
    M = tuple(tuple(Fraction(int(i == j)) for j in range(n)) for i in range(n))
    K = tuple(tuple(_spring_entry(i, j, n) * k for j in range(n)) for i in range(n))
    return Case("springs", n, text, "modes", M, K)


def _spring_entry(i: int, j: int, n: int) -> Fraction:
    if i == j:
        return Fraction(1 if i == n - 1 else 2)
    return Fraction(-1 if abs(i - j) == 1 else 0)


def composite(k: int) -> Case:
    """One body of k parts: boxes and spheres of mass m, size a, at rational offsets
    spread over a lattice (every third part a hole-free sphere); inertia about O."""
    parts = []
    for i in range(k):
        at = f"[{i % 3}*a, {(i // 3) % 3}*a, {i // 9}*a]"
        if i % 3 == 2:
            parts.append(f"      part{i}: {{shape: sphere, mass: m, radius: a/2, at: {at}}}")
        else:
            parts.append(f"      part{i}: {{shape: box, mass: m, width: a, depth: a/2, height: a/3, at: {at}}}")
    text = (f"title: composite body of {k} parts\n"
            "parameters: {m: mass, a: length}\n" + _values(m=1, a=1)
            + "points:\n  O: [0, 0, 0]\n"
            "bodies:\n  assembly:\n    at: [a/7, a/5, a/3]\n    parts:\n" + "\n".join(parts) + "\n"
            "questions:\n  - inertia: {body: assembly, about: O}\n")
    return Case("composite", k, text, "inertia")


def impact(n: int) -> Case:
    """An n-link chain of rods hanging at rest, struck at its lowest end Pn by a
    horizontal impulse P."""
    text = (_chain_scene(n, True, f"impulse on an {n}-link chain of rods").replace(
        "parameters: {m: mass, l: length, g: acceleration}",
        "parameters: {m: mass, l: length, g: acceleration, P: impulse}").replace(
        "values: {m: 1, l: 1, g: 981/100}", "values: {m: 1, l: 1, g: 981/100, P: 2}")
        + f"questions:\n  - impact:\n      at: {_at_rest(n)}\n      impulses: {{P{n}: [P, 0]}}\n")
    return Case("impact", n, text, "impact")


def spin(digits: int) -> Case:
    """A free body whose inertia is J = A Aᵀ + 1 (positive definite) with A's entries
    random integers of ``digits`` digits over 10^digits (seeded, reproducible)."""
    rng = random.Random(1000 + digits)
    A = [[Fraction(rng.randint(-10 ** digits + 1, 10 ** digits - 1), 10 ** digits) for _ in range(3)]
         for _ in range(3)]
    J = [[sum(A[i][r] * A[j][r] for r in range(3)) + (1 if i == j else 0) for j in range(3)]
         for i in range(3)]
    rows = ", ".join("[" + ", ".join(str(x) for x in row) + "]" for row in J)
    text = (f"title: steady spin, random inertia ({digits}-digit entries)\n"
            "parameters: {m: mass}\n" + _values(m=1)
            + f"bodies:\n  body: {{mass: m, inertia: [{rows}], at: [0, 0, 0]}}\n"
            "questions:\n  - steady_spin\n")
    return Case("spin", digits, text, "steady_spin")


FAMILIES: dict[str, Callable[[int], Case]] = {
    "chain_points": chain_points,
    "chain_rods": chain_rods,
    "springs": springs,
    "composite": composite,
    "impact": impact,
    "spin": spin,
    "eom_chain": eom_chain,
}
