"""The numeric block of a solution: each answer's value under the name the worked
solution prints it by (ω₁, λ₂, M, K, Ω_c, v_G1), with its unit and what a reader wants
beside it (a frequency's period, an angle in degrees, the fraction of energy lost).

A family says which answers carry which printed name (``Named``: a path in the answers
tree, docs/json.md, and the name); ``model/values/numbers.py`` reads their values and
units and writes the lines (``Number``), which every renderer prints. The grading of a
student's answers reads the same names (teaching/), so that ``omega_c = …`` is checked
against the answer the solution calls ω_c.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import sympy as sp

from rbdsolve.form.display import Label, Relation

Path = tuple[str | int, ...]  # keys and 0-based indices from the root of an answers tree


class Meaning(Enum):
    """What a number is, where that puts something beside it."""

    PLAIN = "plain"
    FREQUENCY = "frequency"  # an angular frequency ω: its period 2π/ω beside it
    ENERGY_LOST = "energy_lost"  # Tᵢ − T_f: negative reads as an energy gained
    FRACTION = "fraction"  # a ratio shown also as a percentage
    LEAST = "least"  # a least value asked (the friction a contact needs): written μ_C ≥ 0.145588


@dataclass(frozen=True)
class Named:
    """An answer (or a group of them: a vector, a matrix, a state) at ``path`` in the
    answers tree, printed as ``name``: a sympy symbol (omega_1, M), an expression of
    symbols (T_i − T_f, Ω²) or a tuple of them ((θ, φ) for an equilibrium's place).
    ``group``: the heading it falls under (Equilibrium 2, Branch 1), '' for none."""

    path: Path
    name: sp.Basic | Label  # a Label where no sympy name prints as the solution does (ω⊥, φ̇)
    group: str = ""
    meaning: Meaning = Meaning.PLAIN
    accuracy: bool = False  # says how accurate an answer is (a bound, a residual): shown apart


class Beside(Enum):
    """What a note beside a number says."""

    PERIOD = "period"  # a frequency's period 2π/ω, in s
    DEGREES = "degrees"  # angles in rad, also in degrees
    PERCENT = "percent"  # a fraction as a percentage
    GAINED = "gained"  # an energy lost that is negative, printed as the energy gained
    OPEN = "open"  # a value with one parameter left without one: the units ('in 1/s², k in m')


@dataclass(frozen=True)
class Note:
    """A note beside a number, as data: its numbers are printed by the renderer, to the
    digits the reader asked for (``--digits``), like the number itself."""

    kind: Beside
    values: tuple[float, ...] = ()
    open: tuple[str, str | None] | None = None  # Beside.OPEN: the parameter left open, its SI unit (None: not known)


@dataclass(frozen=True)
class Number:
    """One line of the numeric block: ``relation`` (name = value, floats), the SI unit of
    its value ('' for none or a pure number), and a note beside it (a period, the angle
    in degrees: render/numbers.note_text prints it as 'period 1.45 s', '60°')."""

    relation: Relation
    unit: str = ""
    note: Note | None = None
    group: str = ""
    accuracy: bool = False
    path: Path = ()
