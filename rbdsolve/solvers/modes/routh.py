"""The steady state a spinning scene's small motions are taken about, and its linear
equations M ü + G u̇ + K u = 0.

Without steady rates, R = L = T + L_frame − V itself (L_frame: a turning frame's Coriolis
terms, ``Model.gyroscopic``). With the steady rate of a cyclic coordinate given
(``about: {a: 0, b: 0, dot(phi): s}``): φ is cyclic when L holds φ̇ but not φ, so its
momentum p_φ = ∂L/∂φ̇ is constant, its value that of the steady motion; Routh's
function

    R(q, q̇) = L − Σ p_c ċ,   each ċ solved from ∂L/∂ċ = p_c,

is a Lagrangian for the other coordinates (Goldstein, ch. 8.3; Landau & Lifshitz,
Mechanics, §41), and a steady motion with those momenta is an equilibrium of −R₀, R's
part without rates. With R = R₂ + R₁ + R₀ by degree in q̇ and R₁ = Σ cᵢ q̇ᵢ, the small
motions about q₀ follow (Meirovitch, Methods of Analytical Dynamics, ch. 6.6)

    M ü + G u̇ + K u = 0,   M = ∂²R₂/∂q̇∂q̇,   Gᵢⱼ = ∂cᵢ/∂qⱼ − ∂cⱼ/∂qᵢ,   K = −∂²R₀/∂q∂q,

all at q₀. A declared spin is used or refused, never dropped: a rate for a coordinate L
holds is refused by name.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.display import Relation
from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.form.tidy import by_monomials, has_root, tidy
from rbdsolve.model.build import Model
from rbdsolve.model.derivative import derivative
from rbdsolve.model.energies.energy import kinetic_energy, potential_energy
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.solvers.configuration.singular import exact_reason
from rbdsolve.form.zero import simplifies_to_zero


@dataclass(frozen=True)
class Linear:
    """The linear equations M ü + G u̇ + K u = 0 about a steady state: the coordinates
    kept (all but the cyclic ones given by a rate), their values, the cyclic ones' rates
    and constant momenta, and the steps that reduce L to R."""

    names: tuple[str, ...]
    functions: tuple[sp.Expr, ...]  # θ(t) … of the coordinates kept, for printing
    about: Mapping[str, sp.Expr]
    steady: Mapping[str, sp.Expr]  # cyclic coordinate -> its steady rate
    momenta: Mapping[str, sp.Expr]  # cyclic coordinate -> p = ∂L/∂q̇ in the steady motion
    M: sp.ImmutableMatrix
    G: sp.ImmutableMatrix
    K: sp.ImmutableMatrix
    steps: tuple[st.Step, ...] = ()


def lagrangian(model: Model) -> sp.Expr:
    """L = T + L_frame − V, in the model's plain symbols."""
    T = kinetic_energy(model).total + sum((x.value for x in model.gyroscopic), sp.Integer(0))
    return T - potential_energy(model).total


def linearize(question: Question, model: Model, at: Mapping[sp.Symbol, sp.Expr],
              values: Mapping[sp.Symbol, sp.Expr] | None = None, rounded: bool = False) -> Linear:
    """M, G and K about the configuration ``at`` of the coordinates kept, the cyclic
    coordinates at the steady rates the question gives (Routh's reduction); with
    ``values``, the parameters' values put in first (the floating-point route, where the
    steady state holds a root of the parameters or is long: ``slow_steady_state``). ``rounded``:
    ``at`` is a floating-point root found at the values (the numeric equilibria's), steady
    where ∂R₀/∂q is zero to its rounding there (``STEADY_TO``), not exactly."""
    names = model.coordinate_names()
    _refuse_unknowns(model)
    put = dict(values or {})
    rates = {names.index(n): model.symbols.scalar(e).xreplace(put) for n, e in question.options.steady}
    at = {q: v.xreplace(put) for q, v in at.items()}
    L = lagrangian(model).xreplace(put)
    for k in rates:
        if L.has(model.q[k]):
            raise UnsolvedError(f"a steady rate dot({names[k]}) is for a cyclic coordinate (one L does not "
                                f"hold, as a top's spin angle); L holds {names[k]}: give its value instead, "
                                f"{names[k]}: VALUE")
    kept = [k for k in range(len(names)) if k not in rates]
    R, momenta, steps = _routhian(L, model, rates, kept, at)
    q, qd = [model.q[k] for k in kept], [model.qd[k] for k in kept]
    rest = {x: 0 for x in qd}
    R0 = R.xreplace(rest)
    _require_steady(R0, q, at, model, [names[k] for k in kept], bool(rates), rounded)
    M = sp.Matrix(len(q), len(q), lambda i, j: derivative(derivative(R, qd[i]), qd[j])).xreplace(rest)
    M = sp.ImmutableMatrix(M.xreplace(at).applyfunc(tidy))
    if singular := exact_reason(M, [names[k] for k in kept], "at this configuration"):
        raise UnsolvedError(singular + _euler_hint(rates, names))
    c = [derivative(R, x).xreplace(rest) for x in qd]
    G = sp.Matrix(len(q), len(q), lambda i, j: derivative(c[i], q[j]) - derivative(c[j], q[i]))
    K = sp.Matrix(len(q), len(q), lambda i, j: -derivative(derivative(R0, q[i]), q[j]))
    functions = tuple(model.state.functions()[k] for k in kept)
    G, K = (sp.ImmutableMatrix(x.xreplace(at).applyfunc(tidy)) for x in (G, K))
    return Linear(tuple(names[k] for k in kept), functions, {names[k]: at[model.q[k]] for k in kept},
                  {names[k]: r for k, r in rates.items()}, momenta, M, G, K, steps)


