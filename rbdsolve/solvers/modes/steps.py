"""The worked solution of small oscillations: the equilibrium, M and K, det(K − λM) = 0,
the eigenvalues, and each mode as an oscillation, a growth or neutral, with its
amplitudes; and the numeric route's matrices, eigenpairs and conditioning."""

from __future__ import annotations

import math
from collections.abc import Mapping

import sympy as sp

from rbdsolve.form.arrange import configuration, scaled_matrix, subscript
from rbdsolve.form.display import Relation
from rbdsolve.form.factor import no_longer
from rbdsolve.form.labels import Labels
from rbdsolve.form.printers import point_text, unicode_name
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.report import steps as st
from rbdsolve.solvers.conditions.present_conditions import condition_relation, critical_steps
from rbdsolve.solvers.modes.answers import CERTIFIED_DEGREE, Form, ModesAnswers, Motion, NumericModesAnswers
from rbdsolve.solvers.routes.labels import MODES, labels_for


def _repeated_notes(eigenvalues: tuple[sp.Expr, ...], labels: Labels) -> list[st.Step]:
    """A note per repeated λ: its mode space and the basis shown."""
    notes, seen = [], set()
    lam, a, M = labels.text("eigenvalue"), _letter(labels, "amplitude"), labels.text("mass_matrix")
    letter = _letter(labels, "eigenvalue")
    for value in eigenvalues:
        modes = [i for i, x in enumerate(eigenvalues, 1) if x == value]
        if len(modes) > 1 and value not in seen:
            seen.add(value)
            names = ", ".join(f"{a}{subscript(i)}" for i in modes)
            notes.append(st.note(
                f"{' = '.join(f'{letter}{subscript(i)}' for i in modes)}: a root of "
                f"multiplicity {len(modes)}, so its mode space is {len(modes)}-dimensional; {names} below are an "
                f"{M}-orthogonal basis of it ({a}ᵢᵀ {M} {a}ⱼ = 0), and every combination of them is a mode with "
                f"the same {lam}."))
    return notes


def _certified_note(a: ModesAnswers, labels: Labels) -> list[st.Step]:
    """Which eigenvalues are certified decimals, and what that promises."""
    modes = [i for i, form in enumerate(a.forms, 1) if form is Form.CERTIFIED]
    if not modes:
        return []
    letter = _letter(labels, "eigenvalue")
    which = ("All eigenvalues are" if len(modes) == len(a.forms)
             else f"{', '.join(f'{letter}{subscript(i)}' for i in modes)} are")
    return [st.accuracy(
        f"{which} roots of an irreducible factor of degree ≥ {CERTIFIED_DEGREE} of the characteristic "
        f"polynomial, which no formula gives: each is enclosed by ball arithmetic (Arb) and given as a decimal "
        f"whose {a.certified_digits} significant digits are all proven, and so are their frequencies and "
        f"amplitudes (the text rounds them to fewer digits; the JSON answers hold all {a.certified_digits}).")]


def _letter(labels: Labels, key: str) -> str:
    """The label's letter, which an index follows: λ in λ₁, λ₂."""
    return unicode_name(labels.name(key))


def mode_labels(model: Model) -> Labels:
    return labels_for(model, *MODES)


def _texts(labels: Labels) -> dict[str, str]:
    """The labels as prose writes them: M, K, u, λ, ω, γ, a."""
    keys = {"M": "mass_matrix", "K": "stiffness_matrix", "u": "displacement", "lam": "eigenvalue",
            "w": "frequency", "g": "growth_rate", "a": "amplitude"}
    indexed = labels.needs_index("frequency") or labels.needs_index("growth_rate")  # then λₖ = ωₖ² alike
    return {k: labels.text(v, indexed and k in ("lam", "w", "g")) for k, v in keys.items()}


