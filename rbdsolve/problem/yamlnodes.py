"""YAML text -> a tree of located nodes.

PyYAML's composer gives nodes with marks but builds no Python objects, so an alias
bomb is never expanded: we walk the node graph ourselves, counting what we visit.
Every scalar stays text; typing it (number, name, expression) is the schema's job,
so ``mass: 3`` and ``mass: 3*m`` go through the same expression parser.
"""

from __future__ import annotations

import bisect
import os
import re
import select
import stat
import time
from dataclasses import dataclass

import yaml

from rbdsolve.errors import InputError, Location, printable, unprintable

READ_SECONDS = 30.0  # a pipe or FIFO that sends no end of file by then is refused
MAX_FILE_BYTES = 256 * 1024
MAX_NODES = 20_000
MAX_DEPTH = 40
_UTF16_32_BOMS = (b"\xff\xfe", b"\xfe\xff", b"\x00\x00\xfe\xff")


@dataclass(frozen=True)
class Scalar:
    """A YAML scalar with its location; ``plain`` when unquoted on one line (columns in
    it map to the file), ``null`` for an empty value."""

    text: str
    loc: Location
    plain: bool  # unquoted, single line: columns inside the text map to the file
    null: bool = False

    kind_name = "a scalar"


@dataclass(frozen=True)
class Seq:
    """A YAML list with its location."""

    items: tuple[Node, ...]
    loc: Location

    kind_name = "a list"


@dataclass(frozen=True)
class Map:
    """A YAML mapping with its location, its keys kept in the file's order."""

    entries: tuple[tuple[Scalar, Node], ...]
    loc: Location

    kind_name = "a mapping"

    def keys(self) -> list[str]:
        return [k.text for k, _ in self.entries]

    def get(self, key: str) -> Node | None:
        for k, v in self.entries:
            if k.text == key:
                return v
        return None


Node = Scalar | Seq | Map


def read_bytes(path: str, limit: int = MAX_FILE_BYTES) -> bytes:
    """A file's bytes, reading no more than one byte past the size ``limit``, so a huge
    file (or /dev/zero) is refused without being read into memory. A FIFO is opened
    without waiting for its writer and read under the deadline of a pipe. A path with
    a NUL character in it names no file (FileNotFoundError, not Python's ValueError)."""
    if "\0" in path:
        raise FileNotFoundError(f"no such file: {path}")
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    with open(fd, "rb", buffering=0) as handle:
        info = os.fstat(fd)
        if stat.S_ISFIFO(info.st_mode) or stat.S_ISSOCK(info.st_mode):
            return read_stream(handle, path, limit=limit)
        os.set_blocking(fd, True)
        if info.st_size > limit:
            raise InputError(f"file is {info.st_size} bytes; the limit is {limit} bytes", Location(path, 1, 1))
        return handle.read(limit + 1)


def read_stream(stream, name: str, seconds: float | None = None, limit: int = MAX_FILE_BYTES) -> bytes:
    """At most one byte past the size ``limit`` from a pipe, a FIFO or standard input, for
    no longer than ``seconds`` (READ_SECONDS): a writer that never finishes is refused,
    not waited for. A terminal has no deadline (its user ends it with Ctrl-D or Ctrl-C);
    a stream without a file descriptor (a test's) is read up to the limit."""
    try:
        fd = stream.fileno()
    except (OSError, ValueError, AttributeError):
        return stream.read(limit + 1)
    seconds = READ_SECONDS if seconds is None else seconds
    deadline = None if os.isatty(fd) else time.monotonic() + seconds
    chunks: list[bytes] = []
    size = 0
    while size <= limit:
        if deadline is not None and not select.select([fd], [], [], max(deadline - time.monotonic(), 0))[0]:
            raise InputError(f"no end of file within {seconds:g} s: the file is read whole, and this "
                             "stream is still open (or no one writes to it)", Location(name, 1, 1))
        try:
            chunk = os.read(fd, 64 * 1024)
        except BlockingIOError:  # a FIFO whose writer has not come yet
            time.sleep(0.01)
            continue
        if not chunk:
            break
        chunks.append(chunk)
        size += len(chunk)
    return b"".join(chunks)


