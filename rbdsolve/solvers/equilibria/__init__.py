"""Equilibria: ∂V/∂q = 0 and the stability of each from the Hessian K = ∂²V/∂q∂q.

    answers.py  what the question answers, both routes
    exact.py    trigonometric polynomials solved exactly, signs decided exactly
    numeric.py  a scan for every root in one coordinate, Newton from many starts in more
    steps.py    the worked solution of both routes
"""
