"""Equations of motion: Lagrange's equations d/dt(∂L/∂q̇) − ∂L/∂q = 0, in the scene's
frame and in moving frames.

    answers.py  what the question answers, both routes
    exact.py    sympy, the equations collected in q̈ and q̇
    numeric.py  float coefficients, their error measured against the same derivation in 50 digits
    steps.py    the worked solution of both routes
"""
