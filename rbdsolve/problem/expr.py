"""Safe expressions: problem-file text -> a small typed tree, never evaluated.

The text is parsed by Python's ``ast`` and every node is checked against a whitelist:
numbers, declared names, ``+ - * / **``, unary minus, calls to a fixed set of functions,
and vector literals ``[x, y]`` / ``[x, y, z]``. Nothing here calls ``eval``, ``sympify``
or ``parse_expr``; the model layer folds the tree into sympy.

Each node knows whether it is a scalar or a vector, so ``G1 + 1`` or ``sin([1, 2])`` is
refused here, with the column of the offending piece.
"""

from __future__ import annotations

import ast
import math
import re
from dataclasses import dataclass
from enum import Enum
from fractions import Fraction

from rbdsolve.errors import InputError, Location, clipped, did_you_mean

MAX_TEXT = 2000
MAX_NODES = 400
MAX_EXPONENT = 100  # |n| for a numeric exponent; 9**9**9 is refused before anything runs
MAX_DIGITS = 40
MAX_TEN_POWER = 300  # |n| in a literal 1e±n: Fraction('1e99999999') would build the integer
# Numbers that the model folds (10**100 * 10**100, (10**100)**100) stay under this many
# bits (about 3000 digits), far below Python's 4300-digit limit for printing an integer.
MAX_NUMBER_BITS = 10_000
MAX_NUMBER_DIGITS = 3000


class Kind(Enum):
    SCALAR = "scalar"
    VECTOR = "vector"


# Scalar functions of scalars, by number of arguments.
SCALAR_FUNCTIONS: dict[str, int] = {
    "sin": 1, "cos": 1, "tan": 1, "cot": 1, "sec": 1, "csc": 1,
    "asin": 1, "acos": 1, "atan": 1, "atan2": 2,
    "sinh": 1, "cosh": 1, "tanh": 1,
    "exp": 1, "log": 1, "sqrt": 1, "abs": 1,
}  # fmt: skip
# Time derivatives of a coordinate (or of a prescribed function): dot(x) = ẋ, ddot(x) = ẍ.
DERIVATIVE_FUNCTIONS = {"dot": 1, "ddot": 2}
VECTOR_FUNCTIONS = {"cross", "inner", "norm"}
CONSTANTS = {"pi"}


# --- the tree -------------------------------------------------------------------------


@dataclass(frozen=True)
class Num:
    """A number of the expression tree, exact."""

    value: Fraction


@dataclass(frozen=True)
class Name:
    """A name of the expression tree: a parameter, coordinate, point or prescribed
    function."""

    id: str


@dataclass(frozen=True)
class Const:
    """A constant of the expression tree (pi)."""

    id: str


@dataclass(frozen=True)
class BinOp:
    """``left op right`` in the expression tree."""

    op: str  # one of + - * / **
    left: Tree
    right: Tree


@dataclass(frozen=True)
class Neg:
    """−operand in the expression tree."""

    operand: Tree


@dataclass(frozen=True)
class Call:
    """A function applied to its arguments in the expression tree (sin, sqrt, cross, …)."""

    func: str
    args: tuple[Tree, ...]


@dataclass(frozen=True)
class Derivative:
    """A coordinate's time derivative of the given order in the expression tree:
    ``dot(theta)`` (order 1), ``ddot(theta)`` (order 2)."""

    name: str
    order: int


@dataclass(frozen=True)
class Vec:
    """A vector of the expression tree, [x, y] or [x, y, z]."""

    items: tuple[Tree, ...]


Tree = Num | Name | Const | BinOp | Neg | Call | Derivative | Vec


@dataclass(frozen=True)
class Expr:
    """A parsed, type-checked expression with the place it came from."""

    tree: Tree
    kind: Kind
    text: str
    loc: Location

    def names(self) -> frozenset[str]:
        return frozenset(_names(self.tree))


def tree_names(tree: Tree):
    """Every name in ``tree`` (a generator; names may repeat)."""
    return _names(tree)


