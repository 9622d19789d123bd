"""Which answer a student or a teacher means: the JSON paths of docs/json.md, and a few
readable aliases.

An address is a question's label and the path inside its answers, keys joined by '.',
indices in brackets counting from 1 as the printed solution does:
``modes.frequencies[1]`` is ω₁, ``equilibria.equilibria[2].at.phi`` the second
equilibrium's φ, ``modes(2).eigenvalues[1]`` the first eigenvalue of a file's second
modes question. The same spelling names the columns of ``rbdsolve variants``
(model/values/tree.label). The question's label may be left out where only one question has
that path (``frequencies[1]``).

Aliases, for the answers asked most (each only where the file has one question of its
kind, so that it names one answer):

    omega1, ω1, ω₁         modes.frequencies[1]
    lambda1, λ1, λ₁        modes.eigenvalues[1]
    equilibrium2.theta     equilibria.equilibria[2].at.theta
    equilibrium2.stability equilibria.equilibria[2].stability
    dot(x)                 impact.velocities.x   (the velocity just after the impact)
    J1                     inertia.principal_moments[1]

and every name the printed solution gives an answer (Omega_c, Ω_c, R_c, T_f, v_A:
teaching/printed.py), where it names one answer.

(A student's check also names an equilibrium by its place: teaching/check._by_place.)
"""

from __future__ import annotations

import re
from typing import Mapping, Sequence

from rbdsolve.errors import InputError, Location, clipped, did_you_mean

_SUBSCRIPTS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
_INDEX = re.compile(r"\[(\d+)\]")
MAX_INDEX_DIGITS = 6  # a million entries: far past any answer; int() of 5,000 digits is refused by Python
_FIRST = re.compile(r"^([A-Za-z_]+)\(1\)(?=\.|$)")

# (pattern of the alias, the question kind it belongs to, the path it stands for)
ALIASES: tuple[tuple[re.Pattern, str, str], ...] = (
    (re.compile(r"(?:omega|ω)(\d+)"), "modes", "frequencies[{0}]"),
    (re.compile(r"(?:lambda|λ)(\d+)"), "modes", "eigenvalues[{0}]"),
    (re.compile(r"equilibrium(\d+)\.stability"), "equilibria", "equilibria[{0}].stability"),
    (re.compile(r"equilibrium(\d+)\.(\w+)"), "equilibria", "equilibria[{0}].at.{1}"),
    (re.compile(r"dot\((\w+)\)"), "impact", "velocities.{0}"),
    (re.compile(r"J(\d+)"), "inertia", "principal_moments[{0}]"),
)


def normal(text: str) -> str:
    """The address without spaces, subscript digits as digits (ω₁ is omega1's ω1)."""
    return "".join(text.split()).translate(_SUBSCRIPTS)


def resolve(text: str, labels: Sequence[str], loc: Location, printed: Mapping[str, tuple[str, ...]] = {},
            answers: Mapping[str, object] = {}) -> str:
    """The label among ``labels`` that ``text`` addresses (itself, an alias, a path whose
    question is left out, or a name as the solution prints it: ``printed``,
    teaching/printed.py); an InputError at ``loc`` naming the closest otherwise. A name
    that several labels hold with one and the same answer (Ω_c, the critical rate of the
    equilibria and of the modes) addresses the first of them."""
    address = normal(text)
    if not address:
        raise InputError("expected the name of an answer before '=', found nothing", loc)
    indices = _INDEX.findall(address)
    if any(not i.strip("0") for i in indices):
        raise InputError(f"'{clipped(address)}': indices count from 1, as in the printed solution "
                         "(modes.frequencies[1] is ω₁)", loc)
    if any(len(i) > MAX_INDEX_DIGITS for i in indices):
        raise InputError(f"'{clipped(address)}': an index of more than {MAX_INDEX_DIGITS} digits; no answer has "
                         "so many entries", loc)
    address = _FIRST.sub(r"\1", address)  # reactions(1).… is the first reactions question: reactions.…
    known = set(labels)
    if address in known:
        return address
    found = _by_alias(address, labels) or _without_question(address, labels) or list(printed.get(address, ()))
    if len(found) == 1 and found[0] not in known:  # a printed name of a vector, a matrix, a state
        address = found[0]
        found = []
    if len(found) == 1:
        return found[0]
    if len(found) > 1 and _one_answer(found, answers):
        return found[0]
    if len(found) > 1:
        raise InputError(f"'{clipped(address)}' could be any of {', '.join(found)}: give the whole path", loc)
    inside = [label for label in labels if label.startswith((address + "[", address + "."))
              or "." in label and label.split(".", 1)[1].startswith((address + "[", address + "."))]
    if len(inside) == 1:  # a list of one (where contact is lost: one equation)
        return inside[0]
    if inside:
        raise InputError(f"'{clipped(address)}' holds several answers: check them one by one, e.g. {inside[0]}",
                         loc)
    raise InputError(f"no answer is called '{clipped(address)}'{_hint(address, labels)}", loc)


def question_kind(label: str) -> str:
    """'modes' for 'modes(2).eigenvalues[1]'."""
    head = label.split(".", 1)[0]
    return head.split("(", 1)[0]


def _by_alias(address: str, labels: Sequence[str]) -> list[str]:
    for pattern, kind, path in ALIASES:
        match = pattern.fullmatch(address)
        if match:
            questions = sorted({label.split(".", 1)[0] for label in labels if question_kind(label) == kind})
            return [f"{q}.{path.format(*match.groups())}" for q in questions
                    if f"{q}.{path.format(*match.groups())}" in labels]
    return []


def _without_question(address: str, labels: Sequence[str]) -> list[str]:
    return [label for label in labels if label.split(".", 1)[-1] == address and "." in label]


def _hint(address: str, labels: Sequence[str]) -> str:
    """A close label, else the first few of the question's answers."""
    close = did_you_mean(address, labels)
    if close:
        return close
    kinds = sorted({label.split(".", 1)[0] for label in labels})
    shown = ", ".join(kinds) if kinds else "none"
    return f" (the questions are {shown}; e.g. {labels[0]})" if labels else " (this file has no answers to check)"


def _one_answer(found: list[str], answers: Mapping[str, object]) -> bool:
    """Do the labels all hold the same expression (sympy's structural equality: the
    same value written the same way, as one solver family's answer repeated in another)?"""
    held = [answers.get(label) for label in found]
    return held[0] is not None and all(h == held[0] for h in held[1:])
