"""Conditions on the parameters: where a quantity changes sign, its critical values and
the sign between them (the "stable iff Ω < √(g/R)" of an exam answer), exact signs of
expressions and of a matrix's eigenvalues, exact roots where a bound proves them, every
root of a polynomial system or a refusal, and the conditions in their exam form.

Used by the families that decide stability or existence case by case (equilibria,
modes, steady_motion, steady_spin) and by the checks of routes/."""