def _names(tree: Tree):
    if isinstance(tree, Name):
        yield tree.id
    elif isinstance(tree, Derivative):
        yield tree.name
    elif isinstance(tree, BinOp):
        yield from _names(tree.left)
        yield from _names(tree.right)
    elif isinstance(tree, Neg):
        yield from _names(tree.operand)
    elif isinstance(tree, (Call, Vec)):
        for item in tree.args if isinstance(tree, Call) else tree.items:
            yield from _names(item)


def constant_value(tree: Tree) -> Fraction | None:
    """The exact value of a tree built from numbers only (no names), else None."""
    if isinstance(tree, Num):
        return tree.value
    if isinstance(tree, Neg):
        inner = constant_value(tree.operand)
        return None if inner is None else -inner
    if isinstance(tree, BinOp) and tree.op in "+-*/":
        a, b = constant_value(tree.left), constant_value(tree.right)
        if a is None or b is None or (tree.op == "/" and b == 0):
            return None
        return {"+": a + b, "-": a - b, "*": a * b, "/": a / b if b else None}[tree.op]
    if isinstance(tree, BinOp) and tree.op == "**":
        base, exp = constant_value(tree.left), constant_value(tree.right)
        if base is None or exp is None or exp.denominator != 1 or (base == 0 and exp < 0):
            return None
        return base ** int(exp)
    return None


# --- parsing --------------------------------------------------------------------------


@dataclass(frozen=True)
class Scope:
    """What names an expression may use, and of what kind."""

    scalars: frozenset[str] = frozenset()
    vectors: frozenset[str] = frozenset()
    functions_of_time: frozenset[str] = frozenset()  # names dot()/ddot() accept
    refused: tuple[tuple[str, str], ...] = ()  # declared names not allowed here, and why
    later: tuple[tuple[str, str], ...] = ()  # names declared further on (a body's points), not yet usable, and why
    bare: bool = False  # the file declares no coordinates: an unknown name may be one it forgot
    max_order: int = 2  # 1: rates dot() only (velocities at an instant)
    no_rates: str = ""  # why rates are refused here, where the format has a reason to give

    def all_names(self) -> set[str]:
        return set(self.scalars) | set(self.vectors)

    def constants(self, why: str) -> Scope:
        """Only parameters (scalars other than coordinates and t): for masses, lengths,
        stiffnesses, values. Coordinates, t and points are refused with ``why``."""
        varying = (self.scalars & self.functions_of_time) | {"t"} | self.vectors
        return Scope(self.scalars - varying, frozenset(), frozenset(),
                     tuple((n, why) for n in sorted(varying & (self.all_names() | {"t"}))), bare=self.bare)


def parse(text: str, loc: Location, scope: Scope, plain: bool = True) -> Expr:
    """Parse ``text`` (found at ``loc``) into a checked :class:`Expr`.

    ``plain`` says the text sits on one line of the file, unquoted, so a column inside
    the text is a column in the file; otherwise errors point at the start of the value.
    """
    source = text.strip()
    lead = len(text) - len(text.lstrip())
    if not source:
        raise InputError("expected an expression, found nothing", loc)
    if len(source) > MAX_TEXT:
        raise InputError(f"expression is {len(source)} characters; the limit is {MAX_TEXT}", loc)
    try:
        module = ast.parse(source, mode="eval")
    except SyntaxError as exc:
        col = (exc.offset or 1) - 1
        raise InputError(f"cannot read expression '{_clip(source)}': {exc.msg}",
                         _at(loc, plain, lead + col)) from None
    except (RecursionError, MemoryError, ValueError):
        raise InputError("expression is nested too deeply", loc) from None
    checker = _Checker(source, loc, scope, plain, lead)
    try:
        tree, kind = checker.visit(module.body)
    except RecursionError:
        raise InputError("expression is nested too deeply", loc) from None
    return Expr(tree, kind, source, loc)


_clip = clipped  # the start of a long expression, for a message that stays one readable line


def _at(loc: Location, plain: bool, offset: int) -> Location:
    return loc.shifted(offset) if plain else loc


_BINOPS = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**"}


