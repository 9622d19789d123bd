"""A student's check: is my answer right? Without giving the answer away.

    check(problem, entries) -> CheckRun

The problem is solved exactly once, its parameters symbolic. Each entry
``ADDRESS = EXPRESSION`` names one answer (teaching/addresses.py) and gives the student's
expression in the problem's own symbols, read by the same safe parser as a problem file
(problem/expr.py: a whitelist of syntax, never eval or sympify) and folded with the
model's symbols (positive where declared), so that sqrt(g/r) means what the problem
means. teaching/compare.py gives the verdict. A malformed entry (an unknown answer, an
unknown symbol, a non-expression) is one message; the others are still checked.
"""

from __future__ import annotations

import random
import re
from dataclasses import dataclass
from enum import Enum

import sympy as sp
from sympy.core.relational import Relational

from rbdsolve.errors import InputError, Location, UnsolvedError
from rbdsolve.form.printers import to_unicode
from rbdsolve.model.assumptions import admissible_sample
from rbdsolve.model.build import Model, build_model
from rbdsolve.problem import expr as ex
from rbdsolve.problem.schema import Problem
from rbdsolve.model.values.tree import label, leaves
from rbdsolve.solvers import Options, RouteChoice, solve_problem
from rbdsolve.solvers.routes.budget import Allowance, OutOfTime, within
from rbdsolve.teaching.addresses import resolve
from rbdsolve.teaching.compare import Sampler, compare, value_at
from rbdsolve.teaching.files import read_file
from rbdsolve.teaching.given_units import factor_to, split_unit
from rbdsolve.teaching.printed import printed_names
from rbdsolve.teaching.relations import compare_relation, relation, split_relation
from rbdsolve.teaching.variants import question_labels
from rbdsolve.teaching.grading import Rule, slip_of
from rbdsolve.teaching.verdicts import Different, Equivalent, Proof, Slipped, Undecided, Verdict

EXAMPLE = "modes.frequencies[1] = sqrt(24*g/(25*r))"
MAX_ENTRIES = 500  # a check is a student's sheet; each answer may take seconds to compare
_LINE_END = re.compile(r"\r\n|\r|\n")  # the lines an editor shows (str.splitlines also splits at \x0c, \x85 …)


@dataclass(frozen=True)
class Entry:
    """One answer to check: the address as written, the expression's text and where
    the expression starts (a file's line and column, or an --answer option)."""

    address: str
    text: str
    loc: Location


@dataclass(frozen=True)
class Checked:
    """One checked answer: its address (the full path), the expression as given, the
    verdict, and rbdsolve's answer in unicode (shown only when asked)."""

    address: str
    given: str
    verdict: Verdict
    answer: str
    loc: Location

    @property
    def right(self) -> bool:
        return self.verdict.right


@dataclass(frozen=True)
class CheckRun:
    file: str
    checked: tuple[Checked, ...]
    errors: tuple[InputError, ...]


def read_entry(line: str, loc: Location) -> Entry:
    """'ADDRESS = EXPRESSION', split at the first '=' outside brackets (an address may
    hold some: equilibrium(theta=0, phi=pi).stability); the expression's location is its
    column in ``line``."""
    depth, split = 0, None
    for i, ch in enumerate(line):
        depth += (ch in "([") - (ch in ")]")
        if ch == "=" and depth == 0:
            split = i
            break
    if split is None or line[split + 1: split + 2] == "=":
        raise InputError(f"expected 'ANSWER = EXPRESSION', e.g. '{EXAMPLE}'", loc)
    return Entry(line[:split], line[split + 1:], loc.shifted(split + 1))


