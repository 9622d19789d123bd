"""The common unit names rbdsolve knows without pint mean what pint says they mean:
each one's factor to SI, its dimension and its power of π, as pint's definition gives
them (the table only spares a file in these units the import of pint)."""

from __future__ import annotations

import pytest

from rbdsolve.errors import Location
from rbdsolve.problem.quantities import quantity as q


@pytest.mark.parametrize("name", sorted(q._KNOWN))
def test_a_known_unit_is_pints(name):
    assert q._KNOWN[name] == q._pint_named_unit(name, Location("test.yaml", 1, 1))


def test_a_file_in_common_units_does_not_import_pint():
    import subprocess
    import sys

    script = ("import sys; from rbdsolve.errors import Location; from rbdsolve.problem.quantities.quantity import parse_unit; "
              "loc = Location('f.yaml', 1, 1); [parse_unit(u, loc) for u in ('kg*m^2/s', 'rev/min', 'deg', 'N*m/rad', 'cm')]; "
              "print('pint' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert out.stdout.strip() == "False", out.stderr
