"""The floating-point route: M(q) and V(q) with its derivatives, without sympy.

The scene's own expression trees (:mod:`rbdsolve.problem.expr`) are evaluated on
:class:`~rbdsolve.model.numeric.jet.Jet` numbers, which carry exact first and second
derivatives with respect to the generalized coordinates (forward-mode automatic
differentiation). Then, as in :mod:`rbdsolve.model.energies.energy`,

    M(q) = Σ_bodies (m J_vᵀ J_v + J_ωᵀ J_G J_ω),   J_v = ∂r_G/∂q,  J_ω = e_z ∂α/∂q
    V(q) = −Σ_bodies m g·r_G + Σ_springs ½ k s²,   s = |r_a − r_b| − L₀  or  α − α₀
    K    = ∂²V/∂q∂q                                                 (e.g. Goldstein, ch. 6)

For a planar angle α (a turn about z) J_ωᵀ (R J_G Rᵀ) J_ω = J_zz ∇α ∇αᵀ, since the
turn leaves e_z fixed. The mass properties of each body come once from the shape
library (:func:`rbdsolve.model.build.body_mass_properties`) with the parameters'
numbers put in.

What this route does not cover raises :class:`NotNumeric` with the reason; the caller
then takes the symbolic route.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Callable, Mapping, Sequence

import mpmath
import numpy as np
import sympy as sp

from rbdsolve.model.build import body_mass_properties, parts_key
from rbdsolve.model.numeric.jet import FLOAT, MP50, Arithmetic, Jet, apply, atan2, full, power
from rbdsolve.model.state import State
from rbdsolve.model.symbols import Symbols, exact_number
from rbdsolve.problem import expr as ex
from rbdsolve.problem.quantities.quantity import Value
from rbdsolve.problem.scene import Spring
from rbdsolve.problem.schema import Body, Problem

__all__ = ["FLOAT", "MP50", "Arithmetic", "NotNumeric", "NumericScene"]


class NotNumeric(Exception):
    """This scene needs the symbolic route (the message says why)."""


@dataclass(frozen=True)
class NumericBody:
    """A body's numbers: mass m, centre of mass c from its origin in body axes, J_zz
    about the centre; its origin ``at`` and planar ``angle`` stay expression trees."""

    name: str
    mass: object
    centre: tuple[object, object, object]
    J_zz: object
    at: ex.Tree
    angle: ex.Tree | None


@dataclass(frozen=True)
class NumericScene:
    """A planar (or 3D-without-orientation) scene with numbers for every parameter."""

    arithmetic: Arithmetic
    coordinates: tuple[str, ...]
    parameters: tuple[tuple[str, object], ...]  # name -> number in ``arithmetic``
    points: tuple[tuple[str, ex.Tree], ...]  # in dependency order
    bodies: tuple[NumericBody, ...]
    springs: tuple[Spring, ...]
    gravity: ex.Tree | None

    @classmethod
    def build(cls, problem: Problem, values: Mapping[str, float | Fraction | mpmath.mpf],
              arithmetic: Arithmetic = FLOAT, state: State | None = None) -> NumericScene:
        """The scene of ``problem`` with ``values`` for its parameters (these override the
        file's ``values:``). Raises NotNumeric for what needs the symbolic route.
        ``state``: the model's coordinates as symbols, if there is a model (else made
        here; a mass property that names one is refused either way)."""
        _check_supported(problem)
        exact = _exact_values(problem, values)
        names = Symbols({k: sp.Rational(v.numerator, v.denominator) for k, v in exact.items()},
                        state or State.of(tuple(c.name for c in problem.coordinates)), {})
        with arithmetic.precision():
            parameters = tuple((k, arithmetic.number(v)) for k, v in exact.items())
            cache: dict = {}
            bodies = tuple(_numeric_body(b, names, arithmetic, cache) for b in problem.bodies)
        return cls(arithmetic, tuple(c.name for c in problem.coordinates), parameters,
                   tuple((p.name, p.position.tree) for p in problem.points), bodies,
                   problem.springs, problem.gravity.tree if problem.gravity else None)

    @property
    def n(self) -> int:
        return len(self.coordinates)

    def mass_matrix(self, q: Sequence) -> np.ndarray:
        """M(q) = Σ_bodies (m J_vᵀ J_v + J_zz ∇α ∇αᵀ), n×n (first-order jets suffice)."""
        with self.arithmetic.precision():
            return self._mass(_Evaluator(self, q, order=1))

    def linearized(self, q: Sequence) -> tuple[np.ndarray, np.ndarray]:
        """M(q) and ∂²V/∂q∂q from one pass of second-order jets: M reads only their
        gradients, which are the first-order jets' to the last bit (the same operations)."""
        with self.arithmetic.precision():
            scene = _Evaluator(self, q, order=2)
            _, hess = full(self._energy(scene), self.n, self.arithmetic)
            return self._mass(scene), hess

    def _mass(self, scene: _Evaluator) -> np.ndarray:
        M = self.arithmetic.zeros((self.n, self.n))
        for body in self.bodies:
            for x in scene.position(body):
                _add_outer(M, body.mass, x)
            if body.angle is not None:
                _add_outer(M, body.J_zz, scene.eval(body.angle))
        return self.arithmetic.array(M)

    def potential(self, q: Sequence) -> tuple[object, np.ndarray, np.ndarray]:
        """V(q), ∂V/∂q (n,) and ∂²V/∂q∂q (n, n), with
        V = −Σ m g·r_G + Σ ½ k s² (s = |r_a − r_b| − L₀, or α − α₀ for a torsional spring)."""
        with self.arithmetic.precision():
            V = self._potential(q, order=2)
            grad, hess = full(V, self.n, self.arithmetic)
            value = V.value if isinstance(V, Jet) else V
            return self.arithmetic.number(value), grad, hess

    def gradient(self, q: Sequence) -> np.ndarray:
        """∂V/∂q (n,) alone: first-order jets, without the Hessian's n² work per term."""
        with self.arithmetic.precision():
            grad, _ = full(self._potential(q, order=1), self.n, self.arithmetic, hessian=False)
            return grad

    def _potential(self, q: Sequence, order: int):
        """V as a jet of the given order (or a number where V is constant)."""
        return self._energy(_Evaluator(self, q, order=order))

    def term_curvatures(self, q: Sequence) -> np.ndarray:
        """Σ |∂²(term)/∂q∂q| over V's terms (each body's weight, each spring), entry by
        entry: the size of what ∂²V/∂q∂q sums, which its rounding is relative to (K ≈ 0
        where the terms cancel, at a degenerate equilibrium)."""
        return self._term_sizes(q, order=2)

    def term_slopes(self, q: Sequence) -> np.ndarray:
        """Σ |∂(term)/∂q| over V's terms, coordinate by coordinate: the size of what
        ∂V/∂q sums, which its rounding is relative to (∂V/∂q ≈ 0 everywhere where the
        terms cancel: a rod whose springs balance its weight at every angle)."""
        return self._term_sizes(q, order=1)

    def _term_sizes(self, q: Sequence, order: int) -> np.ndarray:
        """Σ |the order-th derivative of each term of V| (the gradients' for order 1,
        the Hessians' for order 2), in floats."""
        with self.arithmetic.precision():
            total = 0.0
            for term in self._terms(_Evaluator(self, q, order=order)):
                grad, hess = full(term, self.n, self.arithmetic, hessian=order == 2)
                total = total + np.abs(np.asarray(grad if order == 1 else hess, dtype=float))
            return np.broadcast_to(total, (self.n,) * order).copy()

    def _energy(self, scene: _Evaluator):
        """V on the evaluator's jets (the formula of ``potential``)."""
        V = self.arithmetic.number(0)
        for term in self._terms(scene):
            V = V + term
        return V

    def _terms(self, scene: _Evaluator):
        """V's terms, one by one: −m g·r_G per body, ½ k s² per spring."""
        if self.gravity is not None:
            g = scene.eval(self.gravity)
            for body in self.bodies:
                yield -(body.mass * _dot(g, scene.position(body)))
        for spring in self.springs:
            k = scene.eval(spring.stiffness.tree)
            yield k / 2 * scene.stretch_squared(spring)


