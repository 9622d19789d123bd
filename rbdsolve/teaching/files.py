"""Reading a teacher's or a student's file (answers, a variants table): whole, as UTF-8
text, under a size limit, every failure one line with exit code 2."""

from __future__ import annotations

from rbdsolve.errors import InputError, Location
from rbdsolve.problem.yamlnodes import read_bytes

MAX_BYTES = 64 * 1024 * 1024  # a variants table of 100 000 students is about 40 MB


def read_file(path: str) -> str:
    """The file's text; an InputError naming it when it is missing, a folder, too large,
    or not UTF-8 text. A FIFO or a pipe is read under the deadline of a problem file
    (problem/yamlnodes.py: no end of file within 30 s is refused, never waited for)."""
    try:
        data = read_bytes(path, MAX_BYTES)
        if len(data) > MAX_BYTES:
            raise InputError(f"{path}: the file is larger than {MAX_BYTES // 2**20} MB")
    except FileNotFoundError:
        raise InputError(f"no such file: {path}") from None
    except IsADirectoryError:
        raise InputError(f"{path} is a folder; give a file") from None
    except OSError as exc:
        raise InputError(f"cannot read {path}: {exc.strerror or exc}") from None
    if b"\x00" in data:
        raise InputError("this is a binary file, not text", Location(path, 1, 1))
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise InputError(f"the file is not UTF-8 text (byte 0x{data[exc.start]:02x}); save it as UTF-8",
                         Location(path, line, 1)) from None