def read_text(path: str, data: bytes) -> str:
    """Decode a problem file, refusing what is not reasonable UTF-8 text."""
    where = Location(path, 1, 1)
    if len(data) > MAX_FILE_BYTES:  # a stream of unknown size: only the limit is known
        raise InputError(f"file is more than {MAX_FILE_BYTES} bytes; the limit is {MAX_FILE_BYTES} bytes", where)
    if data.startswith(_UTF16_32_BOMS):
        raise InputError("the file is UTF-16 or UTF-32 text; save it as UTF-8", where)
    if b"\x00" in data:
        raise InputError("this is a binary file, not a YAML problem file", where)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        col = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
        raise InputError(
            f"the file is not UTF-8 text (byte 0x{data[exc.start]:02x}); save it as UTF-8",
            Location(path, line, col),
        ) from None
    if not text.strip():
        raise InputError("the file is empty: expected a YAML mapping with a 'questions' key", where)
    return text


def parse_yaml(text: str, path: str) -> Map:
    """Compose the single YAML document in ``text`` into located nodes."""
    try:
        root = _compose(text, path)
    except yaml.MarkedYAMLError as exc:
        raise _yaml_error(exc, path, text) from None
    except yaml.reader.ReaderError as exc:  # a control character the YAML reader refuses
        raise _reader_error(exc, text, path) from None
    except yaml.YAMLError as exc:  # unmarked: rare, but say it in one line
        raise InputError(f"YAML error: {exc}", Location(path, 1, 1)) from None
    except RecursionError:
        raise InputError("the YAML is nested too deeply", Location(path, 1, 1)) from None
    if root is None:
        raise InputError("the file holds no YAML document", Location(path, 1, 1))
    tree = _Converter(path, Lines(text)).convert(root, (), 0)
    if not isinstance(tree, Map):
        raise InputError(
            f"expected a mapping at the top of the file, found {tree.kind_name}", tree.loc
        )
    return tree


class _Shallow:
    """PyYAML's composer recurses once per level: stop at MAX_DEPTH levels, before a
    10,000-deep '[[[[…' spends seconds reaching Python's recursion limit."""

    depth = 0
    path = ""

    def compose_node(self, parent, index):
        self.depth += 1
        try:
            if self.depth > MAX_DEPTH + 1:
                mark = self.peek_event().start_mark
                raise InputError(f"nesting deeper than {MAX_DEPTH} levels",
                                 Location(self.path, mark.line + 1, mark.column + 1))
            return super().compose_node(parent, index)
        finally:
            self.depth -= 1


class _ShallowLoader(_Shallow, yaml.SafeLoader):
    """PyYAML in Python throughout: its errors are the ones reported."""


_CParser = getattr(yaml, "_yaml", None) and yaml._yaml.CParser  # libyaml, where PyYAML was built with it


class _FastLoader(_Shallow, yaml.composer.Composer, *((_CParser,) if _CParser else ()),
                  yaml.constructor.SafeConstructor, yaml.resolver.Resolver):
    """libyaml's scanner and parser (C) under PyYAML's composer (Python, the same nodes
    and marks, line and column counted in characters alike): a few times faster on a
    long file. Used for files that parse; any error is found again by _ShallowLoader,
    whose messages the reports show."""

    def __init__(self, stream: str):
        _CParser.__init__(self, stream)
        yaml.composer.Composer.__init__(self)
        yaml.constructor.SafeConstructor.__init__(self)
        yaml.resolver.Resolver.__init__(self)

    def compose_scalar_node(self, anchor):
        node = super().compose_scalar_node(anchor)
        if node.style == "":  # libyaml's plain style; PyYAML's is None
            node.style = None
        return node


def _compose(text: str, path: str) -> yaml.Node | None:
    if _CParser:
        try:
            return _compose_with(_FastLoader, text, path)
        except Exception:  # noqa: BLE001 - bad YAML of any kind: the Python loader says what, as always
            pass
    return _compose_with(_ShallowLoader, text, path)


def _compose_with(loader_class, text: str, path: str) -> yaml.Node | None:
    loader = loader_class(text)
    loader.path = path
    try:
        return loader.get_single_node()
    finally:
        loader.dispose()


def _yaml_error(exc: yaml.MarkedYAMLError, path: str, text: str = "") -> InputError:
    lines = Lines(text)
    unclosed = _unclosed_bracket(exc, text, lines, path)
    if unclosed is not None:
        return unclosed
    mark = exc.problem_mark or exc.context_mark
    loc = lines.at(path, mark) if mark else Location(path, 1, 1)
    problem = exc.problem or "invalid YAML"
    if "'\\t'" in problem or "tab" in problem.lower():
        problem = "a tab character: YAML indents with spaces only"
    else:
        problem = f"YAML syntax error: {printable(problem)}"
        if exc.context:
            problem += f" ({printable(exc.context)})"
        problem += (_bracket_hint(text, loc.line - 1) or _colon_hint(exc, text, loc.line - 1)
                    or _flow_bracket_hint(exc, text, loc))
    return InputError(problem, loc)


