"""Values and units: numbers from exact answers (an answers tree evaluated at the
parameter values, never a complex one), the SI unit of each numeric answer from the
dimensions of the problem's quantities (and the units an answer's meaning fixes: N·m/rad,
not J/rad²), and the numeric block's lines, a value and its unit each; all of these for
one question's answers in one call (``answers.py``); the walk over an answers tree
(``tree.py``).

A room of the model: the numbers and units of what the problem's quantities give, so
that a solver receives numbers and symbols, not unit strings. Used by model/summary/,
the solvers (routes/, the numeric routes, the checks), render/, teaching/ and cli/.
Which values a route needs is the routes' to say (solvers/routes/needed.py)."""
