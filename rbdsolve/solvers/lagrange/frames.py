"""Questions asked in a moving frame: relative equilibria and small oscillations.

In a frame F where the scene is still (a hoop turning at Ω, seen from the hoop), the
Lagrangian L' = T' + L₁ − V' (see :mod:`rbdsolve.model.energies.frames`) has no explicit time,
and its q̇-free part gives the effective potential V' = V_gravity + V_springs + the
centrifugal potentials (of each centre, −½ m |ω × r'|², and of each body's turning,
−½ ω·J' ω) and the translation potential. Relative equilibria solve ∂V'/∂q = 0, and
small oscillations about them follow M ü + G u̇ + K u = 0 with the gyroscopic matrix
G_ij = ∂c_i/∂q_j − ∂c_j/∂q_i from the part linear in q̇, L₁ = Σ c_i q̇_i, kept in the
seen model (``Model.gyroscopic``): the modes solver answers with G where it couples
the coordinates (solvers/modes/gyroscopic.py). "Still" is decided on the scene as F
sees it, after the frame's turn is taken out of every position and orientation: T'
and V' hold no t (a body's orientation composes the frame's turn with its own).
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model, turning_holds_time
from rbdsolve.model.state import t
from rbdsolve.model.energies.energy import memoized
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Solution

if TYPE_CHECKING:
    from rbdsolve.problem.scene import Frame
    from rbdsolve.model.energies.frames import FrameMotion


def frame_of(question: Question) -> str | None:
    return getattr(question.options, "frame", None)


def model_in_frame(question: Question, model: Model) -> Model:
    """The model as seen in the question's frame; refused where the scene still moves
    there."""
    _, seen = _seen(model, model.problem.frame(frame_of(question)))
    return seen


@memoized
def _seen(model: Model, frame: Frame) -> tuple[FrameMotion, Model]:
    """The frame's motion and the model as seen in it; refused where the scene still
    depends on t there. Built once per model and frame: the equilibria, the modes about
    them and each one's check then share one seen model, and so its memoized T, V and
    equilibria (solvers/equilibria/exact.py ``listing``), as the questions of a scene
    without a frame share the model itself."""
    # a frame's machinery, loaded only where a question names a frame
    from rbdsolve.model.energies.frames import frame_motion, in_frame

    motion = frame_motion(model, frame)
    seen = in_frame(model, motion)
    if seen.depends_on_time():  # what still moves, and for a planar angle the orientation that follows F
        moving = seen.moving_parts()
        what = [m.text for m in moving] or ["the scene"]
        text = (f"in frame '{frame.name}' the scene still depends on t: {', '.join(what)} "
                f"{'moves' if len(what) == 1 else 'move'} in it, so it has no relative equilibria there")
        if frame.axis is not None and any(m.planar_angle for m in moving):
            text += ("; a body's planar 'angle' turns it about z in the scene's axes, not with the frame: where "
                     "the body turns with the frame, give its orientation as turns, the frame's turn first, such as "
                     f"orientation: [[{frame.axis.text}, {frame.rate.text}*t], [y, -theta]] (docs/format.md, frames)")
        raise UnsolvedError(text)
    return motion, seen


def solve_in_frame(solve, question: Question, model: Model, options) -> Solution:
    """Run ``solve`` on the model as seen in the question's frame, its steps after
    the ones that say what the frame adds."""
    from rbdsolve.model.summary.frame import frame_steps

    frame = model.problem.frame(frame_of(question))
    refuse_loads_in_frame(model, frame.name)
    motion, seen = _seen(model, frame)
    solution = solve(question, seen, options)
    return replace(solution, steps=(*frame_steps(seen, motion), *solution.steps))


def spin_warnings(model: Model) -> tuple[str, ...]:
    """What equilibria from V alone leave out where L has terms linear in the rates that
    couple the coordinates (a spin, a turning frame's Coriolis terms): said, never
    dropped. Only scenes that can have them are asked (bodies turned by a sequence of
    turns, a frame's terms): T is not built otherwise."""
    if not (model.gyroscopic or any(b.turns for b in model.bodies)) or len(model.q) < 2:
        return ()
    from rbdsolve.model.energies.gyroscopic import gyroscopic_matrix, has_gyroscopic_terms

    if not has_gyroscopic_terms(model) or gyroscopic_matrix(model) == sp.zeros(len(model.q)):
        return ()
    return ("the scene has gyroscopic terms (L holds terms linear in the rates: a spin, or a turning frame's "
            "Coriolis terms), and the stability here is that of the potential alone: one stable here stays stable "
            "with them, and one with an odd number of directions of negative curvature stays unstable "
            "(Kelvin–Tait–Chetaev), but one with an even number may be held by the spin: 'modes' about it answers "
            "with them (M ü + G u̇ + K u = 0)",)


def require_static(model: Model, what: str) -> None:
    """Equilibria and small oscillations of a scene that moves by itself (t appears in
    it explicitly) are not those of ∂V/∂q = 0: refuse rather than answer wrongly."""
    driven = [x for x in model.loads if x.potential is None and any(q.has(t) for q in x.generalized)]
    if driven:
        raise UnsolvedError(f"{driven[0].kind} '{driven[0].name}' changes with time t, so {what} of ∂V/∂q = 0 "
                            "do not apply (a load that varies in time keeps the scene moving); they exist with "
                            "constant loads")
    if model.depends_on_time():
        spun = [b.name for b in model.bodies if b.turns and any(angle.has(t) for _, angle in b.turns)
                and turning_holds_time(b, model.state)]
        if spun:
            raise UnsolvedError(f"body '{spun[0]}' turns at a rate (an angle with t) about an axis that is not one of "
                                "symmetry of its inertia, so its T changes with t and the scene has no steady state: "
                                "a steady spin is one about an axis of symmetry (a disk's or a top's axis; "
                                "docs/format.md, spinning bodies)")
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
