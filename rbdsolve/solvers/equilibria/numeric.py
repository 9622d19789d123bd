"""Equilibria, the floating-point route: ∂V/∂q = 0 by a sign-change scan in one
coordinate (``scan``: complete under a stated assumption) and by Newton's method from
a grid of starts in more (``numeric_model.find_numeric``: no completeness claim); the
strategy and its limits are stated there and in the report. Each root is classified
by the eigenvalues of the Hessian of V there against a tolerance, CURVATURE_TOL times
the Hessian's scale over the search box (all above it: stable; one below −it:
unstable; else zero within rounding: neutral along a continuum, otherwise
undetermined, higher-order terms decide, never a sign from round-off). A continuum of
equilibria (V flat along a straight line, as a cart's x) is reported once, at its
point nearest q = 0 along the free directions, which a warning names
(``continua``); λ = 0 along them is neutral.

Error estimate: one more Newton step, |H⁻¹ ∂V/∂q|, and how far the rounding of
∂V/∂q's terms moves the root, ‖H⁻¹‖ times a few n ε of ∂V/∂q's size over the box,
relative to max(|q|, 1), plus cond(H) ε; on a continuum H and ∂V/∂q are
taken across it only (along it the representative is exact by construction). A
coordinate within that bound of 0, ±π/2 or ±π is that value (numeric/recognized.py).
"""

from __future__ import annotations

import numpy as np

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.printers import unicode_name
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.equilibria.answers import (
    NumericEquilibriaAnswers,
    NumericEquilibrium,
    SingularPoint,
    Stability,
)
from rbdsolve.solvers.equilibria.steps import numeric_steps
from rbdsolve.solvers.lagrange.frames import require_static, spin_warnings
from rbdsolve.solvers.numeric.numeric_model import (
    CURVATURE_TOL,
    compiled_gradient,
    continuum_text,
    find_numeric,
    periodic_angles,
)
from rbdsolve.solvers.configuration import contact_span
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.numeric.recognized import EXACT, recognized_root
from rbdsolve.solvers.numeric.search_box import box_text
from rbdsolve.solvers.configuration.placement import SUGGESTION, numeric_listing
from rbdsolve.solvers.routes.needed import require_values


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    require_static(model, "the equilibria")
    found = find_numeric(model)
    if not found.equilibria:
        return _never_balanced(model, found)
    _, H = compiled_gradient(model)
    names = model.coordinate_names()
    kept, apart = numeric_listing(model, found.equilibria)
    equilibria, errors = [], []
    for r, equivalent in kept:
        x = np.array(r.at)
        hess = np.asarray(H(x), dtype=float)
        curvatures = np.linalg.eigvalsh((hess + hess.T) / 2)
        error, at, recognized, bound = recognized_root(model, r, hess)
        errors.append(error)
        equilibria.append(NumericEquilibrium(at, Stability(r.kind), tuple(float(c) for c in curvatures), r.free,
                                             tuple(dict(zip(names, e.at)) for e in equivalent), recognized, bound))
    singular = tuple(SingularPoint(dict(zip(names, r.at)), s.verdict.value, s.reason, s.kernel) for r, s in apart)
    answers = NumericEquilibriaAnswers(tuple(equilibria), found.starts, singular)
    warnings = (search_claim(model, found), *_range_warnings(model, found), *_continuum_warnings(found, names),
                *contact_span.warnings(list(found.off_edge)), *found.dropped, *spin_warnings(model),
                *(w for e in equilibria for w in _pulling(model, e, names)))
    if singular:
        warnings += (f"{len(singular)} solution(s) of ∂V/∂q = 0 lie at singular points of the coordinates and are "
                     "not equilibria of the scene (listed apart); " + SUGGESTION,)
    return Solution("equilibria", Route.NUMERIC, answers, numeric_steps(answers, model),
                    warnings=warnings, error_estimate=float(max(errors)))


