"""The floating-point routes' machinery: a model's M and K at a configuration as float
arrays, the root search of ∂V/∂q = 0 (one coordinate by a sign-change scan, several by
Newton's method over a box), the box it covers, and which equilibrium the numeric modes
take.

Used by the numeric routes of equilibria, modes, steady_motion and by the mode pictures."""
