"""Machinery several solver families share: options and routes, the time budget,
numeric values of answers, the model section of a report, the numeric model of a scene
and its root search, singular mass matrices, moving frames."""
