"""What the equilibrium equations ∂V/∂q = 0 are, read from their form in milliseconds,
and so whether the exact route can list every solution before it tries.

* **Polynomial** in the sines and cosines of the angles and in the other coordinates
  (s = sin q, c = cos q, s² + c² = 1), and in up to ROOTS square roots of polynomials in
  them, each an unknown w = √B with w² = B (a spring of natural length from a rod's end
  to a wall, 2√2 a √(1 − cos θ); a spring to an axis a rod misses, √(d² + s²)): a
  Gröbner basis lists every root, and does so
  in seconds while the system is small. Its size is measured by the Bézout number of
  each block of equations that share unknowns, the product of their total degrees
  (Cox, Little, O'Shea, *Ideals, Varieties, and Algorithms*, §8.7: a bound on the
  number of isolated roots, and what the basis's cost grows with, with the number of
  symbolic parameters). Past BEZOUT_LIMIT the exact route does not start the basis.
  Measured (processor seconds): every problem in problems/ has blocks of 2 or less
  (one angle, or angles V does not couple), solved in milliseconds; two pendulum angles
  coupled by a zero-length spring to a point off the axis, 16, with five symbolic
  parameters: past 120 s, and as long with every value given (the basis is symbolic);
  three coupled angles, 64: past 120 s.
* **Algebraic**: radicals of the coordinates past those (more than ROOTS of them, a
  cube root) but no function of them: sympy's ``solve`` answers small ones (at most
  ALGEBRAIC_UNKNOWNS unknowns, ALGEBRAIC_OPS operations).
* **Transcendental**: anything else — q both inside and outside sin and cos (a rolling
  slab's R θ cos θ, a torsion spring's c θ), sin of a fraction of q (a half-disk on a
  drum, sin(r θ/(R + r))), a radical of a sine past ROOTS. No closed form lists every
  root; one equation proved monotone has one root
  (``monotone``), and otherwise the exact route lists the **evident roots**
  (``evident.py``): the combinations of 0, π, ±π/2 (0 for a length) that make every
  equation vanish exactly.

``exact.incomplete(model)`` says why the exact list would be partial, or None: the
route choice (``solvers/routes/routes.py``) then runs the numeric search at once where every
parameter has a value, instead of waiting for the exact route to give up.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import sympy as sp

from rbdsolve.solvers.conditions.polynomial import unreadable_degree, unreadable_reason


BEZOUT_LIMIT = 8  # the largest Bézout number of a block the Gröbner route starts
ALGEBRAIC_UNKNOWNS = 2
ALGEBRAIC_OPS = 80  # operations in all the equations together
TRIG = (sp.sin, sp.cos, sp.tan)


class Shape(Enum):
    NONE = "none"  # no equation holds a coordinate (or there are none)
    POLYNOMIAL = "polynomial"
    ALGEBRAIC = "algebraic"
    TRANSCENDENTAL = "transcendental"


@dataclass(frozen=True)
class PolySystem:
    """∂V/∂q = 0 as polynomials: the numerators in s_q = sin q, c_q = cos q (angles) and
    the other unknowns, with s² + c² − 1 for each angle."""

    polynomials: tuple[sp.Expr, ...]
    sines: dict
    cosines: dict
    plain: tuple[sp.Symbol, ...]
    roots: tuple[sp.Symbol, ...] = ()  # w = √B for each square root of the unknowns, with w² − B among the polynomials
    denominators: tuple[sp.Expr, ...] = ()  # where one vanishes at a root, the equation is not defined there

    @property
    def symbols(self) -> list[sp.Symbol]:
        return [*self.sines.values(), *self.cosines.values(), *self.plain, *self.roots]


@dataclass(frozen=True)
class Structure:
    """The equations' shape, their polynomial form where they have one, and, where the
    exact route cannot list every root, why (None: it can)."""

    shape: Shape
    system: PolySystem | None
    bezout: int
    why_partial: str | None


def trig_polynomial(equations, unknowns, angles) -> PolySystem | None:
    """The polynomial form of the equations, or None where they have none."""
    s = {q: sp.Dummy(f"s_{q.name}", real=True) for q in unknowns if q in angles}
    c = {q: sp.Dummy(f"c_{q.name}", real=True) for q in unknowns if q in angles}
    plain = tuple(q for q in unknowns if q not in angles)
    unknown = (*s.values(), *c.values(), *plain)
    written = []
    for e in equations:
        poly = sp.expand_trig(sp.expand(e))
        poly = poly.xreplace({sp.sin(q): s[q] for q in s} | {sp.cos(q): c[q] for q in c})
        if any(poly.has(q) for q in s):
            return None
        written.append(poly)
    roots = _square_roots(written, unknown)
    if roots is None:
        return None
    system, denominators = [], []
    for poly in written:
        numerator, denominator = sp.fraction(sp.together(_with_roots(poly, roots)))
        if not numerator.is_polynomial(*unknown, *roots.values()):
            return None
        system.append(numerator)
        if denominator.has(*unknown, *roots.values()):
            denominators.append(denominator)
    system += [s[q] ** 2 + c[q] ** 2 - 1 for q in s]
    system += [w**2 - radicand for radicand, w in roots.items()]
    return PolySystem(tuple(system), s, c, plain, tuple(roots.values()), tuple(denominators))


ROOTS = 2  # square roots of the unknowns a polynomial form takes in, each as an unknown w, w² = B


def _square_roots(equations, unknown) -> dict[sp.Expr, sp.Symbol] | None:
    """Each square root √B (or its powers, B^(k/2)) of the unknowns in the equations,
    B a polynomial in them, as an unknown w ≥ 0 with w² = B: a rod hinged on a wall,
    a spring of natural length a from its end to the wall 2a above the hinge, has the
    length 2√2 a √(1 − cos θ), and ∂V/∂θ = 0 is polynomial in sin θ, cos θ and w. The
    sign w ≥ 0 is the root's own: a solution with w < 0 solves the squared form only,
    which the existence conditions find (``cases.unsquared_where``). None where a root
    is of another kind (a cube root, a root of a non-polynomial) or past ROOTS."""
    found = {}
    for e in equations:
        for p in e.atoms(sp.Pow):
            if not p.base.has(*unknown) or p.exp.is_integer:
                continue
            if not (p.exp.is_Rational and p.exp.q == 2) or not p.base.is_polynomial(*unknown):
                return None
            base = sp.expand(p.base)
            found.setdefault(base, sp.Dummy(f"w{len(found)}", nonnegative=True))
    return found if len(found) <= ROOTS else None


def _with_roots(expr: sp.Expr, roots: dict[sp.Expr, sp.Symbol]) -> sp.Expr:
    """B^(k/2) written w^k, w = √B (``_square_roots``)."""
    if not roots:
        return expr
    return expr.replace(lambda p: isinstance(p, sp.Pow) and sp.expand(p.base) in roots and p.exp.is_Rational
                        and p.exp.q == 2, lambda p: roots[sp.expand(p.base)] ** (p.exp * 2))


def bezout(system: PolySystem) -> int:
    """The largest Bézout number over the blocks of polynomials that share unknowns (a
    chain whose angles do not meet in V solves as many small systems)."""
    symbols = system.symbols
    degrees, holds = [], []
    for p in system.polynomials:
        present = frozenset(x for x in symbols if p.has(x))
        holds.append(present)
        degrees.append(sp.Poly(p, *present).total_degree() if present else 0)
    blocks: list[tuple[set, int]] = []
    for present, degree in zip(holds, degrees):
        joined = [b for b in blocks if b[0] & present]
        merged = set(present).union(*(b[0] for b in joined))
        product = max(degree, 1)
        for b in joined:
            product *= b[1]
            blocks.remove(b)
        blocks.append((merged, product))
    return max((b[1] for b in blocks), default=1)


def shape_of(equations, unknowns, angles) -> tuple[Shape, PolySystem | None]:
    if not equations or not unknowns:
        return Shape.NONE, None
    system = trig_polynomial(equations, unknowns, angles)
    if system is not None:
        return Shape.POLYNOMIAL, system
    if any(f.has(*unknowns) for e in equations for f in e.atoms(sp.Function)):
        return Shape.TRANSCENDENTAL, None  # a function of a coordinate: sin(r θ/(R + r)), √(… cos θ …) is not one
    return Shape.ALGEBRAIC, None


def algebraic_small(equations, unknowns) -> bool:
    return len(unknowns) <= ALGEBRAIC_UNKNOWNS and sum(sp.count_ops(e) for e in equations) <= ALGEBRAIC_OPS


def _unreadable(system: PolySystem) -> str | None:
    """Why the exact list would be partial where the eliminant has an irreducible factor
    of degree 3 or more in every order (polynomial.unreadable_degree): only the evident
    roots are listed, with the rest left to the numeric route."""
    degree = unreadable_degree(list(system.polynomials), list(system.symbols)) if system.symbols else None
    return unreadable_reason("the equilibrium equations", degree) if degree else None


def decide(shape: Shape, system: PolySystem | None, equations, unknowns, monotone: bool) -> Structure:
    """The structure, with why the exact route's list would be partial (None: complete);
    ``monotone``: one transcendental equation proved monotone (one root)."""
    if shape is Shape.POLYNOMIAL:
        size = bezout(system)
        why = None if size <= BEZOUT_LIMIT else (
            f"the equilibrium equations are polynomial in {len(system.symbols)} unknowns (sines, cosines and "
            f"coordinates) with a Bézout number of {size}, past the {BEZOUT_LIMIT} for which a Gröbner basis takes "
            "seconds")
        return Structure(shape, system, size, why or _unreadable(system))
    if shape is Shape.ALGEBRAIC:
        why = None if algebraic_small(equations, unknowns) else (
            f"the equilibrium equations hold radicals of {len(unknowns)} coordinates: too large for the exact route")
        return Structure(shape, None, 0, why)
    if shape is Shape.TRANSCENDENTAL and not monotone:
        return Structure(shape, None, 0, "the equilibrium equations are transcendental, not polynomial in sin, cos "
                                         "and the coordinates, and no closed form lists every root")
    return Structure(shape, None, 0, None)
