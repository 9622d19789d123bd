"""Long math lines broken where a reader expects it: before a + or − (or an = of a
chain) at the outermost bracket depth that fits, the continuation lines indented
further (a hanging indent), never inside a term such as `(8` / `R)`. A matrix too
long for a line is written a row per line, the rows aligned under the first, as a
textbook sets M(q) of an n-link chain; a row too long for its line breaks between
entries."""

from __future__ import annotations

OPERATORS = (" + ", " − ", " = ", " ⇒ ", " < ", " > ", " ≤ ", " ≥ ")
OPEN, CLOSE = "([{", ")]}"
_LONGEST_OPERATOR = max(map(len, OPERATORS))


def break_points(text: str, entries: bool = False) -> list[tuple[int, int]]:
    """(position, bracket depth) of each place a line may break: the space before an
    operator (the operator then starts the next line); with ``entries``, also the space
    after a comma (the next entry of a matrix row starts the next line)."""
    points, depth = [], 0
    for i, ch in enumerate(text):
        if ch in OPEN:
            depth += 1
        elif ch in CLOSE:
            depth = max(0, depth - 1)
        elif ch == " " and i > 0 and (any(text.startswith(op, i) for op in OPERATORS)
                                      or (entries and text[i - 1] == ",")):
            points.append((i, depth))
    return points


def wrap_math(text: str, width: int, indent: int = 4, hang: int = 8) -> list[str]:
    """``text`` as lines of at most ``width`` columns where it can be: the first line
    indented by ``indent``, the others by ``hang``; a matrix longer than a line, a row
    per line (``_rows``)."""
    if indent + len(text) <= width:
        return [" " * indent + text]
    found = _first_matrix(text)
    if found is None or indent + found[2] - found[0] <= width:  # a matrix that fits a line stays whole
        return _wrapped(text, width, indent, hang)
    column = indent + found[0] + 1  # under the first row's own "["
    if column > width // 2:  # much written before it: the matrix starts its own line, at the hang
        before = [p for p, depth in break_points(text[:found[0]]) if depth == 0 and p > 0]
        if before:
            head, tail = text[:before[-1]], text[before[-1] + 1:]
            return _wrapped(head, width, indent, hang) + wrap_math(tail, width, hang, hang)
        column = hang
    rows = _rows(text, found[1])
    lines = _wrapped(rows[0], width, indent, column + 1, entries=True)
    for row in rows[1:]:
        lines += _wrapped(row, width, column, column + 1, entries=True)
    return lines


def _rows(text: str, cuts: list[int]) -> list[str]:
    """``text`` cut after each "]," that ends a row of its first matrix (``cuts``, from
    ``_first_matrix``): ["M = m [[a, b],", "[c, d]]"]."""
    pieces, last = [], 0
    for cut in cuts:
        pieces.append(text[last:cut])
        last = cut + 1  # the space after "],"
    return [*pieces, text[last:]]


def _first_matrix(text: str) -> tuple[int, list[int], int] | None:
    """The first "[[…]]" in ``text``: where it starts, where each row but the last ends
    (after its "],"), and where it ends; None without one."""
    start = text.find("[[")
    if start < 0:
        return None
    cuts, depth = [], 0
    for i in range(start, len(text)):
        if text[i] in OPEN:
            depth += 1
        elif text[i] in CLOSE:
            depth -= 1
            if depth == 0:
                return start, cuts, i + 1
            if depth == 1 and text.startswith("], ", i):
                cuts.append(i + 2)
    return None  # unbalanced: not a matrix


def _wrapped(text: str, width: int, indent: int, hang: int, entries: bool = False) -> list[str]:
    """``text`` broken at ``_cut`` until each line fits; a term longer than a line stays
    whole (the terminal folds it)."""
    lines, rest, lead = [], text, indent
    while lead + len(rest) > width:
        cut = _cut(rest, width - lead, width - hang, entries)
        if cut is None:
            break
        lines.append(" " * lead + rest[:cut])
        rest, lead = rest[cut + 1:], hang
    lines.append(" " * lead + rest)
    return lines


def _cut(rest: str, room: int, next_room: int, entries: bool) -> int | None:
    """Where to break: the break at the least bracket depth among those that fit and
    fill at least half the line (any that fit, if none does), the furthest of them.
    Where no operator break fills half the line and what follows it would not fit the
    next line either, after a comma too (a long vector's entries); the first break
    there is if none fits; None if there is none."""
    # the breaks that fit are read from the line's room alone (and an operator's length
    # past it): reading the whole rest for every line made a long expression's wrapping
    # quadratic (a four-rod chain's accelerations: a quarter of its run in printing)
    head = rest[:room + _LONGEST_OPERATOR]
    fitting = [(p, d) for p, d in break_points(head, entries) if 0 < p <= room]
    best = _best(fitting, room)
    if not entries and not any(p >= room // 2 for p, _ in fitting) and len(rest) - (best or 0) > next_room:
        fitting += [(p, d) for p, d in break_points(head, entries=True) if 0 < p <= room and rest[p - 1] == ","]
        best = _best(fitting, room)
    if best is not None:
        return best
    later = [p for p, _ in break_points(rest, entries) if p > 0]
    return later[0] if later else None


def _best(fitting: list[tuple[int, int]], room: int) -> int | None:
    """The furthest of the least deep breaks that fill half the line (of all, if none
    does); None if none fits."""
    if not fitting:
        return None
    fitting = [(p, d) for p, d in fitting if p >= room // 2] or fitting
    least = min(d for _, d in fitting)
    return max(p for p, d in fitting if d == least)
