"""form/stand_ins.py: a factored form does not depend on the hash seed of the run.

k (x² − 2xy + y²)/2 factors as k (x − y)²/2 or k (y − x)²/2 depending on the order of
the generators; the stand-ins for x(t) and y(t) were once made in a set's iteration
order, so PYTHONHASHSEED 0 gave one sign and 4 the other."""

from __future__ import annotations

import os
import subprocess
import sys

import sympy as sp

from rbdsolve.form.stand_ins import stand_ins

FACTORED = """
import sympy as sp
from rbdsolve.form.factor import factored
from rbdsolve.model.state import t, user_function
k = sp.Symbol("k", positive=True)
x, y = user_function("x")(t), user_function("y")(t)
print(sp.srepr(factored(k * (x**2 / 2 - x * y + y**2 / 2))))
"""


def _factored_with_seed(seed: int) -> str:
    env = {**os.environ, "PYTHONHASHSEED": str(seed)}
    return subprocess.run([sys.executable, "-c", FACTORED], env=env, capture_output=True, text=True,
                          check=True).stdout


def test_a_factored_form_is_the_same_whatever_the_hash_seed() -> None:
    assert _factored_with_seed(0) == _factored_with_seed(4)


def test_stand_ins_are_made_in_sort_order() -> None:
    x, y, z = sp.symbols("x y z")
    table, _ = stand_ins({sp.cos(z), sp.sin(x), y})
    assert list(table) == sorted(table, key=sp.default_sort_key)
    assert [d.dummy_index for d in table.values()] == sorted(d.dummy_index for d in table.values())
