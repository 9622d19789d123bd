"""Mode shapes to draw: the sketches of a modes question's equilibrium and of each mode
displaced from it, q₀ + a·u_k.

The numbers come from the numeric modes machinery (``equilibrium_for_modes``,
``linearized``, ``generalized_eigh``: the same M, K and eigenvectors as the numeric
route's answers), at the parameter values, 1 where a value is missing (the caption
says so). The amplitude a is chosen per mode so that the point of the scene that moves
most moves VISIBLE × the scene's size (the displacement per unit a is taken from the
sketches themselves), and no angle turns by more than MAX_TURN.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.render.drawing.sketch import Sketch, ones_note, require_planar, sketch, unvalued
from rbdsolve.problem.schema import Question
from rbdsolve.form.arrange import subscript
from rbdsolve.solvers.modes.answers import Motion
from rbdsolve.solvers.modes.numeric import normalized, classify, generalized_eigh

VISIBLE = 0.2  # the largest displacement drawn, as a fraction of the scene's size
MAX_TURN = 0.6  # rad: the largest angle a mode picture turns a coordinate by
PROBE = 1e-4  # the step that measures the displacement per unit amplitude


@dataclass(frozen=True)
class ModeShape:
    index: int  # 1-based, by ascending λ
    eigenvalue: float
    motion: Motion
    vector: tuple[float, ...]  # u, its first entry that is not round-off 1 (as the answers show it)
    amplitude: float  # a: the picture is q₀ + a·u
    sketch: Sketch

    def title(self) -> str:
        """ω_k for an oscillation, γ_k for growth, λ_k for a neutral mode."""
        k = subscript(self.index)
        if self.motion is Motion.OSCILLATION:
            return f"mode {self.index}: ω{k} = {np.sqrt(self.eigenvalue):.4g}"
        if self.motion is Motion.GROWTH:
            return f"mode {self.index}: unstable, γ{k} = {np.sqrt(-self.eigenvalue):.4g}"
        return f"mode {self.index}: neutral, λ{k} ≈ 0"

    def shape_text(self) -> str:
        return "u = (" + ", ".join(f"{x:.3g}" for x in self.vector) + ")"


@dataclass(frozen=True)
class ModeShapes:
    equilibrium: Sketch
    modes: tuple[ModeShape, ...]
    notes: tuple[str, ...]  # parameters taken as 1, the equilibrium chosen


def mode_shapes(model: Model, question: Question) -> ModeShapes:
    """The mode pictures of a modes question; NotDrawable for a scene that is not planar,
    UnsolvedError where the numeric route cannot answer (no stable equilibrium, singular M)."""
    from rbdsolve.solvers.numeric.chosen import equilibrium_for_modes
    from rbdsolve.solvers.numeric.numeric_model import linearized

    require_planar(model)
    filled = model.with_values({name: Fraction(1) for name in unvalued(model)})
    seen = _in_frame(filled, question)
    from rbdsolve.solvers.modes import gyroscopic_terms

    if gyroscopic_terms.applies(question, seen):
        raise UnsolvedError("the modes cannot be drawn: the scene has gyroscopic terms (a turning frame's Coriolis "
                          "terms, a spin), so its small motions are whirls, not normal modes with one shape each")
    about, notes = equilibrium_for_modes(question, seen)
    M, K, _ = linearized(seen, about)
    lam, vectors, bounds = generalized_eigh(K, M)
    q0 = {name: _number(v, filled) for name, v in about.items()}
    rest = sketch(filled, q0)
    modes = tuple(_mode(filled, rest, q0, k, float(x), classify(x, b), vectors[:, k - 1])
                  for k, x, b in zip(range(1, len(lam) + 1), lam, bounds))
    return ModeShapes(rest, modes, ones_note(unvalued(model)) + tuple(notes))


def _in_frame(model: Model, question: Question) -> Model:
    """The model as the question's frame sees it (the solvers' own view), if it names one."""
    from rbdsolve.solvers.lagrange.frames import frame_of

    name = frame_of(question)
    if name is None:
        return model
    from rbdsolve.model.energies.frames import frame_motion, in_frame

    return in_frame(model, frame_motion(model, model.problem.frame(name)))


def _number(value, model: Model) -> float:
    import sympy as sp

    return float(sp.N(sp.sympify(value).xreplace(dict(model.values)), 17))


def _mode(model: Model, rest: Sketch, q0: dict[str, float], index: int, lam: float, motion: Motion,
          u: np.ndarray) -> ModeShape:
    shape = np.asarray(normalized(u))
    shape = shape / np.max(np.abs(shape))  # the largest entry 1: a is then the largest coordinate change
    a = amplitude(model, rest, q0, shape)
    moved = sketch(model, _displaced(q0, shape, a))
    return ModeShape(index, lam, motion, normalized(u), a, moved)


def amplitude(model: Model, rest: Sketch, q0: dict[str, float], u: np.ndarray) -> float:
    """a such that the anchor that moves most moves VISIBLE × the scene's size, no angle
    turning by more than MAX_TURN."""
    probe = sketch(model, _displaced(q0, u, PROBE))
    moved = max((np.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(rest.anchors, probe.anchors)), default=0.0)
    per_unit = moved / PROBE
    a = VISIBLE * rest.size() / per_unit if per_unit > 1e-9 else MAX_TURN
    turns = [abs(x) for x, q in zip(u, model.q) if q in model.angles]
    return min(a, MAX_TURN / max(turns)) if turns and max(turns) > 0 else a


def _displaced(q0: dict[str, float], u: np.ndarray, a: float) -> dict[str, float]:
    return {name: value + a * float(x) for (name, value), x in zip(q0.items(), u)}
