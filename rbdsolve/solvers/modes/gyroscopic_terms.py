"""Which route a modes question takes: a scene with gyroscopic terms (a spin, a turning
frame's Coriolis terms) has its own (gyroscopic.py, M ü + G u̇ + K u = 0); and what is
said of a spin angle given a value in 'about'.

Apart from that route so that a scene without such terms (most exam files) never loads
it: the checks here ask the model only what decides it.
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question


def applies(question: Question, model: Model) -> bool:
    """Steady rates in 'about' (Routh), or terms linear in the rates that couple the
    coordinates (G ≠ 0 somewhere): then the gyroscopic route answers. Only a body turned
    by a sequence of turns (a spin) or a frame's Coriolis terms bring such terms into a
    scene without t."""
    if question.options.steady:
        return True
    if len(model.q) < 2 or not (model.gyroscopic or any(b.turns for b in model.bodies)):
        return False  # only these can have such terms in a still scene: T is not built otherwise
    from rbdsolve.model.energies.gyroscopic import gyroscopic_matrix, has_gyroscopic_terms

    return has_gyroscopic_terms(model) and gyroscopic_matrix(model) != sp.zeros(len(model.q))


def spin_notes(question: Question, model: Model) -> tuple[str, ...]:
    """A spin angle (a coordinate in a body's turns that L does not hold) given a value
    in 'about': the modes are those of the body at rest, said so, with the form for a
    steady spin."""
    turned = {s for b in model.bodies for _, angle in b.turns for s in angle.free_symbols}
    given = [n for n, _ in (question.options.about or ())]
    spins = [n for n, q in zip(model.coordinate_names(), model.q) if n in given and q in turned]
    if not spins:
        return ()
    from rbdsolve.solvers.modes.gyroscopic_steps import cyclic_note
    from rbdsolve.solvers.modes.routh import lagrangian

    L = lagrangian(model)
    return tuple(cyclic_note(n) for n, q in zip(model.coordinate_names(), model.q) if n in spins and not L.has(q))