# --- what the numeric route covers ----------------------------------------------------


def _check_supported(problem: Problem) -> None:
    """Refuse what this route does not model, with the reason."""
    if problem.triads:
        raise NotNumeric("the scene uses triads (3D frames by turns): use the symbolic route")
    if problem.prescribed:
        raise NotNumeric("the scene has prescribed motion (functions of time): use the symbolic route")
    if problem.frames:
        raise NotNumeric("the scene has moving frames: use the symbolic route")
    if problem.forces or problem.couples:
        raise NotNumeric("the scene has applied loads, whose potential is derived with sympy: use the symbolic route")
    own = {b.name for b in problem.bodies} | {n for b in problem.bodies for n, _ in b.points}
    named = [b.at for b in problem.bodies if b.at is not None]
    named += [e for s in problem.springs for e in (s.ends or ())]
    for expr in named:
        if not own.isdisjoint(expr.names()):
            raise NotNumeric(f"'{expr.text}' names a body's point (placed with the body): use the symbolic route")
    for point in problem.points:
        if point.position is None:
            raise NotNumeric(f"point '{point.name}' is given by its velocity at an instant, not a position")
    for body in problem.bodies:
        if body.at is None:
            raise NotNumeric(f"body '{body.name}' is given by its velocities at an instant, not a position")
        if body.orientation:
            raise NotNumeric(f"body '{body.name}' is turned by a 3D orientation")
    for where, expr in _scene_exprs(problem):
        if _uses_time(expr.tree):
            raise NotNumeric(f"{where} depends on time ('{expr.text}')")


