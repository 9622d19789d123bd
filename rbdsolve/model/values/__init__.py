"""Values and units: numbers from exact answers (an answers tree evaluated at the
parameter values, the check that floating-point work has every value it needs), and the
SI unit of each numeric answer from the dimensions of the problem's quantities.

A room of the model: the numbers and units of what the problem's quantities give, so
that a solver receives numbers and symbols, not unit strings. Used by model/summary/,
the solvers (routes/, the numeric routes, the checks), render/, teaching/ and cli/."""
