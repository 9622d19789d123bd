"""Small oscillations with gyroscopic terms, in floating point.

M ü + G u̇ + K u = 0 at the parameter values, M, G and K from the exact linearization
(solvers/modes/routh.py) rounded once. With u = X e^(st) the quadratic eigenproblem
(s² M + s G + K) X = 0 is solved as the generalized eigenproblem of its first-order
form (Tisseur & Meerbergen, The quadratic eigenvalue problem, SIAM Review 2001, §3.4),

    [[0, 1], [−K, −G]] z = s [[1, 0], [0, M]] z,   z = (X, s X),

as the standard eigenproblem of B⁻¹ A, B = [[1, 0], [0, M]] (numpy's eigvals,
numeric/dense.py: QZ on the pencil needs scipy, whose import alone is 0.14 s of a
process; B is as well conditioned as M). s = iω: a real ω is an oscillation, Re s > 0
a growth. The same eigenvalues at 50 digits (mpmath, from M⁻¹) measure the error: the
absolute error bound of each s is its distance to the nearest 50-digit eigenvalue,
times 10 (M, G and K are exact values rounded once, so the 50-digit ones see what
rounding does to them). A root within its bound of the imaginary axis is taken as on
it: the motion is stable to first order when every root is (the roots of a
gyroscopic system come as ±s, ±s̄, so none can be left of the axis alone).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.equilibria.answers import Stability
from rbdsolve.solvers.modes.answers import NumericGyroscopicModesAnswers
from rbdsolve.solvers.modes.gyroscopic import refuse_options
from rbdsolve.solvers.modes.gyroscopic_steps import numeric_gyroscopic_steps
from rbdsolve.solvers.modes.routh import lagrangian, linearize, slow_steady_state
from rbdsolve.solvers.numeric.numeric_model import as_floats, to_floats

DIGITS = 50
SAFETY = 10.0  # the bound is this many times the distance to the 50-digit eigenvalue


def solve(question: Question, model: Model) -> Solution:
    """The floating-point route's answer about the steady state the question names."""
    refuse_options(question)
    linear, notes = _linearized(question, model)
    M, G, K = (to_floats(x, model.values) for x in (linear.M, linear.G, linear.K))
    s, bounds = quadratic_eigenvalues(M, G, K, [x.xreplace(dict(model.values)) for x in (linear.M, linear.G, linear.K)])
    growth = max(float(np.max(s.real - bounds)), 0.0)
    stability = Stability.UNSTABLE if growth > 0 else Stability.STABLE
    on_axis = np.abs(s.real) <= bounds
    frequencies = sorted({round(abs(float(x.imag)), 12): abs(float(x.imag)) for x in s[on_axis] if x.imag > 0}.values())
    neutral = int(np.sum(on_axis & (np.abs(s) <= bounds)) // 2)
    numbers = as_floats(model, linear.about)
    answers = NumericGyroscopicModesAnswers(
        numbers, as_floats(model, linear.steady),
        _rows(M), _rows(G), _rows(K), tuple(frequencies), stability,
        tuple(sorted({round(float(x), 12): float(x) for x in s.real[s.real - bounds > 0]}.values())),
        tuple((float(x.real), float(x.imag)) for x in s), tuple(float(b) for b in bounds), neutral)
    estimate = max((float(b / abs(x)) for x, b in zip(s, bounds) if abs(x) > b), default=None)
    return Solution("modes", Route.NUMERIC, answers, numeric_gyroscopic_steps(answers, linear, model),
                    warnings=notes, error_estimate=estimate)


def _linearized(question: Question, model: Model):
    """M, G and K about the steady state: the one 'about' gives, as the exact route takes
    it; where it gives none, or a configuration that is steady only to its rounding
    (decimals typed from a listing), the numeric equilibria's, refined there — a
    floating-point root, steady to its rounding (``linearize``'s ``rounded``); with a
    spin's rate given too, that configuration refined on the steady motion's own
    equations (``_refined_steady``)."""
    options = question.options
    values = model.values if slow_steady_state(question, model) else None
    if options.about is not None:
        given = dict(options.about)
        at = {q: model.symbols.scalar(given[n]) for q, n in zip(model.q, model.coordinate_names()) if n in given}
        try:
            return linearize(question, model, at, values), ()
        except UnsolvedError:
            if options.steady:  # a steady spin's rate: no equilibrium search of V finds it
                refined = _refined_steady(question, model, at)
                if refined is None:
                    raise
                return linearize(question, model, refined[0], values, rounded=True), (refined[1],)
    from rbdsolve.solvers.numeric.chosen import equilibrium_for_modes

    found, notes = equilibrium_for_modes(question, model)
    at = {q: found[n] for q, n in zip(model.q, model.coordinate_names())}
    return linearize(question, model, at, values, rounded=True), notes


def _refined_steady(question: Question, model: Model, at: dict) -> tuple[dict, str] | None:
    """A steady state given in decimals (a tilt typed from the equilibria's listing, the
    spin at its rate): refined by Newton's method on the steady motion's equations for
    the coordinates kept, ∂L/∂q_k = 0 with those at rest and each cyclic coordinate
    turning at its rate (Routh's identity: the same as ∂R₀/∂q_k at that motion's
    momenta, the steadiness ``routh.linearize`` checks), at the parameter values.
    ``at``: the kept coordinates' values given. None where Newton's method does not
    end within REFINE_TOL of them."""
    from rbdsolve.model.derivative import derivative
    from rbdsolve.model.numeric.compiled import numpy_function
    from rbdsolve.solvers.numeric.chosen import REFINE_TOL
    from rbdsolve.solvers.numeric.newton import newton

    names = model.coordinate_names()
    values = dict(model.values)
    rates = {model.qd[names.index(n)]: model.symbols.scalar(e).xreplace(values) for n, e in question.options.steady}
    kept = [q for q in model.q if q in at]
    motion = {**{qd: sp.Integer(0) for qd in model.qd if qd not in rates}, **rates}
    L = lagrangian(model).xreplace(motion).xreplace(values)
    x = sp.symbols(f"x0:{len(kept)}", real=True)
    slope = [derivative(L, q).xreplace(dict(zip(kept, x))) for q in kept]
    jacobian = [[sp.diff(f, xj) for xj in x] for f in slope]
    g, H = numpy_function([x], slope), numpy_function([x], jacobian)
    given = np.array([float(sp.N(at[q].xreplace(values), 20)) for q in kept])
    refined = newton(given, lambda v: np.asarray(g(v), dtype=float), lambda v: np.asarray(H(v), dtype=float))
    if refined is None or np.max(np.abs(refined - given)) > REFINE_TOL:
        return None
    shown = ", ".join(f"{n} = {float(v):.9g}" for n, v in zip((names[model.q.index(q)] for q in kept), refined))
    note = (f"about: the point given is {float(np.max(np.abs(refined - given))):.2g} from a steady state; refined "
            f"by Newton's method on the steady motion's ∂L/∂q = 0 to {shown}")
    return {q: sp.Float(float(v), 17) for q, v in zip(kept, refined)}, note


def quadratic_eigenvalues(M: np.ndarray, G: np.ndarray, K: np.ndarray, exact) -> tuple[np.ndarray, np.ndarray]:
    """s of (s² M + s G + K) X = 0 (the first-order form's eigenvalues) and each one's absolute
    error bound against the same at 50 digits (the module docstring)."""
    from rbdsolve.solvers.numeric.dense import LinAlgError, pencil_eigenvalues

    n = len(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-K, -G]])
    B = np.block([[np.eye(n), np.zeros((n, n))], [np.zeros((n, n)), M]])
    singular = "the mass matrix is singular at this configuration: a coordinate carries no inertia"
    try:
        s = pencil_eigenvalues(A, B)
    except LinAlgError:
        raise UnsolvedError(singular) from None
    if not np.all(np.isfinite(s)):
        raise UnsolvedError(singular)
    reference = _reference(*exact)
    bounds = np.array([SAFETY * min(abs(complex(x) - r) for r in reference) for x in s])
    scale = max(float(np.max(np.abs(s))), 1.0)
    return s, np.maximum(bounds, 4 * n * np.finfo(float).eps * scale)


def _reference(M: sp.Matrix, G: sp.Matrix, K: sp.Matrix) -> list[complex]:
    """The eigenvalues of [[0, 1], [−M⁻¹K, −M⁻¹G]] at 50 digits (mpmath)."""
    import mpmath

    with mpmath.workdps(DIGITS + 10):
        Mm, Gm, Km = (mpmath.matrix([[mpmath.mpf(sp.N(x, DIGITS + 10)) for x in row] for row in X.tolist()])
                      for X in (M, G, K))
        n = Mm.rows
        inverse = mpmath.inverse(Mm)
        A = mpmath.zeros(2 * n, 2 * n)
        top, bottom = -inverse * Km, -inverse * Gm
        for i in range(n):
            A[i, n + i] = 1
            for j in range(n):
                A[n + i, j], A[n + i, n + j] = top[i, j], bottom[i, j]
        values = mpmath.eig(A, left=False, right=False)
        return [complex(v) for v in values]


def _rows(A: np.ndarray) -> tuple[tuple[float, ...], ...]:
    return tuple(tuple(float(x) for x in row) for row in A)
