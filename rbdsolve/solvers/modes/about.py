"""Which equilibrium the exact modes route takes small oscillations about.

``about: {θ: …}``: the point itself where ∂V/∂q vanishes there exactly; otherwise, with
values for the parameters, the listed exact equilibrium (``equilibria.exact.listing``)
within REFINE_TOL of it in every coordinate (angles modulo 2π), so that a root copied
with 6 digits is taken as the root itself, and a note says so. Farther away, refused,
with the residual as a number. ``about: {equilibrium: N}``: the N-th listed
equilibrium. Neither: the first stable one, as ``equilibria`` classifies it (by the
values, else wherever it exists: ``with_cases``); when several are stable, a note names
the others (the numeric route does the same, ``solvers/numeric/chosen.py``); where none
is, and some are stable for some values only, the refusal names them and what decides.
"""

from __future__ import annotations

import math

import sympy as sp

from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.errors import UnsolvedError
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.solvers.conditions.parameter_order import asked
from rbdsolve.solvers.equilibria.answers import Equilibrium, Stability
from rbdsolve.solvers.equilibria.cases import with_cases
from rbdsolve.solvers.equilibria.exact import Listed, classify_listed, gradient, incomplete, listing
from rbdsolve.solvers.configuration import contact_span
from rbdsolve.solvers.numeric.chosen import NO_EQUILIBRIUM, REFINE_TOL, several_stable
from rbdsolve.solvers.routes.needed import missing_for
from rbdsolve.form.zero import simplifies_to_zero


def exact_equilibrium(question: Question, model: Model) -> tuple[dict, tuple[str, ...]]:
    """{q: value} to linearize about, and notes on how it was chosen."""
    options = question.options
    if options.about is not None:
        return _given(question, model)
    listed = listing(model).equilibria
    if options.equilibrium is not None:
        if options.equilibrium > len(listed):
            raise UnsolvedError(f"{options.loc}: there is no equilibrium {options.equilibrium}: 'equilibria' "
                                f"lists {len(listed)} here")
        return listed[options.equilibrium - 1].at, ()
    first = asked(model, question)
    verdicts = [_stability(model, x, first) for x in listed]
    stable = [k for k, found in enumerate(verdicts, 1) if found.stability is Stability.STABLE]
    if not stable:
        raise UnsolvedError(_none_stable(verdicts, model))
    notes = ()
    if len(stable) > 1:
        others = [(k, _shown(model, listed[k - 1].at)) for k in stable[1:]]
        notes = (several_stable(stable[0], others),)
    return listed[stable[0] - 1].at, notes


def _stability(model: Model, listed: Listed, first: sp.Symbol | None) -> Equilibrium:
    """The listed equilibrium classified as the equilibria question does: by the values,
    or where they leave it undecided, over the parameters' range where it exists
    (``with_cases``: a rod on a spring of natural length, stable at ±acos(c) wherever
    that exists), so that 'modes' takes the one 'equilibria' calls stable."""
    found = classify_listed(model, listed)
    if found.stability in (Stability.STABLE, Stability.UNSTABLE):
        return found
    return with_cases(found, model, listed.at, first)[0]


def _none_stable(verdicts: list[Equilibrium], model: Model) -> str:
    """Why no equilibrium was taken: none is stable, or some only for some values of the
    parameters (those equilibria and the parameters without a value named, to be chosen
    or given)."""
    depends = [(k, found) for k, found in enumerate(verdicts, 1) if found.stability is Stability.DEPENDS]
    choose = "choose one with 'modes: {about: {...}}'"
    if not verdicts:
        return NO_EQUILIBRIUM
    if not depends:
        return f"no stable equilibrium found; {choose}"
    which = ", ".join(str(k) for k, _ in depends)
    given = dict(model.values)
    names = sorted({to_unicode(s) for _, found in depends for case in found.stability_cases
                    for s in case.when.free_symbols if s not in given})
    on = ", ".join(names) or "the parameters"
    noun = "equilibrium" if len(depends) == 1 else "equilibria"
    value = "a value" if len(names) == 1 else "values"
    return (f"no equilibrium is stable for every value of the parameters: the stability of {noun} {which} "
            f"depends on {on} ('equilibria' gives where); give {value} for {on}, or {choose} (such as "
            f"{{equilibrium: {depends[0][0]}}})")


