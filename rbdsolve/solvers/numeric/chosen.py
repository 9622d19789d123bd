"""Which equilibrium small oscillations are taken about, on the floating-point route
(the modes' numeric route and the mode pictures).

``about: {θ: …}`` near an equilibrium is refined by Newton's method on ∂V/∂q (with
the Hessian of V) and used when the refined point lies within REFINE_TOL of the one
given in every coordinate (angles compared modulo 2π), so a root copied with 6 digits
from the printed equilibria is taken as that root; farther away, it is refused with
the residual as a number (a spinning body's steady state given with its spin's rate is
refined on the steady motion's equations instead: modes/gyroscopic_numeric.py).
``about: {equilibrium: N}`` takes the N-th equilibrium as
the numeric ``equilibria`` lists it. Neither: the first stable one, and when there are
several, a note names the others.
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import unicode_name
from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.solvers.configuration import contact_span

# no equilibrium at all (a rod driven by a couple past m g l/4): nothing to choose either
NO_EQUILIBRIUM = ("there is no equilibrium ('equilibria' says why), so no small oscillations about "
                  "one")
REFINE_TOL = 1e-3  # how far (per coordinate) a given point may lie from the equilibrium it names


def equilibrium_for_modes(question: Question, model: Model) -> tuple[dict[str, sp.Expr], tuple[str, ...]]:
    """The equilibrium the question names (refined), or the stable one; and notes on
    how it was chosen."""
    # numpy's machinery only here: the exact route imports this module for its constants
    from rbdsolve.solvers.numeric.numeric_model import continuum_text, find_numeric
    from rbdsolve.solvers.numeric.recognized import exactly
    from rbdsolve.solvers.configuration.placement import numeric_listing

    options = question.options
    if options.about is not None:
        return _refined(question, model)
    kept = [r for r, _ in numeric_listing(model, find_numeric(model).equilibria)[0]]
    if options.equilibrium is not None:
        return _numbered(model, kept, options.equilibrium, options.loc)
    if not kept:
        raise UnsolvedError(NO_EQUILIBRIUM)
    stable = [r for r in kept if r.kind == "stable"]
    across = [r for r in kept if r.kind == "neutral" and r.free and r.stable_across]
    if not stable and not across:
        raise UnsolvedError("no stable equilibrium found numerically; choose one with 'modes: {about: {...}}'")
    chosen = (stable or across)[0]
    notes = []
    if chosen.free:
        notes.append(continuum_text(chosen.free, model.coordinate_names()) + "; the modes are taken about it, the "
                     "first equilibrium found that is stable across the continuum (choose another with 'modes: "
                     "{about: {...}}'); along the continuum λ = 0: neutral")
    if len(stable) > 1:
        notes.append(several_stable(kept.index(chosen) + 1,
                                    [(kept.index(r) + 1, _shown(model, r.at)) for r in stable if r is not chosen]))
    return exactly(model, chosen), tuple(notes)


def several_stable(number: int, others: list[tuple[int, str]]) -> str:
    """The note on a choice among stable equilibria (both routes)."""
    listed = "; ".join(f"equilibrium {k}: {where}" for k, where in others)
    return (f"{len(others) + 1} equilibria are stable; the modes are taken about the first, equilibrium {number} "
            f"as 'equilibria' numbers them. The others: {listed}. Choose one with "
            "'modes: {about: {equilibrium: N}}'")


def _numbered(model: Model, kept: list, number: int, loc) -> tuple[dict[str, sp.Expr], tuple[str, ...]]:
    if number > len(kept):
        raise UnsolvedError(f"{loc}: there is no equilibrium {number}: 'equilibria' finds {len(kept)} here")
    from rbdsolve.solvers.numeric.recognized import exactly

    return exactly(model, kept[number - 1]), ()


def _refined(question: Question, model: Model) -> tuple[dict[str, sp.Expr], tuple[str, ...]]:
    """Newton from the given point; the refined point if it is within REFINE_TOL."""
    import numpy as np

    from rbdsolve.solvers.numeric.newton import newton
    from rbdsolve.solvers.numeric.numeric_model import compiled_gradient, difference, root_tolerance

    about = question.options.about
    contact_span.require_on_edges(question, model)
    given = np.array([_real(model.symbols.scalar(e), model, e, name) for name, e in about])
    g, H = compiled_gradient(model)
    residual = np.asarray(g(given), dtype=float)
    # ∂V/∂q exactly 0 is within any tolerance: V's scale over the box is then not needed
    tol = root_tolerance(model) if np.any(residual) else 0.0
    if np.max(np.abs(residual)) <= tol:
        return {n: model.symbols.scalar(e) for n, e in about}, ()
    refined = newton(given, g, H)
    if refined is not None and np.max(np.abs(difference(model, refined, given))) <= REFINE_TOL \
            and np.max(np.abs(np.asarray(g(refined), dtype=float))) <= tol:
        note = (f"about: the point given is {float(np.max(np.abs(refined - given))):.2g} from an equilibrium; "
                f"refined by Newton's method on ∂V/∂q to {_shown(model, refined)}")
        return _named(model, refined), (note,)
    (name, expr), r = max(zip(about, residual), key=lambda x: abs(x[1]))
    raise UnsolvedError(f"{expr.loc}: not an equilibrium: ∂V/∂{unicode_name(name)} = {r:.6g} there, and no equilibrium lies "
                        f"within {REFINE_TOL:g} of it")


def _real(value: sp.Expr, model: Model, expr, name: str) -> float:
    """A coordinate of ``about`` as a float at the parameter values, refused where it is
    not a real number there (acos(g/l) with g > l)."""
    import math

    number = complex(sp.N(value.xreplace(dict(model.values)), 20))
    if number.imag != 0 or not math.isfinite(number.real):
        raise UnsolvedError(f"{expr.loc}: {name} = {expr.text} is not a real number at the parameter values "
                            f"({number:.6g}); choose a configuration that exists there")
    return number.real


def _named(model: Model, at) -> dict[str, sp.Expr]:
    return {n: sp.Float(float(v), 17) for n, v in zip(model.coordinate_names(), at)}


def _shown(model: Model, at) -> str:
    return ", ".join(f"{n} = {float(v):.9g}" for n, v in zip(model.coordinate_names(), at))
