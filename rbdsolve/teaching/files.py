"""Reading a teacher's or a student's file (answers, a variants table): whole, as UTF-8
text, under a size limit, every failure one line with exit code 2."""

from __future__ import annotations

import os

from rbdsolve.errors import InputError, Location

MAX_BYTES = 64 * 1024 * 1024  # a variants table of 100 000 students is about 40 MB


def read_file(path: str) -> str:
    """The file's text; an InputError naming it when it is missing, a folder, too large,
    or not UTF-8 text."""
    try:
        if os.path.getsize(path) > MAX_BYTES:
            raise InputError(f"{path}: the file is larger than {MAX_BYTES // 2**20} MB")
        with open(path, "rb") as handle:
            data = handle.read(MAX_BYTES + 1)
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