_FLOW = {"while parsing a flow sequence": "[", "while parsing a flow mapping": "{"}


def _unclosed_bracket(exc: yaml.MarkedYAMLError, text: str, lines: Lines, path: str) -> InputError | None:
    """A '[' or '{' left open is said where it opens: PyYAML notices only at the next
    line's key or at the end of the file (an unclosed '[' on line 1 would read as an
    error at 2:1). None where the error is on the bracket's own line, or where the
    bracket is closed further on (the error is then inside it, where PyYAML says)."""
    bracket = _FLOW.get(exc.context or "")
    if bracket is None or exc.problem_mark is None or exc.context_mark is None:
        return None
    opened, found = lines.at(path, exc.context_mark), lines.at(path, exc.problem_mark)
    if found.line == opened.line or _closed(text, exc.context_mark.index):
        return None
    where = "the end of the file" if "<stream end>" in (exc.problem or "") else f"{found.line}:{found.column}"
    closing = "]" if bracket == "[" else "}"
    return InputError(f"YAML syntax error: this '{bracket}' is never closed: no '{closing}' before "
                      f"{where} ({printable(exc.context)})", opened)


def _closed(text: str, start: int) -> bool:
    """Whether the bracket at ``start`` has its match further on: brackets counted
    outside quotes and comments."""
    depth, quote, comment = 0, "", False
    for i in range(start, len(text)):
        ch = text[i]
        if comment:
            comment = ch not in "\r\n"
        elif quote:
            quote = "" if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (i == 0 or text[i - 1] in " \t"):
            comment = True
        elif ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
            if depth == 0:
                return True
    return False


def _bracket_hint(text: str, line: int) -> str:
    """YAML reads a value that starts with '[' as a list, so [3, 0] + l*[…] breaks the
    file there: say to quote it."""
    lines = Lines.split(text)
    for row in (line, line - 1):
        value = lines[row].split(":", 1)[-1].strip() if 0 <= row < len(lines) else ""
        if value.startswith("[") and "]" in value and value[value.index("]") + 1:].strip():
            return f'; an expression that starts with \'[\' must be quoted: "{printable(value)}"'
    return ""


def _flow_bracket_hint(exc: yaml.MarkedYAMLError, text: str, loc: Location) -> str:
    """Inside { }, YAML ends a plain value at '[' (at: r*[cos(phi), sin(phi)]): say to
    quote the value, from its key's ': ' to the ',' or '}' after its brackets close."""
    if "got '['" not in (exc.problem or "") or "flow mapping" not in (exc.context or ""):
        return ""
    lines = Lines.split(text)
    row = lines[loc.line - 1] if 0 < loc.line <= len(lines) else ""
    start, at = row.rfind(": ", 0, loc.column - 1), loc.column - 1
    if start < 0 or row[at:at + 1] != "[":
        return ""
    depth, end = 0, at
    for end in range(at, len(row)):
        depth += {"[": 1, "(": 1, "]": -1, ")": -1}.get(row[end], 0)
        if depth == 0 and row[end] in ",}":
            break
    else:
        end = len(row)
    key = row[:start].split("{")[-1].split(",")[-1].strip()
    value = row[start + 2:end].strip()
    return f'; inside {{ }} an expression holding \'[\' must be quoted: {key}: "{printable(value)}"'


def _colon_hint(exc: yaml.MarkedYAMLError, text: str, line: int) -> str:
    """YAML reads ': ' inside a plain value as a second key (title: a rod: released):
    say to quote the value."""
    if "mapping values are not allowed" not in (exc.problem or ""):
        return ""
    lines = Lines.split(text)
    key, _, value = lines[line].partition(":") if 0 <= line < len(lines) else ("", "", "")
    if ": " not in value.strip() or value.strip()[:1] in "\"'[{":
        return ""
    return f'; a value holding ": " must be quoted: {key.strip()}: "{printable(value.strip())}"'


def _reader_error(exc: yaml.reader.ReaderError, text: str, path: str) -> InputError:
    line = text.count("\n", 0, exc.position) + 1
    column = exc.position - (text.rfind("\n", 0, exc.position) + 1) + 1
    code = exc.character if isinstance(exc.character, int) else ord(exc.character)
    return InputError(f"the control character U+{code:04X} is not allowed in a YAML file", Location(path, line, column))


