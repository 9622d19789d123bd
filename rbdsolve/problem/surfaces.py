"""The surfaces a body rolls on (a line, a circle, another body's edge, a plane in 3D)
and what a contact's coordinate measures: the vocabulary of a scene's contacts
(problem/scene.py), which the model and the numeric search read too.
"""

from __future__ import annotations

from enum import Enum


class SurfaceKind(Enum):
    LINE = "line"  # a straight line (a floor, an incline, a string)
    CIRCLE = "circle"  # a circle (a drum, a track, a bowl in its plane)
    BODY = "body"  # an edge of another body, moving with it (a turning disk, a sliding plank)
    PLANE = "plane"  # a fixed plane in 3D (a table): rolling there is not integrable, kept as a constraint


class Measure(Enum):
    """What a contact's coordinate measures."""

    ANGLE = "angle"  # the body's turn (counterclockwise)
    ALONG = "along"  # the contact point's travel: a distance along a line, an angle round a circle


# why a rolling contact on a plane is a constraint kept, not a coordinate eliminated
NOT_INTEGRABLE = ("rolling on a plane in 3D is not integrable (non-holonomic): v_C = 0 relates the rates but no "
                  "coordinate can be eliminated")