def _scene_exprs(problem: Problem):
    """Every expression the energies depend on, with where it sits."""
    for point in problem.points:
        yield f"point '{point.name}'", point.position
    for body in problem.bodies:
        yield f"body '{body.name}'", body.at
        if body.angle is not None:
            yield f"the angle of body '{body.name}'", body.angle
        for part in body.parts:
            entries = part.inertia.entries if part.inertia else ()
            for e in (part.mass, part.at, part.axis, *(v for _, v in part.dimensions), *entries):
                if e is not None:
                    yield f"body '{body.name}'", e
    for spring in problem.springs:
        for e in (spring.stiffness, *(spring.ends or ()), spring.natural_length, spring.angle, spring.rest):
            if e is not None:
                yield f"spring '{spring.name}'", e
    if problem.gravity is not None:
        yield "gravity", problem.gravity


def _uses_time(tree: ex.Tree) -> bool:
    if isinstance(tree, ex.Name):
        return tree.id == "t"
    if isinstance(tree, ex.Derivative):
        return True
    if isinstance(tree, ex.BinOp):
        return _uses_time(tree.left) or _uses_time(tree.right)
    if isinstance(tree, ex.Neg):
        return _uses_time(tree.operand)
    if isinstance(tree, (ex.Call, ex.Vec)):
        return any(_uses_time(x) for x in (tree.args if isinstance(tree, ex.Call) else tree.items))
    return False


def _exact_values(problem: Problem, values: Mapping) -> dict[str, Fraction]:
    """Every parameter the scene uses, as an exact Fraction (a float or an mpf is a
    binary fraction, kept exactly), from ``values`` or else the file's ``values:``."""
    declared = {p.name for p in problem.parameters} | set(problem.unknowns)
    unknown = sorted(set(values) - declared)
    if unknown:
        raise ValueError(f"values for undeclared parameters: {', '.join(unknown)}")
    table = {k: _fraction(v) for k, v in {**problem.value_map(), **values}.items()}
    used = set().union(*(e.names() for _, e in _scene_exprs(problem))) & declared
    missing = sorted(used - set(table))
    if missing:
        raise NotNumeric(f"no value for the parameter{'s' if len(missing) > 1 else ''} {', '.join(missing)}")
    return {k: table[k] for k in sorted(used)}


