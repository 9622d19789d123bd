"""How a question is answered: the options every route receives, the choice among a
family's routes, which values a route needs, the processor-time budget, the scene's
warnings (model/summary/scene.py) put on each question, every answer checked before it
is printed, and the labels and names a solution prints; ``routes.report`` solves a whole problem.

Used by solvers/__init__.py (solve_file), by every family, and by cli/, api/, teaching/."""
