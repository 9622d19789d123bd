"""The worked solution of small oscillations: the equilibrium, M and K, det(K − λM) = 0,
the eigenvalues, and each mode as an oscillation, a growth or neutral, with its
amplitudes; and the numeric route's matrices, eigenpairs and conditioning."""

from __future__ import annotations

import math

import sympy as sp

from rbdsolve.form.arrange import configuration, scaled_matrix, subscript
from rbdsolve.form.display import Product, Relation, Terms
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.report import steps as st
from rbdsolve.solvers.shared.present_conditions import condition_relation, critical_steps
from rbdsolve.solvers.modes.answers import ModesAnswers, Motion, NumericModesAnswers


def descending(poly: sp.Poly) -> Terms:
    """25/48 μ² − 37/24 μ + 1: highest power first, as an exam solution writes it."""
    x = poly.gens[0]
    return Terms(tuple(Product(c, (x**k,) if k else ()) for (k,), c in poly.terms()))


def _repeated_notes(eigenvalues: tuple[sp.Expr, ...]) -> list[st.Step]:
    """A note per repeated λ: its mode space and the basis shown."""
    notes, seen = [], set()
    for lam in eigenvalues:
        modes = [i for i, x in enumerate(eigenvalues, 1) if x == lam]
        if len(modes) > 1 and lam not in seen:
            seen.add(lam)
            names = ", ".join(f"a{subscript(i)}" for i in modes)
            notes.append(st.note(
                f"{' = '.join(f'λ{subscript(i)}' for i in modes)}: a root of multiplicity {len(modes)}, so its mode "
                f"space is {len(modes)}-dimensional; {names} below are an M-orthogonal basis of it "
                "(aᵢᵀ M aⱼ = 0), and every combination of them is a mode with the same λ."))
    return notes


def exact_steps(a: ModesAnswers, model: Model, char_steps: tuple[Relation, ...]) -> tuple:
    symbols = set(model.symbols.parameters.values())
    steps = [
        st.given("Small motions q = q₀ + u about the equilibrium",
                 configuration(model.state.functions(), list(a.about.values()))),
        st.equation(
            "Linearized equations M u\u0308 + K u = 0, with M = ∂²T/∂q̇∂q̇ and K = ∂²V/∂q∂q "
            "at the equilibrium:",
            Relation(sp.Symbol("M"), scaled_matrix(a.M, symbols)),
            Relation(sp.Symbol("K"), scaled_matrix(a.K, symbols)),
        ),
    ]
    steps.append(st.equation("u = a cos(ωt) gives the eigenvalue problem (K − λM) a = 0, "
                             "λ = ω², solvable when", *char_steps))
    steps.append(st.result("Eigenvalues:", *[
        Relation(sp.Symbol(f"lambda_{i}"), lam) for i, lam in enumerate(a.eigenvalues, 1)]))
    steps += _repeated_notes(a.eigenvalues)
    for i, (lam, w, motion, shape) in enumerate(zip(a.eigenvalues, a.frequencies, a.motions, a.shapes), 1):
        vector = sp.ImmutableMatrix([shape]) if shape else None
        if motion is Motion.OSCILLATION:
            rel = [Relation(sp.Symbol(f"omega_{i}"), sp.Pow(lam, sp.S.Half, evaluate=False), more=(w,))]
            text = f"Mode {i}: λ > 0, an oscillation at ω = √λ with amplitudes a:"
        elif motion is Motion.GROWTH:
            rel = [Relation(sp.Symbol(f"gamma_{i}"), tidy(sp.sqrt(-lam)))]
            text = f"Mode {i}: λ < 0, exponential growth at the rate γ = √(−λ): unstable:"
        elif motion is Motion.DEPENDS:
            rel = [r for c in a.cases[i - 1] for r in _case(c, i, lam, a.critical)]
            text = f"Mode {i}: the sign of λ depends on the parameters, case by case:"
        else:
            rel = []
            text = f"Mode {i}: λ = 0, neutral (no restoring force along this mode):"
        if vector is not None:
            rel.append(Relation(sp.Symbol(f"a_{i}"), vector))
        steps.append(st.result(text, *rel))
        if motion is not Motion.DEPENDS and a.cases and a.cases[i - 1]:  # decided by the values
            steps.append(st.note("Where that holds, case by case:", *[
                condition_relation(c.when, a.critical, lead=f"{c.kind.value} when") for c in a.cases[i - 1]]))
    steps += critical_steps(a.critical, "where a mode changes from oscillation to growth")
    return tuple(steps)