class Lines:
    """Line and column as an editor shows them. PyYAML also breaks lines at U+0085,
    U+2028 and U+2029, which editors show inside a line: positions are counted here
    from the mark's character index, with \\n, \\r\\n and \\r as the only breaks."""

    _BREAK = re.compile("\r\n|\r|\n")

    def __init__(self, text: str):
        self.starts = [0] + [m.end() for m in self._BREAK.finditer(text)]

    @classmethod
    def split(cls, text: str) -> list[str]:
        return cls._BREAK.split(text)

    def at(self, path: str, mark, keypath: tuple = ()) -> Location:
        line = bisect.bisect_right(self.starts, mark.index) - 1
        return Location(path, line + 1, mark.index - self.starts[line] + 1, keypath)


# The tags PyYAML's safe resolver gives plain YAML; any other (!!python/name:…, !include)
# would be dropped or kept as text without a word, so it is refused.
_KNOWN_TAGS = {f"tag:yaml.org,2002:{name}" for name in
               ("str", "int", "float", "bool", "null", "timestamp", "seq", "map", "merge", "value")}


class _Converter:
    def __init__(self, path: str, lines: Lines):
        self.path = path
        self.lines = lines
        self.count = 0

    def convert(self, node: yaml.Node, keypath: tuple, depth: int) -> Node:
        loc = self.lines.at(self.path, node.start_mark, keypath)
        if node.tag not in _KNOWN_TAGS:
            tag = node.tag.replace("tag:yaml.org,2002:", "!!", 1)
            raise InputError(f"the YAML tag '{printable(tag)}' is not supported: a problem file is "
                             "plain YAML; remove the tag", loc)
        self.count += 1
        if self.count > MAX_NODES:
            raise InputError(
                f"the document has more than {MAX_NODES} nodes (aliases count each time "
                "they are used); refusing to expand it",
                loc,
            )
        if depth > MAX_DEPTH:
            raise InputError(f"nesting deeper than {MAX_DEPTH} levels", loc)
        if isinstance(node, yaml.ScalarNode):
            _check_printable(node.value, loc)
            one_line = node.start_mark.line == node.end_mark.line
            null = node.tag == "tag:yaml.org,2002:null" and node.style is None
            return Scalar(node.value, loc, plain=node.style is None and one_line, null=null)
        if isinstance(node, yaml.SequenceNode):
            items = tuple(
                self.convert(item, (*keypath, i), depth + 1) for i, item in enumerate(node.value)
            )
            return Seq(items, loc)
        if isinstance(node, yaml.MappingNode):
            return self._mapping(node, keypath, loc, depth)
        raise InputError("unsupported YAML node", loc)  # pragma: no cover

    def _mapping(self, node: yaml.MappingNode, keypath: tuple, loc: Location, depth: int) -> Map:
        entries: list[tuple[Scalar, Node]] = []
        seen: dict[str, Location] = {}
        for key_node, value_node in node.value:
            key = self.convert(key_node, keypath, depth + 1)
            if not isinstance(key, Scalar) or key.null:
                raise InputError("mapping keys must be plain names", key.loc)
            if key.text == "<<":
                raise InputError("YAML merge keys ('<<') are not supported", key.loc)
            key_loc = Location(self.path, key.loc.line, key.loc.column, (*keypath, key.text))
            if key.text in seen:
                first = seen[key.text]
                raise InputError(
                    f"duplicate key '{key.text}' (first defined at line {first.line})", key_loc
                )
            seen[key.text] = key_loc
            value = self.convert(value_node, (*keypath, key.text), depth + 1)
            entries.append((Scalar(key.text, key_loc, key.plain), value))
        return Map(tuple(entries), loc)


def _check_printable(text: str, loc: Location) -> None:
    """No control character in a string: the byte check before YAML catches those typed
    in the file, this one those YAML makes from escapes ("\\e]0;title\\a", "\\x85")."""
    found = unprintable(text)
    if found is not None and "\ud800" <= found <= "\udfff":
        raise InputError(f"a lone surrogate ({printable(found)}) in a string, from a YAML escape such as "
                         "\"\\ud800\": half of a character, which no text file can hold; remove it", loc)
    if found is not None:
        raise InputError(f"a control character ({printable(found)}) in a string, from a YAML escape such "
                         "as \"\\e\" or \"\\x1b\"; remove it", loc)
