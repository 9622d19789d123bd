"""Lagrange's equations beyond one family: the accelerations they give and a state of
the motion to put in, the energy integral and the speed it gives, and questions asked in
a moving frame (relative equilibria and small oscillations).

Used by the eom, reactions, energy and equilibria/modes families, and by routes/."""
