"""Torque-free precession of an axisymmetric body, seen from the body and from space.

With A the moment about every axis across the symmetry axis e₃ and C the moment about
it, write ω = ω⊥ e⊥ + ω₃ e₃ (ω⊥ across the axis, ω₃ along it). Then L = J_G ω =
A ω⊥ e⊥ + C ω₃ e₃, and Euler's equations (Goldstein §5.6) give

* ω₃ constant, and ω (with L) turning about e₃, relative to the body, at
  Ω_b = (C − A) ω₃ / A (the same sense as the spin when C > A: an oblate body, a coin);
* L fixed in space, and ω = (|L|/A) L̂ + ((A − C)/A) ω₃ e₃: the symmetry axis and ω turn
  about L at the space precession rate φ̇ = |L|/A = √(A² ω⊥² + C² ω₃²)/A;
* constant angles: α between ω and the axis, tan α = ω⊥/ω₃; ν between the axis and L,
  tan ν = A ω⊥ / (C ω₃); γ between ω and L, γ = |α − ν| (α − ν when C > A).

Given ω₃ and either ω⊥ or α (ω⊥ = ω₃ tan α). ω₃ > 0 and ω⊥ ≥ 0 are sizes.
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import UnsolvedError
from rbdsolve.form.display import Label, Relation
from rbdsolve.form.tidy import tidy, tidy_fraction
from rbdsolve.model.build import Model
from rbdsolve.problem.options import PrecessionOptions
from rbdsolve.report import steps as st
from rbdsolve.solvers.conditions.signs import sign_of
from rbdsolve.solvers.steady_spin.answers import FreePrecession


def precession(opts: PrecessionOptions, moments: tuple[sp.Expr, ...], model: Model) -> FreePrecession:
    k, A, C = symmetry_axis(moments, model)
    w3 = model.symbols.scalar(opts.spin)
    if opts.angle is not None:
        alpha = model.symbols.scalar(opts.angle)
        w_t = tidy(w3 * sp.tan(alpha))
    else:
        w_t = model.symbols.scalar(opts.transverse)
        alpha = tidy(sp.atan(w_t / w3))
    L = tidy(sp.sqrt(tidy_fraction(A**2 * w_t**2 + C**2 * w3**2)))
    nu = tidy(sp.atan(tidy_fraction(A * w_t / (C * w3))))
    oblate = sign_of(tidy_fraction(C - A), model.decided_by)
    gamma = tidy(alpha - nu) if oblate == 1 else tidy(nu - alpha) if oblate == -1 else sp.Abs(alpha - nu)
    return FreePrecession(f"e{k + 1}", w3, w_t, tidy(sp.sqrt(tidy_fraction(w_t**2 + w3**2))), L,
                          tidy_fraction((C - A) * w3 / A), tidy(L / A), alpha, nu, gamma)


def symmetry_axis(J: tuple[sp.Expr, ...], model: Model) -> tuple[int, sp.Expr, sp.Expr]:
    """(k, A, C): e_k the symmetry axis, A the two equal moments, C the third."""
    for k in range(3):
        i, j = (n for n in range(3) if n != k)
        if tidy_fraction(J[i] - J[j]) == 0:
            if tidy_fraction(J[k] - J[i]) == 0:
                raise UnsolvedError("'precession': every principal moment is the same, so ω stays along L and "
                                    "nothing precesses")
            return k, J[i], J[k]
    raise UnsolvedError("'precession' needs an axisymmetric body (two equal principal moments); these are "
                        f"{', '.join(to_unicode(x) for x in J)}")


def precession_steps(p: FreePrecession) -> list[st.Step]:
    return [
        st.given(f"The free motion: ω along the symmetry axis {p.axis} and across it,",
                 Relation(sp.Symbol("omega_3"), p.spin), Relation(Label("ω⊥", r"\omega_{\perp}"), p.transverse)),
        st.equation("L = A ω⊥ e⊥ + C ω₃ e₃ is fixed in space (A across the axis, C about it):",
                    Relation(sp.Symbol("|L|"), p.angular_momentum), Relation(Label("|ω|", r"|\omega|"), p.omega)),
        st.result("Seen from the body, ω turns about the symmetry axis at Ω_b = (C − A) ω₃/A; seen from space, "
                  "the axis turns about L at φ̇ = |L|/A:",
                  Relation(sp.Symbol("Omega_b"), p.body_rate), Relation(Label("φ̇", r"\dot{\varphi}"), p.space_rate)),
        st.result("The constant angles: α between ω and the axis (tan α = ω⊥/ω₃), ν between the axis and L "
                  "(tan ν = A ω⊥/(C ω₃)), γ between ω and L:",
                  Relation(sp.Symbol("alpha"), p.alpha), Relation(sp.Symbol("nu"), p.nu),
                  Relation(sp.Symbol("gamma"), p.gamma)),
    ]


def numeric_precession(opts: PrecessionOptions, J, tol: float, model: Model) -> FreePrecession:
    """The same formulas in floats, from the moments in floats (two equal within tol)."""
    import math

    k = next((k for k in range(3) if abs(J[(k + 1) % 3] - J[(k + 2) % 3]) <= tol), None)
    if k is None or abs(J[k] - J[(k + 1) % 3]) <= tol:
        symmetry_axis(tuple(sp.Float(x) for x in J), model)  # the exact route's refusal, in its words
    A, C = float(J[(k + 1) % 3]), float(J[k])

    def number(expr) -> float:
        return float(model.symbols.scalar(expr).xreplace(dict(model.values)))

    w3 = number(opts.spin)
    alpha = number(opts.angle) if opts.angle is not None else math.atan2(number(opts.transverse), w3)
    w_t = w3 * math.tan(alpha) if opts.angle is not None else number(opts.transverse)
    L = math.hypot(A * w_t, C * w3)
    nu = math.atan2(A * w_t, C * w3)
    return FreePrecession(f"e{k + 1}", w3, w_t, math.hypot(w_t, w3), L, (C - A) * w3 / A, L / A, alpha, nu,
                          abs(alpha - nu))