RADICAL_STEADY = "the steady state given holds a root of the parameters, so its exact frequencies are nested radicals"
LONG_STEADY = ("the steady state given is a long expression of the parameters, so its exact frequencies are long "
               "closed forms that take minutes")
LONG_STEADY_OPS = 12  # more operations than a rate or an angle an exam gives as such (s, Ω cos α, π/3)


def slow_steady_state(question: Question, model: Model) -> str | None:
    """Why the exact route about the steady state given would take minutes, or None:
    it holds a root of the parameters (a precession rate pasted from steady_motion's
    quadratic, (r² s − √(r⁴ s² − …))/(…)), or it is a long expression of them (a spin
    that makes a given precession steady, (3 g h/4 + (3a²/20 + 3h²/5) Ω² cos α)/(3a²Ω/10)
    − Ω cos α: past 200 s for a cone top). The check that it is steady and det(K −
    ω²M + iωG)'s roots then swell in the parameters, where with the values put in first
    they are roots of numbers (the numeric route: a second)."""
    given = [model.symbols.scalar(e) for _, e in (*(question.options.about or ()), *question.options.steady)]
    if any(has_root(x) for x in given):
        return RADICAL_STEADY
    if any(sp.count_ops(x) > LONG_STEADY_OPS and x.free_symbols for x in given):
        return LONG_STEADY
    return None


def _refuse_unknowns(model: Model) -> None:
    """A spin rate among the 'unknowns' (a constant a steady_motion question finds) is not
    given: small oscillations about a steady spin need it as a parameter."""
    unknowns = [model.symbols.parameters[n] for n in model.problem.unknowns]
    held = [str(u) for u in unknowns if any(u in b.rotation.free_symbols for b in model.bodies)]
    if held:
        raise UnsolvedError(f"'{held[0]}' is an unknown (a constant that 'steady_motion' finds), and the small "
                            f"oscillations about a steady spin need it given: declare '{held[0]}' under "
                            "'parameters' (with a value, or kept symbolic)")


def _routhian(L: sp.Expr, model: Model, rates: dict, kept: list[int], at) -> tuple[sp.Expr, dict, tuple]:
    """R = L − Σ p_c ċ with each ċ from ∂L/∂ċ = p_c (linear: T is quadratic in the
    rates), p_c its value in the steady motion; (L, {}, ()) without steady rates."""
    if not rates:
        return L, {}, ()
    names = model.coordinate_names()
    cyclic = list(rates)
    cd = [model.qd[k] for k in cyclic]
    p = [sp.Symbol(f"p_{names[k]}") for k in cyclic]
    dL = [derivative(L, x) for x in cd]
    steady = {**{model.qd[k]: 0 for k in kept}, **{model.qd[k]: r for k, r in rates.items()}, **at}
    values = [tidy(d.xreplace(steady)) for d in dL]
    A = sp.Matrix(len(cd), len(cd), lambda i, j: derivative(dL[i], cd[j]))
    if A.det() == 0:
        raise UnsolvedError(f"the momentum of {', '.join(names[k] for k in cyclic)} does not fix its rate "
                            "(∂²L/∂q̇² singular there): Routh's reduction needs it")
    b = sp.Matrix(dL).xreplace({x: 0 for x in cd})
    solved = (A.inv() * (sp.Matrix(p) - b)).applyfunc(tidy)
    routhian = (L - sum(pi * x for pi, x in zip(p, cd))).xreplace(dict(zip(cd, solved)))
    R = sp.expand(routhian.xreplace(dict(zip(p, values))))
    momenta = {names[k]: v for k, v in zip(cyclic, values)}
    shown = [Relation(pi, model.to_time(d), more=(v,)) for pi, d, v in zip(p, map(tidy, dL), values)]
    rate_rows = [Relation(model.state.functions()[k].diff(sp.Symbol("t", real=True)), model.to_time(x))
                 for k, x in zip(cyclic, solved)]
    one = len(cyclic) == 1
    which = ", ".join(unicode_name(names[k]) for k in cyclic)
    written = by_monomials(routhian, [model.qd[k] for k in kept])
    rows = [Relation(sp.Symbol("R"), model.to_time(written))] if sp.count_ops(written) <= MAX_SHOWN_OPS else []
    steps = (
        st.equation(f"{which} {'is' if one else 'are'} cyclic (L holds {'its rate' if one else 'their rates'}, "
                    f"not {'itself' if one else 'them'}): {'its momentum' if one else 'each momentum'} p = ∂L/∂q̇ "
                    "is constant, its value that of the steady motion:", *shown),
        st.equation("Routh's function R = L − Σ p q̇ over the cyclic coordinates, a Lagrangian for the others, "
                    "with", *rate_rows, *rows),
    )
    return R, momenta, steps


