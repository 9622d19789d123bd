"""Inertia: a body's tensor about its centre of mass and about any point (parallel
axis theorem), in any axes; principal moments and axes.

    answers.py  what the question answers, both routes
    exact.py    table formulas, the parallel axis theorem, exact roots of det(λ1 − J) = 0
    numeric.py  the tensor in floats, numpy's eigh
    steps.py    the worked solution of both routes
"""