class _Checker:
    def __init__(self, source: str, loc: Location, scope: Scope, plain: bool, lead: int):
        self.source = source
        self.loc = loc
        self.scope = scope
        self.plain = plain
        self.lead = lead
        self.count = 0

    def fail(self, node: ast.AST, message: str) -> InputError:
        offset = getattr(node, "col_offset", 0) + self.lead
        return InputError(message, _at(self.loc, self.plain, offset))

    def visit(self, node: ast.AST) -> tuple[Tree, Kind]:
        self.count += 1
        if self.count > MAX_NODES:
            raise self.fail(node, f"expression has more than {MAX_NODES} parts")
        method = getattr(self, "visit_" + type(node).__name__, None)
        if method is None:
            raise self.fail(node, f"{_describe(node)} is not allowed in an expression")
        return method(node)

    def visit_Constant(self, node: ast.Constant) -> tuple[Tree, Kind]:
        value = node.value
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(node, f"{_describe(node)} is not allowed in an expression")
        text = ast.get_source_segment(self.source, node) or repr(value)
        digits = sum(ch.isdigit() for ch in text)
        if digits > MAX_DIGITS:
            raise self.fail(node, f"number with {digits} digits; the limit is {MAX_DIGITS}")
        ten_power = re.search(r"[eE]([+-]?[0-9_]+)$", text)
        if ten_power and abs(int(ten_power.group(1).replace("_", ""))) > MAX_TEN_POWER:
            raise self.fail(node, f"the number {text} is out of range (the limit is 1e±{MAX_TEN_POWER})")
        try:
            exact = Fraction(text.replace("_", ""))  # the decimal as written: 0.1 is 1/10
        except (ValueError, ZeroDivisionError):
            raise self.fail(node, f"cannot read the number '{text}'") from None
        return Num(exact), Kind.SCALAR

    def visit_Name(self, node: ast.Name) -> tuple[Tree, Kind]:
        name = node.id
        if name in CONSTANTS:
            return Const(name), Kind.SCALAR
        if name in self.scope.scalars:
            return Name(name), Kind.SCALAR
        if name in self.scope.vectors:
            return Name(name), Kind.VECTOR
        for refused, why in (*self.scope.refused, *self.scope.later):
            if name == refused:
                raise self.fail(node, f"'{name}' cannot appear here: {why}")
        if name.startswith("__"):
            raise self.fail(node, f"the name '{name}' is not allowed")
        if name in SCALAR_FUNCTIONS or name in DERIVATIVE_FUNCTIONS or name in VECTOR_FUNCTIONS:
            raise self.fail(node, f"'{name}' is a function: call it, as in {name}(...)")
        hint = did_you_mean(name, sorted(self.scope.all_names() | CONSTANTS))
        if not hint and self.scope.bare:
            hint = " (the file declares no coordinates: list them as 'coordinates: [...]')"
        raise self.fail(node, f"unknown symbol '{name}'{hint}")

    def visit_UnaryOp(self, node: ast.UnaryOp) -> tuple[Tree, Kind]:
        tree, kind = self.visit(node.operand)
        if isinstance(node.op, ast.USub):
            return Neg(tree), kind
        if isinstance(node.op, ast.UAdd):
            return tree, kind
        raise self.fail(node, f"the operator {_describe(node.op)} is not allowed")

    def visit_BinOp(self, node: ast.BinOp) -> tuple[Tree, Kind]:
        op = _BINOPS.get(type(node.op))
        if op is None:
            raise self.fail(node, f"the operator {_describe(node.op)} is not allowed")
        left, lk = self.visit(node.left)
        right, rk = self.visit(node.right)
        kind = self._combine(node, op, lk, rk)
        if op == "/" and constant_value(right) == 0:
            raise self.fail(node, "division by zero")
        if op == "**":
            self._check_power(node, left, right)
        tree = BinOp(op, left, right)
        if _number_bits(tree) > MAX_NUMBER_BITS:
            raise self.fail(node, f"the numbers in this expression grow past {MAX_NUMBER_DIGITS} digits")
        return tree, kind

    def _combine(self, node: ast.BinOp, op: str, lk: Kind, rk: Kind) -> Kind:
        V, S = Kind.VECTOR, Kind.SCALAR
        if op in "+-":
            if lk != rk:
                raise self.fail(node, f"cannot {'add' if op == '+' else 'subtract'} a vector and a scalar")
            return lk
        if op == "*":
            if lk == V and rk == V:
                raise self.fail(node, "cannot multiply two vectors: use inner(a, b) or cross(a, b)")
            return V if V in (lk, rk) else S
        if op == "/":
            if rk == V:
                raise self.fail(node, "cannot divide by a vector")
            return lk
        if lk == V or rk == V:  # **
            raise self.fail(node, "cannot raise a vector to a power, or to a vector power")
        return S

    def _check_power(self, node: ast.BinOp, base: Tree, exponent: Tree) -> None:
        value = constant_value(exponent)
        if value is not None and abs(value) > MAX_EXPONENT:
            raise self.fail(node, f"exponent {value} is too large (the limit is {MAX_EXPONENT})")
        if value is not None and value < 0 and constant_value(base) == 0:
            raise self.fail(node, "division by zero (0 to a negative power)")
        if value is None and constant_value(base) is not None and _has_power(exponent):
            raise self.fail(node, "a number raised to a power tower is refused")

    def visit_Call(self, node: ast.Call) -> tuple[Tree, Kind]:
        if not isinstance(node.func, ast.Name):
            raise self.fail(node.func, f"{_describe(node.func)} is not allowed in an expression; "
                            "only plain function names can be called, like sin(x)")
        func = node.func.id
        if func.startswith("__"):
            raise self.fail(node, f"the name '{func}' is not allowed")
        if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
            raise self.fail(node, f"{func}() takes plain arguments only")
        if func in DERIVATIVE_FUNCTIONS:
            return self._derivative(node, func)
        allowed = set(SCALAR_FUNCTIONS) | set(DERIVATIVE_FUNCTIONS) | VECTOR_FUNCTIONS
        if func not in allowed:
            hint = did_you_mean(func, sorted(allowed))
            raise self.fail(node, f"unknown function '{func}'{hint}")
        args = [self.visit(a) for a in node.args]
        trees = tuple(t for t, _ in args)
        kinds = [k for _, k in args]
        if func in VECTOR_FUNCTIONS:
            return Call(func, trees), self._vector_call(node, func, kinds)
        arity = SCALAR_FUNCTIONS[func]
        if len(args) != arity:
            raise self.fail(node, f"{func}() takes {arity} argument{'s' if arity > 1 else ''}, found {len(args)}")
        if Kind.VECTOR in kinds:
            raise self.fail(node, f"{func}() takes a scalar, found a vector")
        return Call(func, trees), Kind.SCALAR

    def _vector_call(self, node: ast.Call, func: str, kinds: list[Kind]) -> Kind:
        want = 1 if func == "norm" else 2
        if len(kinds) != want or any(k != Kind.VECTOR for k in kinds):
            raise self.fail(node, f"{func}() takes {want} vector{'s' if want > 1 else ''}")
        return Kind.VECTOR if func == "cross" else Kind.SCALAR

    def _derivative(self, node: ast.Call, func: str) -> tuple[Tree, Kind]:
        order = DERIVATIVE_FUNCTIONS[func]
        if len(node.args) != 1 or not isinstance(node.args[0], ast.Name):
            raise self.fail(node, f"{func}() takes the name of a coordinate, as in {func}(x)")
        name = node.args[0].id
        if not self.scope.functions_of_time:
            why = f": {self.scope.no_rates}" if self.scope.no_rates else ""
            raise self.fail(node, f"rates such as {func}({name}) are not allowed here{why}")
        if name not in self.scope.functions_of_time:
            known = sorted(self.scope.functions_of_time)
            hint = did_you_mean(name, known)
            what = f"; coordinates are {', '.join(known)}" if known and not hint else ""
            raise self.fail(node.args[0], f"{func}() needs a coordinate, found '{name}'{hint}{what}")
        if order > self.scope.max_order:
            raise self.fail(node, f"only rates such as dot({name}) are allowed here, not {func}({name})")
        return Derivative(name, order), Kind.SCALAR

    def visit_List(self, node: ast.List) -> tuple[Tree, Kind]:
        if len(node.elts) not in (2, 3):
            raise self.fail(node, f"a vector has 2 or 3 components, found {len(node.elts)}")
        items = []
        for elt in node.elts:
            tree, kind = self.visit(elt)
            if kind != Kind.SCALAR:
                raise self.fail(elt, "a vector's components must be scalars")
            items.append(tree)
        return Vec(tuple(items)), Kind.VECTOR

    visit_Tuple = visit_List