def searched(model: Model, found) -> str:
    """How the search went and over which box."""
    how = (f"a sign-change scan of ∂V/∂q at {found.starts} {found.sampling}" if len(model.q) == 1
           else f"Newton's method from {found.starts} {found.sampling}")
    return (f"{how}, over {box_text(model, periodic_angles(model))} (equilibria outside it are not searched; a coordinate's "
            "'range' sets it)")


def search_claim(model: Model, found) -> str:
    """What the search covers and what it guarantees (the completeness claim)."""
    if len(model.q) == 1:
        return (f"numeric search: {searched(model, found)}; every equilibrium in it is found provided "
                "|∂²V/∂q²| on each cell stays within twice its largest sampled value there and equilibria "
                "are more than the smallest cell apart (closer ones are reported once, or missed)")
    return (f"numeric search: {searched(model, found)}; an equilibrium whose basin misses every start "
            "would be missed (no completeness guarantee in more than one coordinate)")


def _range_warnings(model: Model, found) -> list[str]:
    """Declared angles along which V is not 2π-periodic, and intervals left unsettled."""
    names = dict(zip(model.q, model.coordinate_names()))
    lines = [f"V is not 2π-periodic in {unicode_name(names[q])} (it enters V outside sin and cos, e.g. in a torsional "
             "spring): it was searched as a length, not only over (−π, π]"
             for q in model.q if q in model.angles and q not in periodic_angles(model)]
    if found.unresolved:
        spans = ", ".join(f"[{a:.6g}, {b:.6g}]" for a, b in found.unresolved[:5])
        lines.append(f"the search is incomplete: the scan ran out of evaluations with {len(found.unresolved)} "
                     f"interval(s) unsettled ({spans}{', …' if len(found.unresolved) > 5 else ''})")
    return lines


def _continuum_warnings(found, names: list[str]) -> list[str]:
    """One line per kind of continuum found, and one where the Hessian is singular
    beyond the free directions (higher-order terms decide; perhaps a curved continuum)."""
    lines = list(dict.fromkeys(continuum_text(r.free, names) for r in found.equilibria if r.free))
    singular = [i for i, r in enumerate(found.equilibria, 1) if r.kind == "undetermined"]
    if singular:
        lines.append(f"the Hessian of V is singular at equilibri{'um' if len(singular) == 1 else 'a'} "
                     f"{', '.join(map(str, singular))} (an eigenvalue within {CURVATURE_TOL:g} × the Hessian's "
                     "scale of zero, or within its rounding, beyond any continuum found): undetermined, "
                     "higher-order terms decide the stability there, and a curved continuum of equilibria would be listed point by point")
    return lines


def _pulling(model: Model, e: NumericEquilibrium, names: list[str]) -> tuple[str, ...]:
    """``contact_push.pulling`` at an equilibrium each of whose coordinates is recognized
    as a simple exact value (θ = π: the balances at rest then hold exactly); () else."""
    if set(e.recognized) != set(names) or not model.contacts:
        return ()
    from rbdsolve.solvers.equilibria.contact_push import pulling  # with contacts only: the reactions' balances
    return pulling(model, {q: EXACT[e.recognized[n]] for n, q in zip(names, model.q)})


def _never_balanced(model: Model, found) -> Solution:
    """No equilibrium found: the answer where ∂V/∂q holds no coordinate and is a nonzero
    number at the values (the loads never balance, as on the exact route: uniform.py),
    else a failure that says where the search looked."""
    from rbdsolve.solvers.equilibria.exact import gradient
    from rbdsolve.solvers.equilibria.uniform import never_balanced

    never = never_balanced(model, gradient(model))
    if never is None:
        why = "".join(f"; {d}" for d in found.dropped)  # a root past a spring's zero length, say
        raise UnsolvedError(f"{searched(model, found)} found no equilibrium{why}")
    answers = NumericEquilibriaAnswers((), found.starts)
    return Solution("equilibria", Route.NUMERIC, answers, (*numeric_steps(answers, model), never),
                    error_estimate=0.0)  # (∂V/∂q is a number: nothing to estimate)