def _case(case, i: int, lam: sp.Expr, critical) -> list[Relation]:
    """oscillation when Ω < Ω_c, ω₁ = √λ; growth when Ω > Ω_c, γ₁ = √(−λ)."""
    condition = condition_relation(case.when, critical, lead=f"{case.kind.value} when")
    if case.kind is Motion.OSCILLATION:
        return [condition, Relation(sp.Symbol(f"omega_{i}"), tidy(sp.sqrt(lam)))]
    if case.kind is Motion.GROWTH:
        return [condition, Relation(sp.Symbol(f"gamma_{i}"), tidy(sp.sqrt(-lam)))]
    return [condition, Relation(sp.Symbol(f"lambda_{i}"), sp.Integer(0))]


EPS = 2.0**-52  # binary64's machine epsilon, in which the numeric route works
MAX_SHOWN = 8  # larger matrices and mode shapes are left to the JSON answers


def numeric_steps(a: NumericModesAnswers, model: Model, how: str) -> tuple[st.Step, ...]:
    n = len(a.eigenvalues)
    matrices = ((Relation(sp.Symbol("M"), _floats(a.M)), Relation(sp.Symbol("K"), _floats(a.K)))
                if n <= MAX_SHOWN else ())
    steps = [
        st.given("Small motions q = q₀ + u about the equilibrium",
                 configuration(model.state.functions(), [sp.Float(v, 15) for v in a.about.values()])),
        st.equation(f"Linearized equations M u\u0308 + K u = 0 at the equilibrium, in numbers ({how}"
                    + (f"; M and K are {n}×{n}, in the JSON answers):" if n > MAX_SHOWN else "):"), *matrices),
        st.equation("The generalized symmetric eigenproblem K a = λ M a, by Cholesky factorization of M "
                    "(scipy.linalg.eigh):",
                    *[Relation(sp.Symbol(f"lambda_{i}"), sp.Float(x, 15)) for i, x in enumerate(a.eigenvalues, 1)]),
        _conditioning_note(a),
    ]
    for i, (lam, w, motion, shape, err) in enumerate(
            zip(a.eigenvalues, a.frequencies, a.motions, a.shapes, a.absolute_errors), 1):
        rel = []
        if motion is Motion.OSCILLATION:
            rel.append(Relation(sp.Symbol(f"omega_{i}"), sp.Float(w, 15)))
            text = f"Mode {i}: λ > 0, an oscillation at ω = √λ with amplitudes a:"
        elif motion is Motion.GROWTH:
            rel.append(Relation(sp.Symbol(f"gamma_{i}"), sp.Float(math.sqrt(-lam), 15)))
            text = f"Mode {i}: λ < 0, exponential growth at the rate γ = √(−λ): unstable:"
        else:
            text = f"Mode {i}: |λ| ≤ {err:.1e}, its error bound: λ is not told from 0 within rounding, neutral:"
        if n <= MAX_SHOWN:
            rel.append(Relation(sp.Symbol(f"a_{i}"), _floats((shape,))))
        steps.append(st.result(text, *rel))
    return tuple(steps)


def _conditioning_note(a: NumericModesAnswers) -> st.Step:
    """κ₂(M), the spread of λ, the largest κ(λ) and the clusters (modes_spaces)."""
    kappas = [k for k in a.conditions if k is not None]
    text = f"Conditioning: κ₂(M) = {a.condition_M:.2g}"
    if a.spread is not None:
        text += f", max |λ|/min |λ| = {a.spread:.2g}"
    if kappas:
        text += (f", largest relative condition number κ(λ) = (‖K‖₂ + |λ| ‖M‖₂) ‖a‖₂²/|λ| with aᵀ M a = 1: "
                 f"{max(kappas):.2g} (relative error about ε κ, ε = {EPS:.1e})")
    for group in a.clusters:
        if len(group) > 1:
            text += (f"; λ{'/λ'.join(map(str, group))} are equal within their bounds: one mode space, "
                     "its shapes below an M-orthogonal basis of it")
    return st.accuracy(text + ".")


def _floats(rows) -> sp.ImmutableMatrix:
    return sp.ImmutableMatrix([[sp.Float(x, 15) for x in row] for row in rows])
