"""JSON text as rbdsolve writes it everywhere (solutions, variants tables, grading runs):
strict (no NaN or Infinity), UTF-8, and nothing in it a terminal would act on.

json.dumps with ``ensure_ascii=False`` escapes the C0 controls but leaves DEL, the C1
controls (U+009B is a terminal's CSI), the bidirectional overrides, U+2028/9 and lone
surrogates raw; each is written as its ``\\uXXXX`` escape here, so the value read back is
the same and ``cat run.json`` shows only text. No sympy: a class's grading imports this.
"""

from __future__ import annotations

import json

from rbdsolve.errors import UNPRINTABLE


def strict_json(body: object, indent: int | None = None) -> str:
    """``body`` as strict JSON and a newline (a ValueError for a number that is not
    finite), every character errors.printable would escape written as \\uXXXX."""
    text = json.dumps(body, ensure_ascii=False, allow_nan=False, indent=indent)
    return UNPRINTABLE.sub(lambda m: f"\\u{ord(m.group()):04x}", text) + "\n"