def _fraction(x) -> Fraction:
    """An exact fraction for the jet arithmetic: a Value or sympy number that is not
    rational (pi/6) is taken to 60 digits, past the 50 of the high-precision route."""
    if isinstance(x, Value):
        x = exact_number(x)
    if isinstance(x, sp.Rational):
        return Fraction(int(x.p), int(x.q))
    if isinstance(x, sp.Basic):
        with mpmath.workdps(70):
            x = mpmath.mpf(str(sp.N(x, 60)))
    if isinstance(x, mpmath.mpf):
        man, exp = x.man_exp
        return Fraction(man) * Fraction(2) ** exp
    return Fraction(x)


def exact_fraction(x) -> Fraction:
    """``_fraction`` for the solvers: a model value (sympy) as an exact Fraction."""
    return _fraction(x)


def _numeric_body(body: Body, names: Symbols, arithmetic: Arithmetic, cache: dict) -> NumericBody:
    """Mass, centre and J_zz from the shape library's formulas with numbers put in
    (once per distinct body description: a chain of equal links needs one)."""
    key = parts_key(body)
    if key not in cache:
        props = body_mass_properties(body, names)
        cache[key] = tuple(_number(x, arithmetic) for x in (props.mass, *props.centre, props.inertia[2, 2]))
    mass, cx, cy, cz, J_zz = cache[key]
    angle = body.angle.tree if body.angle is not None else None
    return NumericBody(body.name, mass, (cx, cy, cz), J_zz, body.at.tree, angle)


def _number(x: sp.Expr, arithmetic: Arithmetic):
    """An exact sympy number (√3 r/2 with r = 7/10) rounded once into ``arithmetic``."""
    if x.free_symbols:
        raise NotNumeric(f"a mass property depends on {sorted(map(str, x.free_symbols))}")
    digits = (arithmetic.digits or 17) + 10
    value = sp.N(x, digits)
    return float(value) if arithmetic.digits is None else mpmath.mpf(value)


# --- evaluation on jets ---------------------------------------------------------------


_METHODS: dict[type, Callable] = {}  # a tree node's kind -> its _Evaluator method