def _motion_text(i: int, motion: Motion, labels: Labels) -> str:
    t = _texts(labels)
    if motion is Motion.OSCILLATION:
        return f"Mode {i}: {t['lam']} > 0, an oscillation at {t['w']} = √{t['lam']} with amplitudes {t['a']}:"
    if motion is Motion.GROWTH:
        return f"Mode {i}: {t['lam']} < 0, exponential growth at the rate {t['g']} = √(−{t['lam']}): unstable:"
    if motion is Motion.DEPENDS:
        return f"Mode {i}: the sign of {t['lam']} depends on the parameters, case by case:"
    return f"Mode {i}: {t['lam']} = 0, neutral (no restoring force along this mode):"


def exact_steps(a: ModesAnswers, model: Model, char_steps: tuple[Relation, ...], note: str = "") -> tuple:
    """The worked solution; ``note``: why the eigenvalue problem is solved at the values
    (said before it), or nothing."""
    symbols = set(model.symbols.parameters.values())
    labels = mode_labels(model)
    t = _texts(labels)
    steps = [
        st.given(f"Small motions q = q₀ + {t['u']} about the equilibrium",
                 configuration(model.state.functions(), list(a.about.values()))),
        st.equation(
            f"Linearized equations {t['M']} {t['u']}\u0308 + {t['K']} {t['u']} = 0, with {t['M']} = ∂²T/∂q̇∂q̇ "
            f"and {t['K']} = ∂²V/∂q∂q at the equilibrium:",
            Relation(labels.symbol("mass_matrix"), scaled_matrix(a.M, symbols)),
            Relation(labels.symbol("stiffness_matrix"), scaled_matrix(a.K, symbols)),
        ),
    ]
    if note:
        steps.append(st.note(note))
    wt = f"{t['w']}t" if len(t["w"]) == 1 else f"{t['w']} t"  # cos(ωt), cos(ωₖ t)
    steps.append(st.equation(f"{t['u']} = {t['a']} cos({wt}) gives the eigenvalue problem "
                             f"({t['K']} − {t['lam']}{t['M']}) {t['a']} = 0, {t['lam']} = {t['w']}², solvable when",
                             *char_steps))
    certified = Form.CERTIFIED in a.forms
    steps.append(st.result("Eigenvalues, in certified decimals (see Accuracy):" if certified else "Eigenvalues:", *[
        Relation(labels.symbol("eigenvalue", i), lam) for i, lam in enumerate(a.eigenvalues, 1)]))
    steps += _certified_note(a, labels)
    steps += _repeated_notes(a.eigenvalues, labels)
    for i, (lam, w, motion, shape) in enumerate(zip(a.eigenvalues, a.frequencies, a.motions, a.shapes), 1):
        vector = sp.ImmutableMatrix([shape]) if shape else None
        if motion is Motion.OSCILLATION:
            root = sp.Pow(lam, sp.S.Half, evaluate=False)
            rel = [Relation(labels.symbol("frequency", i), root, more=() if no_longer(root, w) else (w,))]
        elif motion is Motion.GROWTH:
            rel = [Relation(labels.symbol("growth_rate", i), tidy(sp.sqrt(-lam)))]
        elif motion is Motion.DEPENDS:
            rel = [r for c in a.cases[i - 1] for r in _case(c, i, lam, a.critical, labels)]
        else:
            rel = []
        if vector is not None:
            rel.append(Relation(labels.symbol("amplitude", i), vector))
        steps.append(st.result(_motion_text(i, motion, labels), *rel))
        if motion is not Motion.DEPENDS and a.cases and a.cases[i - 1]:  # decided by the values
            steps.append(st.note("Where that holds, case by case:", *[
                condition_relation(c.when, a.critical, lead=f"{c.kind.value} when") for c in a.cases[i - 1]]))
    steps += critical_steps(a.critical, "where a mode changes from oscillation to growth")
    return tuple(steps)


