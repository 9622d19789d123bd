"""Questions asked in a moving frame: relative equilibria and small oscillations.

In a frame F where the scene is still (a hoop turning at Ω, seen from the hoop), the
Lagrangian L' = T' + L₁ − V' (see :mod:`rbdsolve.model.frames`) has no explicit time,
and its q̇-free part gives the effective potential V' = V_gravity + V_springs + the
centrifugal and translation potentials. Relative equilibria solve ∂V'/∂q = 0, and
small oscillations about them follow M ü + G u̇ + K u = 0 with the gyroscopic matrix
G_ij = ∂c_i/∂q_j − ∂c_j/∂q_i from the part linear in q̇, L₁ = Σ c_i q̇_i. The modes
solver handles G = 0 (always so with one coordinate); otherwise the question is
refused rather than answered without G.
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import UnsolvedError
from rbdsolve.form.arrange import subscript
from rbdsolve.form.display import Relation
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.model.energy import potential_energy
from rbdsolve.model.frames import FrameMotion, frame_lagrangian, frame_motion, in_frame
from rbdsolve.model.state import t
from rbdsolve.problem.schema import Question, QuestionKind
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Solution
from rbdsolve.solvers.shared.present import present


def frame_of(question: Question) -> str | None:
    return getattr(question.options, "frame", None)


def solve_in_frame(solve, question: Question, model: Model, options) -> Solution:
    """Run ``solve`` on the model as seen in the question's frame, its steps after
    the ones that say what the frame adds."""
    frame = model.problem.frame(frame_of(question))
    refuse_loads_in_frame(model, frame.name)
    motion = frame_motion(model, frame)
    seen = in_frame(model, motion)
    if seen.depends_on_time():
        raise UnsolvedError(f"in frame '{frame.name}' the scene still depends on t (a body, a spring or gravity "
                            "moves in it): it has no relative equilibria there")
    if question.kind is QuestionKind.MODES:
        _require_no_gyroscopic_coupling(model, motion)
    solution = solve(question, seen, options)
    return replace(solution, steps=(*_frame_steps(seen, motion), *solution.steps))


def _require_no_gyroscopic_coupling(model: Model, motion: FrameMotion) -> None:
    L = frame_lagrangian(model, motion).L
    c = [sp.diff(L, qd).xreplace({x: 0 for x in model.qd}) for qd in model.qd]
    n = len(c)
    G = sp.Matrix(n, n, lambda i, j: tidy(sp.diff(c[i], model.q[j]) - sp.diff(c[j], model.q[i])))
    if G != sp.zeros(n, n):
        raise UnsolvedError(f"in frame '{motion.frame.name}' the motion has gyroscopic (Coriolis) coupling, "
                            f"G = {to_unicode(sp.ImmutableMatrix(model.readable(G)))}: small oscillations with G are not "
                            "supported yet")


def _frame_steps(seen: Model, motion: FrameMotion) -> list[st.Step]:
    frame = motion.frame
    how = []
    if frame.origin is not None:
        how.append(f"its origin follows {frame.origin.text}")
    if frame.axis is not None:
        how.append(f"it turns at the rate {frame.rate.text} about {frame.axis.text}")
    V = potential_energy(seen)
    rows = [Relation(sp.Symbol(f"V_{i}"), present(term.value, seen)) for i, term in enumerate(V.terms, start=1)]
    legend = ", ".join(f"V{subscript(i)} {term.name}" for i, term in enumerate(V.terms, start=1))
    return [
        st.given(f"In frame {frame.name} ({' and '.join(how) or 'the scene axes'}), positions are "
                 "r' = Rᵀ (r − r_O) and the inertial forces have potentials: −½ m |ω × r'|² "
                 "(centrifugal) and m a_O' · r' (the origin's acceleration)."),
        st.definition(f"Effective potential in frame {frame.name}; {legend}:", *rows,
                      Relation(sp.Symbol("V'"), present(V.total, seen))),
    ]


def require_static(model: Model, what: str) -> None:
    """Equilibria and small oscillations of a scene that moves by itself (t appears in
    it explicitly) are not those of ∂V/∂q = 0: refuse rather than answer wrongly."""
    driven = [x for x in model.loads if x.potential is None and any(q.has(t) for q in x.generalized)]
    if driven:
        raise UnsolvedError(f"{driven[0].kind} '{driven[0].name}' changes with time t, so {what} of ∂V/∂q = 0 "
                            "do not apply (a load that varies in time keeps the scene moving); they exist with "
                            "constant loads")
    if model.depends_on_time():
        raise UnsolvedError(f"the scene depends explicitly on time t, so {what} of ∂V/∂q = 0 "
                            "do not apply; in a frame where the scene is still they do (see 'frames:' and the "
                            "question's 'frame' option)")
    free = [x for x in model.loads if x.potential is None]
    if free:
        raise UnsolvedError(f"{free[0].kind} '{free[0].name}' has no potential (its work depends on the path taken, "
                            f"as a force that turns with its body does), so {what} of ∂V/∂q = 0 do not apply; "
                            "the format gives them for loads with a potential: a constant force, a constant "
                            "couple, a pull of constant size towards a fixed point ('towards:')")


def refuse_loads_in_frame(model: Model, frame: str) -> None:
    """Applied loads are given in the scene's axes; seen from a moving frame their
    potential would move with it: not supported, said so."""
    if model.loads:
        raise UnsolvedError(f"the applied loads ({', '.join(x.name for x in model.loads)}) are given in the scene's "
                            f"axes, and the format does not carry them into frame '{frame}' yet: ask this question "
                            "in the scene's axes (without 'frame')")