def read_entries(path: str) -> tuple[list[Entry], list[InputError]]:
    """An answers file: one 'ADDRESS = EXPRESSION' a line; '#' starts a comment line."""
    entries, errors = [], []
    for n, line in enumerate(_LINE_END.split(read_file(path)), start=1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        try:
            entries.append(read_entry(line, Location(path, n, 1)))
        except InputError as exc:
            errors.append(exc)
    if not entries and not errors:
        errors.append(InputError(f"no answers in the file; write one a line, e.g. '{EXAMPLE}'", Location(path, 1, 1)))
    return entries, errors


def check(problem: Problem, entries: list[Entry], budget: float | None = None, rule: Rule = Rule()) -> CheckRun:
    """Each entry's verdict against the exact solution of ``problem``; a number given
    for an answer whose parameters all have values is held to ``rule``."""
    if len(entries) > MAX_ENTRIES:
        raise InputError(f"{len(entries)} answers to check; the limit is {MAX_ENTRIES}: check them in parts "
                         f"(answer {MAX_ENTRIES + 1} is here)", entries[MAX_ENTRIES].loc)
    run = Allowance(budget)  # one budget for the check: the model, the solve, every comparison
    try:
        with within(run.left(), "the model (T and V)", budget):
            model = build_model(problem)
    except OutOfTime as exc:
        raise UnsolvedError(f"{problem.file}: {exc}") from None
    report = solve_problem(model, Options(route=RouteChoice.EXACT, budget=run.left(), budget_total=budget))
    kinds = question_labels([s.question for s in report.solutions])
    answers = {label((q, *path)): leaf for q, s in zip(kinds, report.solutions) if s.answers is not None
               for path, leaf in leaves(s.answers)}
    unsolved = {q: s.error for q, s in zip(kinds, report.solutions) if s.answers is None}
    sampler = _sampler(model)
    names = printed_names(model, report, kinds)
    units = {label((q, *path)): u for q, s in zip(kinds, report.solutions) for path, u in leaves(s.units)
             if isinstance(u, str)}
    checked, errors = [], []
    for entry in entries:
        try:
            checked.append(_check_one(entry, model, answers, unsolved, sampler, rule, names, units, run))
        except InputError as exc:
            errors.append(exc)
    return CheckRun(problem.file, tuple(checked), tuple(errors))


def _check_one(entry: Entry, model: Model, answers: dict, unsolved: dict, sampler: Sampler, rule: Rule,
               names: dict, units: dict, run: Allowance = Allowance(None)) -> Checked:
    head = "".join(entry.address.split()).split(".", 1)[0]
    if head in unsolved:
        return Checked(head, entry.text.strip(), Undecided(f"rbdsolve has no exact answer to '{head}' "
                                                           f"({unsolved[head]})"), "", entry.loc)
    start = Location(entry.loc.file, entry.loc.line, 1)
    address = resolve(_by_place(entry.address, answers, model, start), list(answers), start, names, answers)
    right = answers[address]
    if isinstance(right, Enum):
        return _check_word(entry, address, right)
    if isinstance(right, (Relational, sp.And, sp.Or, sp.Not)):  # an equation or a condition as the answer
        verdict = compare_relation(_read_relation(entry, model), right, sampler)
        return Checked(address, entry.text.strip(), verdict, to_unicode(right), entry.loc)
    if not isinstance(right, sp.Expr):
        what = "has no value here" if right is None else "is not an expression"
        raise InputError(f"'{address}' {what}, so it cannot be checked", entry.loc)
    given = _read(entry, model, units.get(address))
    if _a_number_for_values(given, right, model):
        verdict = _at_values(given, right, model, rule)
    else:
        verdict = compare(given, right, sampler.within(existence(address, answers)), _is_angle(address, model), run)
    return Checked(address, entry.text.strip(), verdict, to_unicode(right), entry.loc)


def existence(address: str, answers: dict) -> list[sp.Basic]:
    """The conditions under which the answer at ``address`` exists: the ``exists_when``
    of each record that holds it (an equilibrium, a steady motion's branch), not the
    answer's own (a condition asked for is compared on both sides of it)."""
    parts = address.split(".")
    found = [answers.get(".".join([*parts[:k], "exists_when"])) for k in range(1, len(parts))]
    if "solved" in parts[:-1]:  # a steady motion's one solution is its one branch too (json.md: 'solved' holds it)
        head = ".".join(parts[: parts.index("solved")])
        if f"{head}.branches[2].exists_when" not in answers:
            found.append(answers.get(f"{head}.branches[1].exists_when"))
    return [c for c in found if isinstance(c, sp.Basic) and c is not sp.true]


def _by_place(address: str, answers: dict, model: Model, loc: Location) -> str:
    """'equilibrium(theta=0, phi=pi).stability' as the address of the equilibrium at that
    place (a student knows where an equilibrium is, not where rbdsolve lists it):
    'equilibria.equilibria[3].stability'. Other addresses are returned as they are."""
    found = _PLACE.fullmatch("".join(address.split()))
    if not found:
        return address
    wanted = _place(found.group(1), model, loc)
    places: dict[str, dict[str, sp.Basic]] = {}
    for name, value in answers.items():
        at = _AT.fullmatch(name)
        if at:
            places.setdefault(at.group(1), {})[at.group(2)] = value
    matches = [k for k, at in places.items() if all(q in at and _same_place(at[q], v, q, model)
                                                   for q, v in wanted.items())]
    if len(matches) != 1:
        what = "no equilibrium is" if not matches else "more than one equilibrium is"
        raise InputError(f"{what} at {found.group(1)}; name the equilibrium by its number "
                         "(equilibrium1.stability) or give every coordinate", loc)
    rest = found.group(2)
    return f"{matches[0]}.{'at.' + rest if rest in model.symbols.coordinates else rest}"


_PLACE = re.compile(r"equilibrium\((.+)\)\.(.+)")
_AT = re.compile(r"(equilibria(?:\(\d+\))?\.equilibria\[\d+\])\.at\.(\w+)")


def _place(text: str, model: Model, loc: Location) -> dict[str, sp.Expr]:
    """'theta=0,phi=pi' as {coordinate: value}, each value read by the safe parser (numbers,
    pi, the parameters)."""
    out = {}
    values = ex.Scope(frozenset(model.symbols.parameters))
    for part in text.split(","):
        name, sep, value = part.partition("=")
        if not sep or name not in model.symbols.coordinates:
            known = ", ".join(model.symbols.coordinates)
            raise InputError(f"expected equilibrium(COORDINATE=VALUE, ...) with the coordinates {known}, "
                             f"found '{part}'", loc)
        out[name] = model.symbols.scalar(ex.parse(value, loc, values, plain=False))
    return out


def _same_place(at: object, value: sp.Expr, name: str, model: Model) -> bool:
    """The same coordinate value; for an angle, up to whole turns (−π is π)."""
    if not isinstance(at, sp.Expr):
        return False
    difference = sp.simplify(at - value)
    if model.symbols.coordinates[name] in model.angles:
        difference = sp.simplify(difference / (2 * sp.pi))
        return difference.is_integer is True
    return difference == 0


def _a_number_for_values(given: sp.Expr, right: sp.Expr, model: Model) -> bool:
    """A number given for an answer whose every parameter has a value in the file."""
    return not given.free_symbols and bool(right.free_symbols) and right.free_symbols <= set(model.values)


def _at_values(given: sp.Expr, right: sp.Expr, model: Model, rule: Rule) -> Verdict:
    """A student's number against the answer's at the file's values: the teacher's rule
    (a tolerance: the student rounds), and the slips it names."""
    ours, theirs = value_at(given, {}), value_at(right.xreplace(model.values), {})
    if ours is None or theirs is None or ours.imag or theirs.imag:
        return Undecided("the answer or yours is not a real number at the file's values")
    if rule.agrees(ours.real, theirs.real):
        return Equivalent(Proof.AT_VALUES)
    slips = slip_of(ours.real, theirs.real, rule)
    if slips:
        return Slipped(slips)
    point = tuple((to_unicode(s), f"{float(v):.6g}") for s, v in model.values.items() if s in right.free_symbols)
    return Different(point, f"{ours.real:.6g}", f"{theirs.real:.6g}")


def _check_word(entry: Entry, address: str, right: Enum) -> Checked:
    """A kind (a stability, a motion): the same word, in any case."""
    given = entry.text.strip()
    if given.lower() == right.value:
        verdict: Verdict = Equivalent(Proof.SIMPLIFIED)
    else:
        choices = ", ".join(m.value for m in type(right) if m.value != "depends")
        if given.lower() not in {m.value for m in type(right)}:
            raise InputError(f"'{given}' is not one of: {choices}", entry.loc)
        verdict = Different((), given, right.value)
    return Checked(address, given, verdict, right.value, entry.loc)


def scope(problem: Problem) -> ex.Scope:
    """The names a student's answer may use: the parameters and unknowns, the
    coordinates (θ, and their rates dot(θ), ddot(θ)), given functions of time, and t."""
    coordinates = {c.name for c in problem.coordinates}
    functions = {p.name for p in problem.prescribed}
    names = {p.name for p in problem.parameters} | set(problem.unknowns) | coordinates | functions | {"t"}
    return ex.Scope(frozenset(names), frozenset(), frozenset(coordinates | functions))


def _read(entry: Entry, model: Model, answer_unit: str | None = None) -> sp.Expr:
    """The student's expression in the model's symbols, coordinates as functions of time
    (as the answers are); a number with its unit ('4.58 rad/s', '30°') in the answer's
    unit (teaching/given_units.py)."""
    with_unit = split_unit(entry.text)
    if with_unit is not None:
        number, unit = with_unit
        factor = factor_to(unit, answer_unit)
        if factor is None:
            raise InputError(f"'{unit}' is not the unit of this answer: give it in {answer_unit}", entry.loc)
        return sp.Rational(number.replace("−", "-")) * factor
    names = scope(model.problem)
    try:
        parsed = ex.parse(entry.text, entry.loc, names)
    except InputError as exc:  # an unknown symbol with no close name: say which there are
        if exc.message.startswith("unknown symbol") and "(" not in exc.message:
            known = ", ".join(sorted(names.scalars - {"t"}, key=str.lower))
            raise InputError(f"{exc.message} (this problem's symbols are {known}, and t)", exc.location) from None
        raise
    if parsed.kind is not ex.Kind.SCALAR:
        raise InputError("give one number or expression, not a vector: check a vector's entries one by one, "
                         "e.g. 'modes.shapes[1][2] = 4/3'", entry.loc)
    return model.state.to_time(model.symbols.scalar(parsed))


def _read_relation(entry: Entry, model: Model) -> sp.Basic:
    """'cos(theta) = 2/3', 'Omega > sqrt(g/R)': each side read as an expression."""
    split = split_relation(entry.text)
    if split is None:
        raise InputError("this answer is an equation or a condition: give one, e.g. 'cos(theta) = 2/3' or "
                         "'Omega > sqrt(g/R)'", entry.loc)
    left, op, right = split
    sides = [_read(Entry(entry.address, text, entry.loc.shifted(shift)), model)
             for text, shift in ((left, 0), (right, len(left) + len(op)))]
    return relation(sides[0], op, sides[1])


def _is_angle(address: str, model: Model) -> bool:
    """An equilibrium's or a mode's coordinate that is an angle: equal up to whole turns."""
    parts = address.split(".")
    if len(parts) < 2 or parts[-2] not in ("at", "about"):
        return False
    q = model.symbols.coordinates.get(parts[-1])
    return q is not None and q in model.angles


def _sampler(model: Model) -> Sampler:
    """Points that satisfy the model's assumptions; parameters positive where declared."""
    parameters = tuple(model.symbols.parameters.values())
    names = {s: to_unicode(s) for s in parameters}
    names |= {q: to_unicode(sp.Symbol(n)) for n, q in model.symbols.coordinates.items()}

    # The assumptions' own symbols are drawn after the answer's, in name order: drawn in
    # a set's iteration order (the hash seed's), they took other values, so another
    # point was admissible first and a wrong answer was shown "different at" another point.
    assumed = sorted({s for a in model.assumptions for s in a.difference.free_symbols}, key=sp.default_sort_key)

    # An angle coordinate's value (θ(t), a plain symbol in compare._plain) is drawn in
    # (−π, π], where the solution lists it: "different at θ = −7" named a point no reader
    # would look at.
    angles = {f"{n}(t)" for n, q in model.symbols.coordinates.items() if q in model.angles}
    # A parameter the file gives a range (values: {r: [0.2, 0.8]}, drawn per variant) is
    # drawn inside it: a point outside says nothing of the exam's answer.
    ranged = {model.symbols.parameters[r.name]: (_exact(r.low), _exact(r.high)) for r in model.problem.ranges
              if r.name in model.symbols.parameters}
    # A parameter the file gives in degrees (a release angle φ₀ = 30 deg) is drawn in the
    # quadrant of its value: at φ₀ = 4 rad the key's |cos φ₀| is −cos φ₀, and a right
    # answer was marked wrong at a release no exam means.
    values = dict(model.values)
    ranged = {s: _quadrant(values[s]) for n in model.problem.angle_values()
              if (s := model.symbols.parameters.get(n)) is not None and s in values} | ranged

    def draw(symbols, rng: random.Random, nice: bool) -> dict | None:
        wanted = list(dict.fromkeys([*symbols, *assumed]))
        turning = {s: (-sp.pi, sp.pi) for s in wanted if getattr(s, "name", "") in angles}
        spans = turning | {s: ranged[s] for s in wanted if s in ranged}
        if not nice:
            return admissible_sample(model.assumptions, model.symbols, rng, symbols=wanted, tries=200, ranges=spans)
        for _ in range(50):
            point = {s: _nice(s, rng, spans.get(s), s in turning) for s in wanted}
            if admissible_sample(model.assumptions, model.symbols, rng, fixed=point, symbols=[], tries=1):
                return point
        return None

    return Sampler(draw, names, parameters)


def _nice(s: sp.Symbol, rng: random.Random, span: tuple | None, turning: bool) -> sp.Expr:
    """A value a student evaluates by hand: a small whole number (±1..3 for an angle,
    1..9 else, positive where declared so), inside the parameter's range where it has
    one (its middle where no whole number is)."""
    if span is not None and not turning:
        low, high = span
        whole = list(range(int(sp.ceiling(low)), int(sp.floor(high)) + 1))
        return sp.Integer(rng.choice(whole)) if whole else (low + high) / 2
    size = sp.Integer(rng.randint(1, 3 if turning else 9))
    return size if s.is_positive or rng.random() < 0.5 else -size


def _quadrant(value: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """The quarter turn (kπ/2, (k + 1)π/2) that holds an angle's value, a hundredth of it
    in from each end (the draws are closed intervals: 0 is no release angle of (0°, 90°));
    where the value is a whole number of quarter turns (0°, 90°), the one that begins
    there (its sines and cosines keep their signs on it)."""
    quarter = sp.pi / 2
    low = sp.floor(sp.nsimplify(value) / quarter) * quarter
    return low + quarter / 100, low + quarter * 99 / 100


def _exact(value) -> sp.Expr:
    """A range's end as an exact number: its fraction (3/10 for 30 cm), else its value."""
    return sp.Rational(value.rational) if value.rational is not None else sp.Float(value.approx, 30)
