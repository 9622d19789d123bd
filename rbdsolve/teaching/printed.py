"""Answers named as the printed solution names them: ω₁, Ω_c, R_c, λ₂, T_f, v_A.

    printed_names(model, report, kinds) -> {name: (address, ...)}

Each family says which answer its worked solution prints under which name (its
``named``: report/numbers.py), the same names the numeric block uses. A student who
copies a name from the solution (``Omega_c``, ``Ω_c``, ``Ωc``, ``omega_1``) means that
answer; a name printed in several places (K of each equilibrium) stands for all of them,
and the address resolver asks for the whole path.
"""

from __future__ import annotations

from typing import Mapping, Sequence

import sympy as sp

from rbdsolve.form.display import Label
from rbdsolve.form.printers import to_unicode
from rbdsolve.model.build import Model
from rbdsolve.report.steps import ProblemReport
from rbdsolve.model.values.tree import label
from rbdsolve.solvers import FAMILIES
from rbdsolve.teaching.addresses import normal


def printed_names(model: Model, report: ProblemReport, kinds: Sequence[str]) -> Mapping[str, tuple[str, ...]]:
    """Every spelling of each printed name -> the addresses it names, in order."""
    out: dict[str, list[str]] = {}
    for question, solution, kind in zip(model.problem.questions, report.solutions, kinds):
        family = FAMILIES[question.kind]
        if solution.answers is None or family.named is None:
            continue
        for n in family.named(question, solution.answers, model):
            for spelling in spellings(n.name):
                out.setdefault(spelling, [])
                address = label((kind, *n.path))
                if address not in out[spelling]:
                    out[spelling].append(address)
    return {k: tuple(v) for k, v in out.items()}


def spellings(name: object) -> set[str]:
    """'Omega_c' -> Omega_c, Omegac, Ω_c, Ωc: as typed, as printed, with and without '_'."""
    if isinstance(name, Label):
        texts = {name.text}
    elif isinstance(name, sp.Symbol):
        texts = {name.name, to_unicode(name)}
    else:
        return set()
    written = {normal(t) for t in texts}
    return written | {t.replace("_", "") for t in written} | {t.replace(",", "") for t in written}
