"""The Python API given hostile input (issue 39, item 5): every bad input raises
rbdsolve's own InputError (exit code 2), with the message the command line would give,
never a ValueError, TypeError or AttributeError of Python's; a dict and a string are
held to a file's limits, and refused as fast."""

from __future__ import annotations

import time
from fractions import Fraction

import pytest
import sympy as sp
import yaml

import rbdsolve

from conftest import ROOT

PENDULUM = ROOT / "problems" / "examples" / "pendulum.yaml"
TEXT = PENDULUM.read_text(encoding="utf-8")
DATA = yaml.safe_load(TEXT)
BIG = 10**5000  # Python refuses to write an integer of more than 4,300 digits: str() is a ValueError


@pytest.mark.parametrize("call, message", [
    (lambda: rbdsolve.load("p\x00.yaml"), r"^no such file: p\\x00.yaml$"),
    (lambda: rbdsolve.load_dict({**DATA, "values": {"m": BIG}}),
     r"^<dict>:1:1: values.m: the number is too large \(the limit is 1e300\)$"),
    (lambda: rbdsolve.load_dict({**DATA, "values": {"m": Fraction(1, BIG)}}), r"values.m: the number is too large"),
    (lambda: rbdsolve.load_dict({**DATA, "parameters": {BIG: "mass"}}), r"^<dict>:1:1: parameters: the number is too large"),
    (lambda: rbdsolve.solve(PENDULUM, values={"m": BIG}), r"^values\['m'\]: the number is too large"),
    (lambda: rbdsolve.solve(PENDULUM, values={"m": sp.Integer(BIG)}), r"^values\['m'\]: the number is too large"),
    (lambda: rbdsolve.loads(TEXT, name=12345), r"^name: expected text .*, found int 12345$"),
    (lambda: rbdsolve.load_dict(DATA, name=None), r"^name: expected text .*, found NoneType None$"),
    (lambda: rbdsolve.solve(PENDULUM, values={1: 1}), r"^values: a parameter's name is text, found int 1$"),
    (lambda: rbdsolve.solve(PENDULUM, values=[("m", 1)]), r"^values: expected a mapping of parameter names"),
    (lambda: rbdsolve.solve(PENDULUM, values="m=1"), r"^values: expected a mapping"),
    (lambda: rbdsolve.load_dict({**DATA, "title": "a\ud800b"}),
     r"^<dict>:1:8: title: a lone surrogate \(\\ud800\) in a string"),
    (lambda: rbdsolve.loads(TEXT.replace("title: ", "title: \ud800", 1)),
     r"^<string>:1:8: a lone surrogate \(\\ud800\) in the text"),
    (lambda: rbdsolve.loads('title: "\\ud800"\n' + TEXT.split("\n", 1)[1]),
     r"^<string>:1:8: title: a lone surrogate \(\\ud800\) in a string"),
    (lambda: rbdsolve.solve(PENDULUM, values={"l": "1e300 ly"}), r"^values\['l'\]: the number 1e300 ly is too large"),
])
def test_bad_input_is_an_input_error(call, message: str) -> None:
    with pytest.raises(rbdsolve.InputError, match=message) as caught:
        call()
    assert caught.value.exit_code == 2


@pytest.mark.parametrize("call", [
    lambda: rbdsolve.loads("title: " + "a" * 5_000_000 + "\n" + TEXT.split("\n", 1)[1]),
    lambda: rbdsolve.load_dict({**DATA, "title": "a" * 5_000_000}),
    lambda: rbdsolve.load_dict({**DATA, "statement": ["x"] * 1_000_000}),
])
def test_a_dict_or_a_string_past_a_files_limits_is_refused_fast(call) -> None:
    start = time.process_time()
    with pytest.raises(rbdsolve.InputError, match="the limit"):
        call()
    assert time.process_time() - start < 0.5  # 6.3 s before: the dict was written out as YAML first


def test_a_lone_surrogate_in_a_problem_file_is_refused_where_it_is(tmp_path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text('title: "a\\udc80"\n' + TEXT.split("\n", 1)[1], encoding="utf-8")
    with pytest.raises(rbdsolve.InputError, match=r":1:8: title: a lone surrogate \(\\udc80\)"):
        rbdsolve.load(path)
