"""How a question is answered: the options every route receives, the choice among a
family's routes, the processor-time budget, every answer checked before it is printed,
and the labels a solution prints; ``routes.report`` solves a whole problem.

Used by solvers/__init__.py (solve_file), by every family, and by cli/, api/, teaching/."""