def _number_bits(tree: Tree) -> int:
    """An upper bound on the size in bits of the numbers sympy makes when it folds
    ``tree``: products and sums add sizes, a constant power multiplies them. Checked
    before anything folds, so 10**100**… never reaches the integer arithmetic."""
    if isinstance(tree, Num):
        return tree.value.numerator.bit_length() + tree.value.denominator.bit_length()
    if isinstance(tree, Neg):
        return _number_bits(tree.operand)
    if isinstance(tree, BinOp) and tree.op == "**":
        exponent = constant_value(tree.right)
        scale = math.ceil(abs(exponent)) if exponent is not None else 1
        return _number_bits(tree.left) * max(scale, 1) + _number_bits(tree.right)
    if isinstance(tree, BinOp):
        return _number_bits(tree.left) + _number_bits(tree.right)
    if isinstance(tree, (Call, Vec)):
        return max((_number_bits(a) for a in (tree.args if isinstance(tree, Call) else tree.items)), default=0)
    return 0


def _has_power(tree: Tree) -> bool:
    if isinstance(tree, BinOp):
        return tree.op == "**" or _has_power(tree.left) or _has_power(tree.right)
    if isinstance(tree, Neg):
        return _has_power(tree.operand)
    return False


def _describe(node: ast.AST) -> str:
    names = {
        "Attribute": "attribute access (a.b)",
        "Subscript": "indexing (a[i])",
        "Lambda": "a lambda",
        "ListComp": "a comprehension",
        "GeneratorExp": "a comprehension",
        "DictComp": "a comprehension",
        "SetComp": "a comprehension",
        "JoinedStr": "an f-string",
        "NamedExpr": "assignment (:=)",
        "Compare": "a comparison",
        "BoolOp": "'and'/'or'",
        "IfExp": "'if ... else'",
        "Dict": "a dictionary",
        "Set": "a set",
        "Starred": "unpacking (*)",
        "Await": "'await'",
        "Yield": "'yield'",
        "Mod": "'%'",
        "FloorDiv": "'//'",
        "MatMult": "'@'",
        "BitXor": "'^' (use ** for powers)",
        "BitAnd": "'&'",
        "BitOr": "'|'",
        "LShift": "'<<'",
        "RShift": "'>>'",
        "Invert": "'~'",
        "Not": "'not'",
    }
    kind = type(node).__name__
    if kind == "Constant":
        return f"the literal {ast.unparse(node)[:30]}"
    return names.get(kind, f"'{kind}'")


def _is_expression(source: str) -> bool:
    if len(source) > MAX_TEXT:
        return True  # parse() refuses it with the length limit
    try:
        ast.parse(source, mode="eval")
    except (SyntaxError, RecursionError, MemoryError, ValueError):
        return False
    return True


def is_number_text(text: str) -> bool:
    try:
        Fraction(text.strip())
    except (ValueError, ZeroDivisionError):
        return False
    return True


def parse_number(text: str, loc: Location, plain: bool = True) -> Fraction:
    """A plain numeric value (no names), e.g. a parameter's value: '9.81', '1/2', '-3'."""
    source = text.strip()
    if not _is_expression(source) or any(ch.isalpha() and ch not in "eE" for ch in source):
        # A name or a sentence ('heavy', 'nine point eight') is not a value at all.
        raise InputError(f"expected a number, found '{_clip(source)}'", loc)
    expr = parse(text, loc, Scope(), plain)
    value = constant_value(expr.tree)
    if value is None:
        raise InputError(f"expected a number, found '{_clip(source)}'", loc)
    if abs(value) > 10**300:
        raise InputError(f"the number {text.strip()} is too large (the limit is 1e300)", loc)
    return value
