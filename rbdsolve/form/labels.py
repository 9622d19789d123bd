"""The solvers' own labels — the mass matrix M, an eigenvalue λ₁, a mode's amplitudes
a₁, a composite body's total mass m — chosen so that they never coincide with a name
the problem uses.

Each internal label is a key of ``REGISTRY`` with its candidates in order of
preference; ``Labels.of(problem's names)`` takes, for each key a solution asks for,
the first candidate that prints differently from every name of the problem and from
the labels already taken for the same solution. A scene with a parameter M gets the
mass matrix M_q; a cart's acceleration a pushes the amplitudes to X. The JSON keys
(``M``, ``eigenvalues``, ``shapes``) never change: only the printed labels do.

An indexed label (λ₁, ω₂) clashes with a problem name of the same letter and a number
(omega1, omega_2); the bare letter used in prose ("ω = √λ") clashes with the bare
name (a hoop's rate omega), and then prose writes it with an index k (ωₖ = √λₖ).
"""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
from typing import Iterable, Mapping

import sympy as sp

from rbdsolve.form.printers import split_name, unicode_name

REGISTRY: dict[str, tuple[str, ...]] = {
    "mass_matrix": ("M", "M_q"),
    "stiffness_matrix": ("K", "K_q"),
    "gyroscopic_matrix": ("G", "G_q"),
    "displacement": ("u", "eta", "xi"),
    "eigenvalue": ("lamda", "Lambda"),
    "scaled_eigenvalue": ("mu", "kappa", "nu"),
    "frequency": ("omega", "nu", "varpi"),
    "growth_rate": ("gamma", "sigma"),
    "exponent": ("s", "p", "z"),  # u = X e^(st): a root of the quadratic eigenproblem
    "energy_constant": ("h", "H", "h_E"),  # T + V = h, Jacobi's h: beside a hump of height h, H
    "amplitude": ("a", "X", "Y"),
    "total_mass": ("m", "M", "m_tot"),
    "angular_momentum": ("L", "H", "L_ang"),  # L_O = J_G ω + r_OG × m v_G; H_O beside an axle of length L
    "angular_velocity": ("omega", "omega_b"),  # a body's ω beside a spin rate named omega
    "coordinate_index": ("a", "j", "k"),  # I_a, ∂T/∂q̇_a in the impact's prose
    "particle_mass": ("mu", "m_p"),  # u|i − P/μ: a sticking particle's mass
}
INDEXED = frozenset({"eigenvalue", "frequency", "growth_rate", "amplitude", "exponent"})
STRICT = frozenset({"amplitude", "eigenvalue", "exponent"})  # indexed, yet a bare name of the letter moves them too:
# a₁ beside a cart's a; λ is the variable of det(K − λM) = 0 as well
LAST_RESORT = "'"  # appended to the last candidate until it is free: M_q'


@dataclass(frozen=True)
class Labels:
    """The labels one solution prints, each chosen once: key → sympy name."""

    chosen: Mapping[str, str]  # read-only
    taken: frozenset[str]  # how the problem's names print

    @staticmethod
    def of(names: Iterable[str], keys: Iterable[str]) -> Labels:
        """Labels for ``keys`` (in that order: an earlier key has the first pick) beside
        the problem's ``names`` (parameters, coordinates, points, bodies...)."""
        names = tuple(names)
        shown = {unicode_name(n) for n in names}
        letters = {_letter(n) for n in names if split_name(n)[1].isdigit()}
        chosen: dict[str, str] = {}
        for key in keys:
            name = _first_free(REGISTRY[key], shown, letters, key in INDEXED, key in STRICT)
            chosen[key] = name
            shown.add(unicode_name(name))
            letters.add(_letter(name))
        return Labels(MappingProxyType(chosen), frozenset(unicode_name(n) for n in names))

    def name(self, key: str) -> str:
        return self.chosen[key]

    def symbol(self, key: str, index: int | None = None) -> sp.Symbol:
        """M, or λ₁ with an index (sympy name lamda_1)."""
        name = self.chosen[key]
        return sp.Symbol(name if index is None else f"{name}_{index}")

    def text(self, key: str, indexed: bool = False) -> str:
        """The label in prose: M, λ; with an index k where asked, or where the label is
        indexed and the problem uses its bare letter (ωₖ beside a hoop's rate ω)."""
        name = self.chosen[key]
        if indexed or self.needs_index(key):
            return unicode_name(f"{name}_k")
        return unicode_name(name)

    def needs_index(self, key: str) -> bool:
        return key in INDEXED and key not in STRICT and unicode_name(self.chosen[key]) in self.taken


def _letter(name: str) -> str:
    return unicode_name(split_name(name)[0])


def _first_free(candidates: tuple[str, ...], shown: set[str], letters: set[str], indexed: bool,
                strict: bool = False) -> str:
    """The first candidate that prints unlike the names taken: for an indexed label,
    unlike every indexed name (λ₁ beside lamda1), for a plain one unlike every name;
    a strict indexed one both."""
    def free(name: str) -> bool:
        apart = _letter(name) not in letters if indexed else True
        return apart and (unicode_name(name) not in shown if strict or not indexed else True)

    name = next((n for n in candidates if free(n)), candidates[-1])
    while not free(name):
        name += LAST_RESORT
    return name