def _case(case, i: int, lam: sp.Expr, critical, labels: Labels) -> list[Relation]:
    """oscillation when Ω < Ω_c, ω₁ = √λ; growth when Ω > Ω_c, γ₁ = √(−λ)."""
    condition = condition_relation(case.when, critical, lead=f"{case.kind.value} when")
    if case.kind is Motion.OSCILLATION:
        return [condition, Relation(labels.symbol("frequency", i), tidy(sp.sqrt(lam)))]
    if case.kind is Motion.GROWTH:
        return [condition, Relation(labels.symbol("growth_rate", i), tidy(sp.sqrt(-lam)))]
    return [condition, Relation(labels.symbol("eigenvalue", i), sp.Integer(0))]


EPS = 2.0**-52  # binary64's machine epsilon, in which the numeric route works
MAX_SHOWN = 8  # larger matrices and mode shapes are left to the JSON answers


def numeric_steps(a: NumericModesAnswers, model: Model, how: str, about: Mapping[str, sp.Expr]) -> tuple[st.Step, ...]:
    """``about``: the equilibrium as the listing writes it (π where it recognized π; the
    answers hold its floats)."""
    n = len(a.eigenvalues)
    labels = mode_labels(model)
    t = _texts(labels)
    matrices = ((Relation(labels.symbol("mass_matrix"), _floats(a.M)),
                 Relation(labels.symbol("stiffness_matrix"), _floats(a.K))) if n <= MAX_SHOWN else ())
    steps = [
        st.given(f"Small motions q = q₀ + {t['u']} about the equilibrium",
                 configuration(model.state.functions(), [sp.Float(v, 15) if v.is_Float else v
                                                         for v in map(sp.sympify, about.values())])),
        st.equation(f"Linearized equations {t['M']} {t['u']}\u0308 + {t['K']} {t['u']} = 0 at the equilibrium, "
                    f"in numbers ({how}"
                    + (f"; {t['M']} and {t['K']} are {n}×{n}, in the JSON answers):" if n > MAX_SHOWN else "):"),
                    *matrices),
        st.equation(f"The generalized symmetric eigenproblem {t['K']} {t['a']} = {t['lam']} {t['M']} {t['a']}, "
                    f"by Cholesky factorization of {t['M']} (LAPACK's, through numpy):",
                    *[Relation(labels.symbol("eigenvalue", i), sp.Float(x, 15)) for i, x in enumerate(a.eigenvalues, 1)]),
        _conditioning_note(a, about),
    ]
    for i, (lam, w, motion, shape, err) in enumerate(
            zip(a.eigenvalues, a.frequencies, a.motions, a.shapes, a.absolute_errors), 1):
        rel = []
        if motion is Motion.OSCILLATION:
            rel.append(Relation(labels.symbol("frequency", i), sp.Float(w, 15)))
            text = _motion_text(i, motion, labels)
        elif motion is Motion.GROWTH:
            rel.append(Relation(labels.symbol("growth_rate", i), sp.Float(math.sqrt(-lam), 15)))
            text = _motion_text(i, motion, labels)
        else:
            text = (f"Mode {i}: |{t['lam']}| ≤ {err:.1e}, its error bound: {t['lam']} is not told from 0 within "
                    "rounding, neutral:")
        if n <= MAX_SHOWN:
            rel.append(Relation(labels.symbol("amplitude", i), _floats((shape,))))
        steps.append(st.result(text, *rel))
    return tuple(steps)


def _conditioning_note(a: NumericModesAnswers, about: Mapping[str, sp.Expr]) -> st.Step:
    """κ₂(M), the spread of λ, the largest κ(λ) and the clusters (modes_spaces), named by
    the equilibrium where it has at most three coordinates (a question about each of
    several prints one such note per equilibrium, in one accuracy block)."""
    kappas = [k for k in a.conditions if k is not None]
    text = f"Conditioning{f' about {point_text(about)}' if len(about) <= 3 else ''}: κ₂(M) = {a.condition_M:.2g}"
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
