"""docs/api.md's examples run as written (doctest), from the repository's root."""

from __future__ import annotations

import doctest

from conftest import ROOT


def test_every_example_in_the_api_manual_runs(monkeypatch) -> None:
    monkeypatch.chdir(ROOT)
    outcome = doctest.testfile(str(ROOT / "docs" / "api.md"), module_relative=False,
                               optionflags=doctest.ELLIPSIS, raise_on_error=False, verbose=False)
    assert outcome.attempted >= 15  # the manual's examples were found, not skipped
    assert outcome.failed == 0, f"{outcome.failed} of docs/api.md's examples failed (printed above)"