class _Evaluator:
    """The scene at one configuration: every name bound to a number, a jet (a
    coordinate) or a vector (a point, a tuple of 3)."""

    def __init__(self, scene: NumericScene, q: Sequence, order: int):
        if len(q) != scene.n:
            raise ValueError(f"expected {scene.n} coordinates, found {len(q)}")
        self.arithmetic = a = scene.arithmetic
        self.env: dict[str, object] = dict(scene.parameters)
        for i, (name, value) in enumerate(zip(scene.coordinates, q)):
            self.env[name] = Jet.seed(a.number(value), i, order, a)
        for name, tree in scene.points:
            self.env[name] = self.eval(tree)

    def position(self, body: NumericBody) -> tuple:
        """r_G = r_at + R(α) c, R(α) the turn by α about z."""
        at = self.eval(body.at)
        cx, cy, cz = body.centre
        if body.angle is None or (cx == 0 and cy == 0):
            return (at[0] + cx, at[1] + cy, at[2] + cz)
        alpha = self.eval(body.angle)
        c, s = apply("cos", alpha, self.arithmetic), apply("sin", alpha, self.arithmetic)
        return (at[0] + c * cx - s * cy, at[1] + s * cx + c * cy, at[2] + cz)

    def stretch_squared(self, spring: Spring):
        """s²: (|d| − L₀)² for d = r_a − r_b, or (α − α₀)². With L₀ = 0 it is d·d itself,
        smooth where the ends meet (|d| is not)."""
        if spring.ends is None:
            rest = self.eval(spring.rest.tree) if spring.rest is not None else 0
            return power(self.eval(spring.angle.tree) - rest, 2, self.arithmetic)
        a, b = (self.eval(e.tree) for e in spring.ends)
        d = tuple(x - y for x, y in zip(a, b))
        rest = self.eval(spring.natural_length.tree) if spring.natural_length is not None else 0
        if _value(rest) == 0:
            return _dot(d, d)
        return power(apply("sqrt", _dot(d, d), self.arithmetic) - rest, 2, self.arithmetic)

    def eval(self, tree: ex.Tree):
        """The node by its kind's method (``_BinOp`` for a BinOp), looked up once per kind."""
        method = _METHODS.get(type(tree))
        if method is None:
            method = _METHODS[type(tree)] = getattr(_Evaluator, "_" + type(tree).__name__)
        return method(self, tree)

    def _Num(self, tree: ex.Num):
        return self.arithmetic.number(tree.value)

    def _Const(self, tree: ex.Const):
        return self.arithmetic.pi()

    def _Name(self, tree: ex.Name):
        if tree.id not in self.env:
            raise NotNumeric(f"'{tree.id}' has no numeric value here")
        return self.env[tree.id]

    def _Derivative(self, tree: ex.Derivative):
        raise NotNumeric("rates dot(q) appear in a position")

    def _Neg(self, tree: ex.Neg):
        x = self.eval(tree.operand)
        return tuple(-c for c in x) if isinstance(x, tuple) else -x

    def _Vec(self, tree: ex.Vec):
        items = [self.eval(x) for x in tree.items]
        return tuple(items) + (self.arithmetic.number(0),) * (3 - len(items))

    def _BinOp(self, tree: ex.BinOp):
        if tree.op == "**":
            return self._power(tree)
        a, b = self.eval(tree.left), self.eval(tree.right)
        if tree.op == "+":
            return tuple(x + y for x, y in zip(a, b)) if isinstance(a, tuple) else a + b
        if tree.op == "-":
            return tuple(x - y for x, y in zip(a, b)) if isinstance(a, tuple) else a - b
        if tree.op == "*":
            if isinstance(a, tuple):
                return tuple(x * b for x in a)
            return tuple(a * y for y in b) if isinstance(b, tuple) else a * b
        return tuple(x / b for x in a) if isinstance(a, tuple) else a / b

    def _power(self, tree: ex.BinOp):
        """u^p: an exact integer exponent stays an integer (so (−2)³ is real); a jet
        exponent goes through exp(p log u)."""
        base = self.eval(tree.left)
        exact = ex.constant_value(tree.right)
        if exact is not None and exact.denominator == 1:
            return power(base, int(exact), self.arithmetic)
        p = self.eval(tree.right)
        if isinstance(p, Jet):
            return apply("exp", p * apply("log", base, self.arithmetic), self.arithmetic)
        return power(base, p, self.arithmetic)

    def _Call(self, tree: ex.Call):
        args = [self.eval(x) for x in tree.args]
        if tree.func == "atan2":
            return atan2(args[0], args[1], self.arithmetic)
        if tree.func == "inner":
            return _dot(args[0], args[1])
        if tree.func == "norm":
            return apply("sqrt", _dot(args[0], args[0]), self.arithmetic)
        if tree.func == "cross":
            (a1, a2, a3), (b1, b2, b3) = args
            return (a2 * b3 - a3 * b2, a3 * b1 - a1 * b3, a1 * b2 - a2 * b1)
        return apply(tree.func, args[0], self.arithmetic)


def _value(x):
    return x.value if isinstance(x, Jet) else x


def _dot(a: tuple, b: tuple):
    """a·b, skipping exact zero components (the z of a planar scene costs nothing)."""
    terms = [x * y for x, y in zip(a, b) if not (_is_zero(x) or _is_zero(y))]
    return sum(terms[1:], terms[0]) if terms else 0


def _is_zero(x) -> bool:
    return not isinstance(x, Jet) and x == 0


def _add_outer(M: np.ndarray, weight, x) -> None:
    """M += weight ∇x ∇xᵀ on the coordinates x depends on (nothing for a constant)."""
    if isinstance(x, Jet):
        M[np.ix_(x.index, x.index)] += weight * np.outer(x.grad, x.grad)
