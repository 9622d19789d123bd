"""The section a question asked in a moving frame opens with, after the model section:
how the frame moves, what it adds to the scene (positions r' = Rᵀ (r − r_O), the
potentials of the inertial forces: −½ m |ω × r'|² centrifugal, m a_O' · r' for the
origin's acceleration, −½ ω·J' ω for a turning body), and the effective potential V'
term by term, as the model section writes T and V (model/energies/frames.py builds the
model as the frame sees it). Used by solvers/lagrange/frames.py."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import arranged, subscript
from rbdsolve.form.display import Relation
from rbdsolve.form.printers import to_unicode
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import potential_energy
from rbdsolve.model.energies.frames import FrameMotion
from rbdsolve.report import steps as st


def frame_steps(seen: Model, motion: FrameMotion) -> list[st.Step]:
    """What the frame adds (r' = Rᵀ (r − r_O), the inertial forces' potentials), then
    the effective potential V' term by term, read from the model as the frame sees it
    (``seen``: model/energies/frames.py ``in_frame``)."""
    frame = motion.frame
    how = []
    if frame.origin is not None:
        how.append(f"its origin follows {frame.origin.text}")
    if frame.axis is not None:
        how.append(f"it turns at the rate {to_unicode(seen.readable(motion.rate))} about {frame.axis.text}")
    turning = "; a body that turns adds −½ ω·J' ω, J' its inertia in the frame's axes." if _turning(seen) else "."
    V, reading = potential_energy(seen), seen.reading()
    rows = [Relation(sp.Symbol(f"V_{i}"), arranged(term.value, reading)) for i, term in enumerate(V.terms, start=1)]
    total = Relation(sp.Symbol("V'"), arranged(V.total, reading))
    legend = ", ".join(f"V{subscript(i)} {term.name}" for i, term in enumerate(V.terms, start=1))
    return [
        st.given(f"In frame {frame.name} ({' and '.join(how) or 'the scene axes'}), positions are "
                 "r' = Rᵀ (r − r_O) and the inertial forces have potentials: −½ m |ω × r'|² "
                 "(centrifugal) and m a_O' · r' (the origin's acceleration)" + turning),
        # the solver's steps that follow write ∂V/∂q and ∂²V/∂q∂q: here V is V'
        st.definition(f"Effective potential in frame {frame.name} (the V of the steps below); {legend}:",
                      *rows, total),
    ]


def _turning(seen: Model) -> bool:
    return any(x.name.endswith(", turning") for x in seen.inertial)
