"""Small oscillations: M = ∂²T/∂q̇², K = ∂²V/∂q² at an equilibrium, det(K − λM) = 0,
frequencies and mode shapes.

    answers.py    what the question answers, both routes
    exact.py      the characteristic polynomial over the rationals, exact roots and shapes
    numeric.py    Cholesky and the symmetric eigenproblem (numeric/dense.py), with error bounds
    spaces.py     repeated eigenvalues and clusters: mode spaces and their bounds
    amplitude.py  the linearization checked by simulating the nonlinear motion
    steps.py      the worked solution of both routes
"""