def _given(question: Question, model: Model) -> tuple[dict, tuple[str, ...]]:
    about = question.options.about
    contact_span.require_on_edges(question, model)
    at = {q: model.symbols.scalar(e) for q, (_, e) in zip(model.q, about)}
    residual = [tidy(g.xreplace(at)) for g in gradient(model)]
    if all(simplifies_to_zero(r) for r in residual):
        return at, ()
    if model.values and all(simplifies_to_zero(r.xreplace(dict(model.values))) for r in residual):
        name, _, shown = _off(about, residual, model)
        return at, (f"about: an equilibrium at the values given, not for every value of the parameters: "
                    f"∂V/∂{unicode_name(name)} = {shown} there, 0 with the values given",)
    missing = missing_for(model, question)
    if missing:
        name, expr, shown = _off(about, residual, model)
        give = ("values for the parameters" if not model.values else
                f"{'a value' if len(missing) == 1 else 'values'} for {', '.join(missing)}")
        raise UnsolvedError(f"{expr.loc}: not an equilibrium: ∂V/∂{unicode_name(name)} = {shown} there (give {give} "
                            "to have a nearby equilibrium found)")
    try:
        listing(model)
    except UnsolvedError as exc:
        (name, expr), r = max(zip(about, residual), key=lambda x: abs(_number(x[1], model)))
        raise UnsolvedError(f"{expr.loc}: not exactly an equilibrium (∂V/∂{unicode_name(name)} = {_number(r, model):.6g} there), "
                            f"and the exact route cannot list the equilibria to find the one near it ({exc.reason})",
                            "with a value for every parameter, the numeric route refines it to the equilibrium near "
                            "it") from None
    near = _nearest_listed(model, at)
    if near is None and incomplete(model) is not None:  # only the evident roots are listed
        (name, expr), r = max(zip(about, residual), key=lambda x: abs(_number(x[1], model)))
        raise UnsolvedError(f"{expr.loc}: not exactly an equilibrium (∂V/∂{unicode_name(name)} = {_number(r, model):.6g} "
                            f"there), and the exact route cannot list the equilibria to find the one near it "
                            f"({incomplete(model)})")
    if near is not None:
        note = (f"about: the point given is {near[1]:.2g} from equilibrium {near[0]} as 'equilibria' lists it; "
                f"taken there, {_shown(model, listing(model).equilibria[near[0] - 1].at)}")
        return listing(model).equilibria[near[0] - 1].at, (note,)
    (name, expr), r = max(zip(about, residual), key=lambda x: abs(_number(x[1], model)))
    raise UnsolvedError(f"{expr.loc}: not an equilibrium: ∂V/∂{unicode_name(name)} = {_number(r, model):.6g} there, and no "
                        f"equilibrium lies within {REFINE_TOL:g} of it")


def _off(about, residual: list[sp.Expr], model: Model) -> tuple[str, object, str]:
    """The first coordinate whose ∂V/∂q is not zero for every value at the point given,
    its expression in the file, and that ∂V/∂q as the message shows it: k l (L₀ − d) for
    a bob on a spring of natural length L₀ to a point d to the side, at θ = 0."""
    (name, expr), r = next((a, r) for a, r in zip(about, residual) if not simplifies_to_zero(r))
    return name, expr, to_unicode(model.readable(r)) if sp.count_ops(r) <= 20 else "not zero"


def _nearest_listed(model: Model, at: dict) -> tuple[int, float] | None:
    """(number, distance) of the listed equilibrium within REFINE_TOL of ``at``, if any."""
    listed = listing(model).equilibria
    best = None
    for k, x in enumerate(listed, 1):
        gap = max(_gap(model, q, _number(at[q], model), _number(x.at[q], model)) for q in model.q)
        if gap <= REFINE_TOL and (best is None or gap < best[1]):
            best = (k, gap)
    return best


def _gap(model: Model, q, a: float, b: float) -> float:
    d = a - b
    if q in model.angles:
        d = (d + math.pi) % (2 * math.pi) - math.pi
    return abs(d)


def _number(value: sp.Expr, model: Model) -> float:
    z = complex(sp.N(sp.sympify(value).xreplace(dict(model.values)), 20))
    return z.real if abs(z.imag) <= 1e-12 * max(1.0, abs(z.real)) else math.inf


def _shown(model: Model, at: dict) -> str:
    return ", ".join(f"{n} = {to_unicode(v)}" for n, v in zip(model.coordinate_names(), at.values()))
