"""The model's summary: the model section every solution opens with (coordinates, T and
V term by term, with their common scale; a large model's energies as matrices), and a
model's expressions in the exam form.

A room of the model, beside the energies it describes, so that printing them needs
nothing above the model. Used by solvers/routes/ (the report of a whole problem),
solvers/lagrange/ (moving frames) and the solver families' steps."""
