"""The model's summary: the model section every solution opens with (coordinates, T and
V term by term, with their common scale, arranged by ``Model.reading``; a large model's
energies as matrices), the section a question asked in a moving frame
opens with (``frame.py``), and what the scene itself makes doubtful (a body that swings
without an angle, a parameter used nowhere: ``scene.py``).

A room of the model, beside the energies it describes, so that printing them needs
nothing above the model. Used by solvers/routes/ (the report of a whole problem, the
scene's warnings on each question), solvers/lagrange/ (a question in a moving frame)
and the solver families' steps."""