MAX_SHOWN_OPS = 80  # a longer Routhian is left out of the steps (its M, G and K follow)


STEADY_TO = 1e-9  # a floating-point root's ∂R₀/∂q, relative to its terms, that counts as zero


def _require_steady(R0: sp.Expr, q: list, at, model: Model, names: list[str], routh: bool,
                    rounded: bool = False) -> None:
    """q₀ is a steady state: ∂R₀/∂q = 0 there (R₀ = T₀ − V, or Routh's R₀); for a
    floating-point root (``rounded``), zero to within STEADY_TO of its terms at the values."""
    what = "−R₀ (Routh's function without rates)" if routh else "V − T₀"
    for name, qi in zip(names, q):
        if rounded and _relative_residual(derivative(R0, qi), at, model) <= STEADY_TO:
            continue
        residual = tidy(derivative(R0, qi).xreplace(at))
        if residual.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise UnsolvedError(f"∂({what})/∂{unicode_name(name)} has no value at this configuration: the "
                                "coordinates are singular there" + (_euler_hint({0: None}, names) if routh else ""))
        if residual != 0 and not simplifies_to_zero(residual):
            shown = to_unicode(model.readable(-residual)) if sp.count_ops(residual) <= 30 else "not zero"
            spun = [n for n in model.coordinate_names() if n not in names]  # the cyclic ones, at their rates
            said, remedy = _rounded_hint(derivative(R0, qi), at, model, spun[0] if len(spun) == 1 else "NAME")
            raise UnsolvedError(f"not a steady state: ∂({what})/∂{unicode_name(name)} = {shown} there{said}", remedy)


def _relative_residual(slope: sp.Expr, at, model: Model) -> float:
    """|∂R₀/∂q| at ``at`` and the values over the sum of its terms' sizes there (inf
    where it has no value, or without values)."""
    found = _residual_and_size(slope, at, model)
    if found is None:
        return float("inf")
    residual, size = found
    return abs(residual) / size if size else (0.0 if residual == 0 else float("inf"))


def _residual_and_size(slope: sp.Expr, at, model: Model) -> tuple[float, float] | None:
    if not model.values:
        return None
    values = dict(model.values)
    try:
        residual = float(sp.N(slope.xreplace(at).xreplace(values), 20))
        size = sum(abs(float(sp.N(t.xreplace(at).xreplace(values), 20))) for t in sp.Add.make_args(sp.expand(slope)))
    except (TypeError, ValueError):
        return None
    return residual, size


ROUNDED_REMEDY = ("a rate or an angle rounded? Give it exactly, as the root a steady_motion question prints "
                  "(dot({spun}): EXPRESSION under about:): a decimal, however many digits, is never exactly steady")


def _rounded_hint(slope: sp.Expr, at, model: Model, spun: str) -> tuple[str, str]:
    """At the parameter values, the residual's size against its terms', and the remedy
    where it is a rounding's (a steady rate pasted with six digits leaves ~1e-6): the
    exact route's only, the numeric route refines such a point (gyroscopic_numeric).
    ``spun``: the coordinate whose rate the remedy names (the scene's own, not ψ)."""
    found = _residual_and_size(slope, at, model)
    if found is None:
        return "", ""
    residual, size = found
    relative = abs(residual) / size if size else float("inf")
    text = f": {-residual:.3g} at the parameter values"
    if relative > 1e-4:
        return text, ""
    return f"{text}, {relative:.1g} of its terms", ROUNDED_REMEDY.format(spun=spun)


def _euler_hint(rates: dict, names: list[str]) -> str:
    """Where a spin's steady rate meets a singular M: Euler angles at θ = 0 (ψ and φ about
    one axis), with the form that works named."""
    if not rates:
        return ""
    return ("; with a steady spin this is most often Euler angles z-x-z at θ = 0, where ψ and φ turn about one "
            "axis: for the sleeping top write the tilt as turns about two horizontal axes, "
            "orientation [[x, a], [y, b], [z, phi]] with coordinates [a, b, phi] (docs/format.md, spinning bodies)")
