"""An equilibrium of ∂V/∂q = 0 where a contact would have to pull (equilibria/contact_push.py):
said in a warning, from Newton–Euler at rest with the contacts as the only supports."""

from __future__ import annotations

import sympy as sp

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.solvers.equilibria.contact_push import pulling


def test_a_cylinder_at_the_top_inside_a_cylinder_would_need_the_track_to_pull() -> None:
    """By hand: at rest at the top inside the track (θ = π) the push along the normal,
    which points down to the centre there, balances the weight only as N = −m g < 0; at
    the bottom (θ = 0) N = m g > 0, nothing to say."""
    model = build_model(load_file(PROBLEMS / "contacts" / "cylinder-in-cylinder.yaml"))
    (q,) = model.q
    (top,) = pulling(model, {q: sp.pi})
    assert "contact at C would have to pull" in top and "N_C = −g m < 0" in top
    assert pulling(model, {q: sp.Integer(0)}) == ()


def test_a_weighted_disk_at_the_top_of_its_track_too() -> None:
    """By hand: disk m and its weight m₀ at rest at the top, N_C = −(m + m₀) g."""
    model = build_model(load_file(PROBLEMS / "contacts" / "weighted-disk-in-track.yaml"))
    (q,) = model.q
    (top,) = pulling(model, {q: sp.pi})
    assert "N_C = −g (m + m₀) < 0" in top
