"""The problem file as a student writes it: top-level keys in the usual order, one
line per point, body, spring and contact (flow mappings), questions as a list."""

from __future__ import annotations

_SPECIAL = set(",[]{}:#&*!|>'\"%@`")


def scalar(v, flow: bool = True) -> str:
    """A value in YAML: numbers and plain words as they are; an expression with a comma,
    a bracket or a colon quoted (inside a flow mapping a comma would end it)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)
    s = str(v)
    if s.startswith("[") and not flow:
        return f'"{s}"'
    if flow and any(c in _SPECIAL for c in s) or s.strip() != s or s == "":
        return '"' + s.replace('"', '\\"') + '"'
    return s


def flow(v) -> str:
    """A nested value in flow style: {a: 1, b: [x, y]}."""
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {flow(x)}" for k, x in v.items()) + "}"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(flow(x) for x in v) + "]"
    return scalar(v)


def document(doc: dict, comments: dict[str, str] | None = None) -> str:
    """The file's text. ``doc`` maps each top-level key to a str (written as is after
    the key), a dict (one line per entry: name: flow) or a list (questions)."""
    lines: list[str] = []
    comments = comments or {}
    for key, value in doc.items():
        if value is None or value == {} or value == []:
            continue
        if key in comments:
            lines.append(f"# {comments[key]}")
        if key == "statement":
            lines.append("statement: >")
            lines += [f"  {x}" for x in _wrap(value)]
        elif isinstance(value, str):
            lines.append(f"{key}: {scalar(value, flow=False) if key in ('title', 'source') else value}")
        elif key == "questions":
            lines.append("questions:")
            for q in value:
                if isinstance(q, str):
                    lines.append(f"  - {q}")
                else:
                    (kind, opts), = q.items()
                    lines.append(f"  - {kind}: {flow(opts)}")
        elif isinstance(value, dict) and key in ("parameters", "values", "coordinates_map") and _short(value):
            lines.append(f"{key}: {flow(value)}")
        elif isinstance(value, dict):
            lines.append(f"{key}:")
            for name, entry in value.items():
                text = flow(entry) if isinstance(entry, (dict, list, tuple)) else scalar(entry, flow=False)
                lines.append(f"  {name}: {text}")
        else:
            lines.append(f"{key}: {flow(value)}")
    return "\n".join(lines) + "\n"


def _short(d: dict) -> bool:
    return len(flow(d)) < 88


def _wrap(text: str, width: int = 86) -> list[str]:
    words, out, line = text.split(), [], ""
    for w in words:
        if line and len(line) + 1 + len(w) > width:
            out.append(line)
            line = w
        else:
            line = f"{line} {w}" if line else w
    if line:
        out.append(line)
    return out
