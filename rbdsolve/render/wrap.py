"""Long math lines broken where a reader expects it: before a + or − (or an = of a
chain) at the outermost bracket depth that fits, the continuation lines indented
further (a hanging indent), never inside a term such as `(8` / `R)`."""

from __future__ import annotations

OPERATORS = (" + ", " − ", " = ", " ⇒ ", " < ", " > ", " ≤ ", " ≥ ")
OPEN, CLOSE = "([{", ")]}"


def break_points(text: str) -> list[tuple[int, int]]:
    """(position, bracket depth) of each place a line may break: the space before an
    operator (the operator then starts the next line)."""
    points, depth = [], 0
    for i, ch in enumerate(text):
        if ch in OPEN:
            depth += 1
        elif ch in CLOSE:
            depth = max(0, depth - 1)
        elif ch == " " and i > 0 and any(text.startswith(op, i) for op in OPERATORS):
            points.append((i, depth))
    return points


def wrap_math(text: str, width: int, indent: int = 4, hang: int = 8) -> list[str]:
    """``text`` as lines of at most ``width`` columns where it can be: the first line
    indented by ``indent``, the others by ``hang``. Each break is the one at the least
    bracket depth among those that fit and fill at least half the line (any that fit,
    if none does), the furthest of them; a term longer than a line stays whole (the
    terminal folds it)."""
    lines, rest, lead = [], text, indent
    while lead + len(rest) > width:
        room = width - lead
        fitting = [(p, d) for p, d in break_points(rest) if 0 < p <= room]
        if not fitting:
            later = [p for p, _ in break_points(rest) if p > 0]
            if not later:
                break
            cut = later[0]
        else:
            fitting = [(p, d) for p, d in fitting if p >= room // 2] or fitting
            least = min(d for _, d in fitting)
            cut = max(p for p, d in fitting if d == least)
        lines.append(" " * lead + rest[:cut])
        rest, lead = rest[cut + 1:], hang
    lines.append(" " * lead + rest)
    return lines
