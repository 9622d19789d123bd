"""Values as exams write them: exact constants and quantities with units, in SI.

    values: {theta0: pi/6, k: 2/3, r: 30 cm, m: 200 g, Omega: 1200 rev/min, g: 9.81 m/s^2}

A value is a constant expression (numbers, ``pi``, the functions of ``problem.expr``,
no names), read by rbdsolve's own parser, optionally followed by a unit. The unit is
read here too (names, ``*``, ``·``, a space, ``/``, ``^`` or ``**`` and an integer):
only single unit names go to pint, for their factor to SI and their dimension, and
pint is imported only when a unit other than the common ones (``_KNOWN``: pint's own
definitions of m, cm, kg, deg, rev, N, …, built in) is present (start-up time). Factors are exact:
pint's decimal definitions are kept as fractions (cm = 1/100 m), and a factor that
is a rational multiple of π (deg = π/180 rad, rev/min = π/30 rad/s) is written with
``pi``, so ``45 deg`` is π/4 and ``30 cm`` is 3/10.

A :class:`Dimension` is the exponents of mass, length and time; an angle is a pure
number (radians), as in SI.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

from rbdsolve.errors import InputError, Location, did_you_mean
from rbdsolve.problem import expr as ex

_SUPERSCRIPTS = str.maketrans("-0123456789/", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹ᐟ")


@dataclass(frozen=True)
class Dimension:
    """Exponents of mass (kg), length (m) and time (s): force is (1, 1, -2)."""

    mass: Fraction = Fraction(0)
    length: Fraction = Fraction(0)
    time: Fraction = Fraction(0)

    def __mul__(self, other: Dimension) -> Dimension:
        return Dimension(self.mass + other.mass, self.length + other.length, self.time + other.time)

    def __truediv__(self, other: Dimension) -> Dimension:
        return self * other ** -1

    def __pow__(self, n) -> Dimension:
        n = Fraction(n)
        return Dimension(self.mass * n, self.length * n, self.time * n)

    @property
    def unit(self) -> str:
        """The SI unit: rad/s for a rate (in rigid body dynamics, an angular one), N·s
        for an impulse, J, kg·m²; otherwise its base units (kg·m/s³); '' for a number."""
        named = _NAMED.get((self.mass, self.length, self.time))
        if named is not None:
            return named
        up = [_power(u, e) for u, e in zip(("kg", "m", "s"), self.exponents) if e > 0]
        down = [_power(u, -e) for u, e in zip(("kg", "m", "s"), self.exponents) if e < 0]
        return ("·".join(up) or "1") + ("/" + "·".join(down) if down else "")

    @property
    def exponents(self) -> tuple[Fraction, Fraction, Fraction]:
        return (self.mass, self.length, self.time)

    def describe(self) -> str:
        """'a length', 'a mass', 'a pure number (or an angle)', 'a quantity in N·s'."""
        return _WORDS.get(self.exponents, f"a quantity in {self.unit}")


def _power(unit: str, e: Fraction) -> str:
    return unit if e == 1 else unit + str(e).translate(_SUPERSCRIPTS)


def _d(m: int, l: int, t: int) -> tuple[Fraction, Fraction, Fraction]:
    return (Fraction(m), Fraction(l), Fraction(t))


_NAMED = {_d(0, 0, 0): "", _d(0, 0, -1): "rad/s", _d(0, 0, -2): "1/s²", _d(1, 1, -1): "N·s",
          _d(1, 1, -2): "N", _d(1, 2, -2): "J", _d(1, 2, 0): "kg·m²", _d(1, 2, -1): "kg·m²/s",
          _d(1, 0, -2): "N/m", _d(0, 1, -1): "m/s", _d(0, 1, -2): "m/s²"}  # fmt: skip
_WORDS = {_d(0, 0, 0): "a pure number (or an angle)", _d(1, 0, 0): "a mass", _d(0, 1, 0): "a length",
          _d(0, 0, 1): "a time", _d(0, 1, -2): "an acceleration", _d(0, 1, -1): "a speed",
          _d(0, 0, -1): "a rate (1/s)", _d(1, 1, -2): "a force", _d(1, 2, 0): "a moment of inertia",
          _d(1, 0, -2): "a stiffness (N/m)", _d(1, 2, -2): "an energy or a torque"}  # fmt: skip
MASS, LENGTH, ACCELERATION, NUMBER = Dimension(mass=Fraction(1)), Dimension(length=Fraction(1)), \
    Dimension(length=Fraction(1), time=Fraction(-2)), Dimension()


@dataclass(frozen=True)
class Unit:
    """A unit as written (``rev/min``): its exact factor to SI and its dimension;
    ``angle``: written in angle units alone (``30 deg``, ``2 rev``), so the value is an
    angle, whose degrees the parameter values beside the answers show."""

    text: str
    factor: ex.Tree
    dimension: Dimension
    angle: bool = False


@dataclass(frozen=True)
class Value:
    """An exact real constant (a tree of numbers, ``pi`` and functions), in SI units.

    ``dimension`` is None for a plain number (the file says nothing of its dimension);
    ``approx`` is its floating-point value, for comparisons and tables; ``angle``: given
    in an angle unit (``30 deg``: ``Unit.angle``)."""

    tree: ex.Tree
    text: str
    approx: float
    dimension: Dimension | None = None
    angle: bool = False

    def __float__(self) -> float:
        return self.approx

    @property
    def rational(self) -> Fraction | None:
        """The value as a fraction where it is one (``30 cm``: 3/10), else None (π/6)."""
        return ex.constant_value(self.tree)

    def step(self, k: int, step: Value) -> Value:
        """self + k·step, exactly (a grid of exam values such as π/12 + k·π/12)."""
        tree = ex.BinOp("+", self.tree, ex.BinOp("*", ex.Num(Fraction(k)), step.tree)) if k else self.tree
        return Value(tree, f"{self.text} + {k}·({step.text})", self.approx + k * step.approx, self.dimension,
                     self.angle)


def number_value(x: Fraction | int) -> Value:
    """A plain number as a :class:`Value` (a value drawn in code, a filler of 1)."""
    x = Fraction(x)
    return Value(ex.Num(x), str(x), float(x))


def parse_value(text: str, loc: Location, plain: bool = True, unit: Unit | None = None) -> Value:
    """A value as written: ``9.81``, ``pi/6``, ``sqrt(2)``, ``30 cm``, ``1200 rev/min``.

    A bare number takes ``unit`` (a parameter's declared unit) when there is one. The
    number and its unit are split at the first place, from the left, where both read:
    ``1e-3 m`` is 1/1000 metre, not 1 of a unit 'e-3 m'."""
    source = text.strip()
    lead = len(text) - len(text.lstrip())
    if not source:
        raise InputError("expected a number, found nothing", loc)
    whole = _number(source, loc, plain, lead)
    if isinstance(whole, ex.Expr):
        return _value(whole.tree, source, loc, unit)
    if not whole.message.startswith("expected a number"):
        raise whole  # a number out of range, a division by zero: not a unit's doing
    unit_error = number_error = None
    for cut in _cuts(source):
        number = _number(source[:cut], loc, plain, lead)
        if not isinstance(number, ex.Expr) and number.message.startswith("expected a number"):
            continue
        try:
            written = parse_unit(source[cut:], _at(loc, plain, lead + cut), plain)
        except InputError as exc:
            unit_error = unit_error or exc
            continue
        if not isinstance(number, ex.Expr):  # '1e999 m': a unit, after a number out of range
            number_error = number_error or number
            continue
        return _value(number.tree, source, loc, written)
    raise number_error or unit_error or whole


def _number(text: str, loc: Location, plain: bool, lead: int) -> ex.Expr | InputError:
    """The constant expression ``text`` (no names but pi), or the error reading it."""
    if not text.strip():
        return InputError("expected a number, found nothing", loc)
    try:
        return ex.parse(text, _at(loc, plain, lead), ex.Scope(), plain)
    except InputError as exc:
        if "unknown symbol" in exc.message or "cannot read expression" in exc.message:
            return InputError(f"expected a number, found '{ex._clip(text.strip())}' (a value is a number "
                              "such as 9.81, pi/6 or sqrt(2), with its unit if any: 30 cm)", loc)
        return exc


def _cuts(source: str):
    """Where a unit may start: a letter (or °) after a space, a digit, '.' or ')'."""
    for i in range(1, len(source)):
        if (source[i].isalpha() or source[i] == "°") and (source[i - 1].isspace() or source[i - 1].isdigit()
                                                         or source[i - 1] in ".)"):
            yield i


def _at(loc: Location, plain: bool, offset: int) -> Location:
    return loc.shifted(offset) if plain else loc


def _value(tree: ex.Tree, text: str, loc: Location, unit: Unit | None) -> Value:
    if unit is not None:
        tree = tree if unit.factor == ex.Num(Fraction(1)) else ex.BinOp("*", tree, unit.factor)
    approx = approximate(tree)
    if (approx is None and _overflows(tree)) or (approx is not None and math.isinf(approx)) or \
            (approx is not None and abs(approx) > 1e300):
        raise InputError(f"the number {ex._clip(text)} is too large (the limit is 1e300)", loc)
    if approx is None or not math.isfinite(approx):
        raise InputError(f"'{ex._clip(text)}' is not a real number", loc)
    return Value(tree, text, approx, unit.dimension if unit is not None else None, unit is not None and unit.angle)


def _overflows(tree: ex.Tree) -> bool:
    """Does the tree's floating-point value overflow (10**400 in SI, 1e300 light years)?"""
    try:
        _approx(tree)
    except OverflowError:
        return True
    except (ValueError, ZeroDivisionError, TypeError):
        return False
    return False


_FUNCTIONS = {"sin": math.sin, "cos": math.cos, "tan": math.tan, "cot": lambda x: 1 / math.tan(x),
              "sec": lambda x: 1 / math.cos(x), "csc": lambda x: 1 / math.sin(x), "asin": math.asin,
              "acos": math.acos, "atan": math.atan, "atan2": math.atan2, "sinh": math.sinh, "cosh": math.cosh,
              "tanh": math.tanh, "exp": math.exp, "log": math.log, "sqrt": math.sqrt, "abs": abs}  # fmt: skip


def approximate(tree: ex.Tree) -> float | None:
    """A constant tree in floating point, or None where it is not a real number
    (sqrt(-1), log(0)) or names something other than ``pi``."""
    try:
        return _approx(tree)
    except (ValueError, ZeroDivisionError, OverflowError, TypeError):
        return None


def _approx(tree: ex.Tree) -> float:
    if isinstance(tree, ex.Num):
        return float(tree.value)
    if isinstance(tree, ex.Const):
        return math.pi
    if isinstance(tree, ex.Neg):
        return -_approx(tree.operand)
    if isinstance(tree, ex.BinOp):
        a, b = _approx(tree.left), _approx(tree.right)
        result = {"+": a + b, "-": a - b, "*": a * b}.get(tree.op) if tree.op in "+-*" else \
            (a / b if tree.op == "/" else a ** b)
        if isinstance(result, complex):
            raise ValueError("complex")
        return float(result)
    if isinstance(tree, ex.Call):
        return float(_FUNCTIONS[tree.func](*(_approx(a) for a in tree.args)))
    raise TypeError(f"not a constant: {tree}")


# --- units ----------------------------------------------------------------------------

_UNIT_TOKEN = re.compile(r"\s*(?:(?P<name>[^\W\d_][\w]*|°)|(?P<op>\*\*|\^|\*|·|/)|(?P<num>[+-]?\d+))")


def parse_unit(text: str, loc: Location, plain: bool = True) -> Unit:
    """``m/s^2``, ``kg*m**2``, ``N m/rad``, ``rev/min``: a product of unit names with
    integer powers; each name after '/' divides."""
    factor, dimension, pi_power, names = Fraction(1), Dimension(), 0, []
    pos, divide, expect_name = 0, False, True
    source = text.rstrip()
    while pos < len(source):
        match = _UNIT_TOKEN.match(source, pos)
        if match is None:
            raise InputError(f"cannot read the unit '{source.strip()}' at '{source[pos:].strip()[:20]}': a unit "
                             "is unit names with * or /, and powers with ^ (m/s^2, kg*m^2)", _at(loc, plain, pos))
        start = match.start(match.lastgroup)
        if match.group("name"):
            name = match.group("name")
            power, pos = _exponent(source, match.end(), loc, plain)
            f, d, p = _named_unit(name, _at(loc, plain, start))
            names.append(name)
            sign = -power if divide else power
            factor, dimension, pi_power = factor * f ** sign, dimension * d ** sign, pi_power + p * sign
            divide, expect_name = False, False
            continue
        if match.group("op") in ("*", "·", "/") and not expect_name:
            divide, expect_name, pos = match.group("op") == "/", True, match.end()
            continue
        raise InputError(f"unexpected '{match.group().strip()}' in the unit '{source.strip()}'", _at(loc, plain, start))
    if expect_name:
        raise InputError(f"the unit '{source.strip()}' ends with an operator", _at(loc, plain, len(source)))
    tree = ex.Num(factor)
    if pi_power:
        tree = ex.BinOp("*", tree, ex.BinOp("**", ex.Const("pi"), ex.Num(Fraction(pi_power))))
    return Unit(source.strip(), tree, dimension, dimension == NUMBER and all(n in _ANGLES for n in names))


def _exponent(source: str, pos: int, loc: Location, plain: bool) -> tuple[int, int]:
    """An optional ``^n`` or ``**n`` after a unit name: (n, where reading goes on)."""
    match = re.compile(r"\s*(\^|\*\*)\s*([+-]?\d+(?:\.\d*)?|[+-]?\.\d+)").match(source, pos)
    if match is None:
        return 1, pos
    if "." in match.group(2) or len(match.group(2)) > 3:
        raise InputError(f"the power {match.group(2)} of a unit is refused: a unit's power is a whole number "
                         "from -4 to 4, not 0", _at(loc, plain, match.start(2)))
    n = int(match.group(2))
    if not 0 < abs(n) <= 4:
        raise InputError(f"the power {n} of a unit is refused (from -4 to 4, not 0)", _at(loc, plain, match.start(2)))
    return n, match.end()


_ALIASES = {"°": "degree"}
_ANGLES = frozenset({"rad", "deg", "degree", "°", "rev", "revolution"})
_BASE = {"[mass]": "mass", "[length]": "length", "[time]": "time"}
_COMMON = ("m", "cm", "mm", "km", "kg", "g", "s", "min", "h", "rad", "deg", "rev", "rpm", "N", "J", "Hz", "W")


_LENGTH, _MASS, _TIME = Dimension(length=Fraction(1)), Dimension(mass=Fraction(1)), Dimension(time=Fraction(1))
_ANGLE, _FORCE = Dimension(), Dimension(Fraction(1), Fraction(1), Fraction(-2))
# The names exams use most, as pint defines them (factor to SI with π taken out,
# dimension, power of π), so that a file in these units does not import pint, a quarter
# of a second (issue 37); tests/problem/quantities/test_known_units.py holds each to pint's.
_KNOWN: dict[str, tuple[Fraction, Dimension, int]] = {
    "m": (Fraction(1), _LENGTH, 0), "cm": (Fraction(1, 100), _LENGTH, 0), "mm": (Fraction(1, 1000), _LENGTH, 0),
    "km": (Fraction(1000), _LENGTH, 0), "kg": (Fraction(1), _MASS, 0), "g": (Fraction(1, 1000), _MASS, 0),
    "s": (Fraction(1), _TIME, 0), "ms": (Fraction(1, 1000), _TIME, 0), "min": (Fraction(60), _TIME, 0),
    "h": (Fraction(3600), _TIME, 0), "rad": (Fraction(1), _ANGLE, 0), "deg": (Fraction(1, 180), _ANGLE, 1),
    "degree": (Fraction(1, 180), _ANGLE, 1), "°": (Fraction(1, 180), _ANGLE, 1), "rev": (Fraction(2), _ANGLE, 1),
    "revolution": (Fraction(2), _ANGLE, 1), "rpm": (Fraction(1, 30), _TIME ** -1, 1),
    "N": (Fraction(1), _FORCE, 0), "J": (Fraction(1), _FORCE * _LENGTH, 0), "W": (Fraction(1), _FORCE * _LENGTH / _TIME, 0),
    "Hz": (Fraction(1), _TIME ** -1, 0),
}


def _named_unit(name: str, loc: Location) -> tuple[Fraction, Dimension, int]:
    """One unit name: its exact factor to SI (π taken out: (1/180, …, 1) for deg), its
    dimension and its power of π. Pint is asked about this single name only, and only
    for a name not among the common ones (``_KNOWN``)."""
    if name in _KNOWN:
        return _KNOWN[name]
    return _pint_named_unit(name, loc)


def _pint_named_unit(name: str, loc: Location) -> tuple[Fraction, Dimension, int]:
    """One unit name, as pint defines it."""
    found = _pint_unit(_ALIASES.get(name, name))
    if found is None:
        raise InputError(f"unknown unit '{name}'{did_you_mean(name, list(_COMMON))}", loc)
    factor, dims = found
    other = sorted(k for k in dims if k not in _BASE)
    if other:
        raise InputError(f"the unit '{name}' measures {other[0]}: a value here is in units of mass, length, "
                         "time and angle", loc)
    dimension = Dimension(**{_BASE[k]: Fraction(v) for k, v in dims.items()})
    ratio, pi_power = _exact_factor(factor)
    return ratio, dimension, pi_power


def _exact_factor(factor: Fraction) -> tuple[Fraction, int]:
    """(r, k) with factor = r·π^k: pint's decimal definitions are exact fractions; a
    factor with π in it has pint's 50-digit π in it, and dividing that out leaves a
    small fraction."""
    if factor.denominator <= 10**30:
        return factor, 0
    pi = _pint_pi()
    for k in (1, -1, 2, -2):
        ratio = factor / pi**k
        if ratio.denominator <= 10**12 and ratio.numerator <= 10**15:
            return ratio, k
    return factor, 0


@lru_cache(maxsize=1)
def _registry():
    import pint  # lazy: only files with units pay for it

    registry = pint.UnitRegistry(non_int_type=Fraction)
    registry.define("rev = revolution")
    return registry


@lru_cache(maxsize=1)
def _pint_pi() -> Fraction:
    return Fraction(_registry().Quantity(Fraction(1), "pi").to_base_units().magnitude)


@lru_cache(maxsize=256)
def _pint_unit(name: str) -> tuple[Fraction, dict[str, Fraction]] | None:
    import pint

    registry = _registry()
    try:
        registry.get_name(name)
        base = registry.Quantity(Fraction(1), name).to_base_units()
    except (pint.errors.PintError, AttributeError, ValueError, TypeError, KeyError):
        return None
    return Fraction(base.magnitude), {k: Fraction(v) for k, v in base.dimensionality.items()}
