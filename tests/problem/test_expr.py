"""The safe expression parser: what it accepts, what it refuses, and where it points."""

from __future__ import annotations

from fractions import Fraction

import pytest

from rbdsolve.errors import InputError, Location
from rbdsolve.problem import expr as ex

SCOPE = ex.Scope(
    scalars=frozenset({"m", "r", "g", "theta", "phi", "t"}),
    vectors=frozenset({"G1", "O"}),
    functions_of_time=frozenset({"theta", "phi"}),
)
HERE = Location("p.yaml", 3, 10, ("points", "G2"))


def parse(text: str) -> ex.Expr:
    return ex.parse(text, HERE, SCOPE)


def error(text: str) -> InputError:
    with pytest.raises(InputError) as info:
        parse(text)
    return info.value


@pytest.mark.parametrize(
    "text, kind",
    [
        ("3*m", ex.Kind.SCALAR),
        ("sqrt(3)*r", ex.Kind.SCALAR),
        ("-m*g*r*cos(theta)", ex.Kind.SCALAR),
        ("r/2 * [sin(theta), -cos(theta)]", ex.Kind.VECTOR),
        ("G1 + r/2*[sin(phi), -cos(phi), 0]", ex.Kind.VECTOR),
        ("dot(theta)**2 + ddot(phi)", ex.Kind.SCALAR),
        ("atan2(1, 2) + pi", ex.Kind.SCALAR),
        ("inner(G1, O) + norm(cross(G1, O))", ex.Kind.SCALAR),
        ("2**10", ex.Kind.SCALAR),
    ],
)
def test_accepts(text: str, kind: ex.Kind) -> None:
    assert parse(text).kind == kind


def test_decimals_are_exact() -> None:
    assert parse("0.1").tree == ex.Num(Fraction(1, 10))
    assert ex.constant_value(parse("1/3 + 1e-3").tree) == Fraction(1, 3) + Fraction(1, 1000)


def test_unknown_symbol_suggests_the_closest_name() -> None:
    err = error("3*M")
    assert "unknown symbol 'M' (did you mean 'm'?)" in err.message
    assert (err.location.line, err.location.column) == (3, 12)  # the M, two columns in
    assert err.location.key_path() == "points.G2"


@pytest.mark.parametrize(
    "text, words",
    [
        ("__import__('os').system('touch /tmp/pwned')", "not allowed"),
        ("m.__class__", "attribute access"),
        ("G1[0]", "indexing"),
        ("lambda x: x", "lambda"),
        ("[x for x in (1, 2)]", "comprehension"),
        ("f'{m}'", "f-string"),
        ("(x := 3)", "assignment"),
        ("sin(*[1])", "plain arguments"),
        ("sin(x=1)", "plain arguments"),
        ("exec('1')", "unknown function 'exec'"),
        ("eval('1')", "unknown function 'eval'"),
        ("open('/etc/passwd')", "unknown function 'open'"),
        ("__builtins__", "not allowed"),
        ("'text'", "literal"),
        ("m if g else r", "'if ... else'"),
        ("m < g", "comparison"),
        ("m ^ 2", "use ** for powers"),
        ("9**9**9", "too large"),
        ("2**1000", "too large"),
        ("1" * 60, "digits"),
        ("m +", "cannot read expression"),
        ("G1 + 1", "cannot add a vector and a scalar"),
        ("G1 * O", "cannot multiply two vectors"),
        ("sin(G1)", "takes a scalar"),
        ("[1, 2, 3, 4]", "2 or 3 components"),
        ("[G1, 1]", "components must be scalars"),
        ("dot(m)", "needs a coordinate"),
        ("sin", "is a function"),
        ("sin(1, 2)", "takes 1 argument"),
        ("x" * 3000, "limit"),
        ("(" * 300 + "1" + ")" * 300, "nested"),
        ("1j", "literal"),
    ],
)
def test_refuses(text: str, words: str) -> None:
    assert words in error(text).message


def test_nothing_runs(tmp_path) -> None:
    canary = tmp_path / "canary"
    payloads = [
        f"__import__('os').system('touch {canary}')",
        f"open('{canary}', 'w')",
        f"exec(\"open('{canary}', 'w')\")",
        "[c for c in ().__class__.__base__.__subclasses__()]",
    ]
    for payload in payloads:
        with pytest.raises(InputError):
            parse(payload)
    assert not canary.exists()


def test_parse_number() -> None:
    assert ex.parse_number("9.81", HERE) == Fraction(981, 100)
    assert ex.parse_number("-1/2", HERE) == Fraction(-1, 2)
    with pytest.raises(InputError, match="expected a number, found .m."):
        ex.parse_number("m", HERE)
