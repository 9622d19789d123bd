"""The model's summary: the model section every solution opens with (coordinates, T and
V term by term, with their common scale; a large model's energies as matrices), and a
model's expressions in the exam form.

A room of the model, beside what it describes (the walk from solve_file prints it
without climbing back up from the model). Used by solvers/routes/ (the report of a
whole problem), solvers/lagrange/ (moving frames) and the solver families' steps."""
