"""The floating-point model: M(q), V(q) and its derivatives without sympy, evaluated
on jets (forward-mode automatic differentiation to second order) from the scene's own
expression trees.

Used by the numeric routes (solvers/numeric/ and the families' numeric.py)."""
