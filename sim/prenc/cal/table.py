# SPDX-License-Identifier: Apache-2.0
"""The calibration table: where each edge of the sync track really is.

The sync track has 4 L edges (L = 2^N slots): edge x is the one a clockwise step into
quarter x crosses, nominally at x quarters (x / 4 slots). On a printed disc it sits at

    a[x] = x + c[x] / 2^FRAC  quarters,

c[x] a signed integer: the table holds c. Calibration finds the edges relative to
each other; the table's zero is the mean of the edges (the corrections sum to about
0), so the calibrated angle's zero is the disc's own average edge, as close to the
printed zero as one disc can tell.

File format (text; what Verilog's $readmemh reads, so a board can build it in):

    // prenc calibration table 1
    // n 10
    // entries 4096
    // frac 12
    // crc32 1a2b3c4d
    0012
    ffe3
    ...

- the five header lines, in this order, `//` comments to $readmemh;
- then `entries` = 4 x 2^n data lines, line x holding c[x] as a 16-bit two's
  complement hex word (4 digits): the range is +-8 quarters (+-2 slots) in steps of
  2^-12 quarter;
- crc32: zlib's CRC-32 of the data words, each as 2 bytes big-endian, in order.

`read` refuses a file that is missing, has another N than the reader's, the wrong
number of words, a word that is not 4 hex digits, or a CRC that does not match, each
with a message that names the file and what is wrong.
"""

from __future__ import annotations

import os
import tempfile
import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

FORMAT = 1
FRAC = 12              # fractional bits of a correction, in quarters
WORD_BITS = 16
LIMIT = (1 << (WORD_BITS - 1)) - 1   # |c| <= LIMIT: +-8 quarters less an LSB


class TableError(ValueError):
    """A calibration table that cannot be used: the message says why."""


def entries(n: int) -> int:
    return 4 << n


@dataclass(frozen=True)
class Table:
    """c[x] for every edge x of a disc of 2^n slots (int64 array of 4 x 2^n)."""

    n: int
    c: np.ndarray

    def __post_init__(self) -> None:
        if not 2 <= self.n <= 24:
            raise TableError(f"n = {self.n} is out of range 2..24")
        c = np.asarray(self.c)
        if c.shape != (entries(self.n),):
            raise TableError(f"a table for n = {self.n} has {entries(self.n)} corrections, "
                             f"not {c.size}")
        if c.size and int(np.max(np.abs(c))) > LIMIT:
            raise TableError(f"a correction of {int(np.max(np.abs(c)))} / 2^{FRAC} quarters "
                             f"is beyond the format's +-{LIMIT}")

    @classmethod
    def from_quarters(cls, n: int, corrections) -> "Table":
        """From corrections in quarters (floats), rounded to the format's steps."""
        c = np.rint(np.asarray(corrections, dtype=np.float64) * (1 << FRAC)).astype(np.int64)
        return cls(n, c)

    @classmethod
    def zero(cls, n: int) -> "Table":
        return cls(n, np.zeros(entries(n), dtype=np.int64))

    @property
    def quarters(self) -> np.ndarray:
        """c[x] in quarters."""
        return np.asarray(self.c, dtype=np.float64) / (1 << FRAC)

    def words(self) -> np.ndarray:
        """The 16-bit words of the file (two's complement)."""
        return (np.asarray(self.c, dtype=np.int64) & 0xFFFF).astype(np.uint16)

    def crc32(self) -> int:
        return zlib.crc32(self.words().astype(">u2").tobytes()) & 0xFFFFFFFF

    def text(self) -> str:
        head = [f"// prenc calibration table {FORMAT}", f"// n {self.n}",
                f"// entries {entries(self.n)}", f"// frac {FRAC}", f"// crc32 {self.crc32():08x}"]
        body = np.char.mod("%04x", self.words())
        return "\n".join(head + body.tolist()) + "\n"

    def write(self, path: str | os.PathLike) -> Path:
        """Write the file (to a temporary file beside it, then renamed into place)."""
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
        try:
            with os.fdopen(fd, "w") as f:
                f.write(self.text())
            os.replace(tmp, path)
        except BaseException:
            os.unlink(tmp)
            raise
        return path


def parse(text: str, name: str = "the table", n: int | None = None) -> Table:
    """A table from a file's text; `n`, when given, is the reader's N, which it must match."""
    lines = text.splitlines()
    keys = [("prenc calibration table", str(FORMAT)), ("n", None), ("entries", None),
            ("frac", str(FRAC)), ("crc32", None)]
    header: dict[str, str] = {}
    for i, (key, expect) in enumerate(keys):
        line = lines[i].strip() if i < len(lines) else ""
        if not line.startswith("//") or not line[2:].strip().startswith(key + " "):
            raise TableError(f"{name}: line {i + 1} should be '// {key} ...': "
                             "this is not a prenc calibration table")
        value = line[2:].strip()[len(key):].strip()
        if expect is not None and value != expect:
            raise TableError(f"{name}: '{key}' is {value}, this reader reads {expect}")
        header[key] = value
    try:
        table_n = int(header["n"])
        count = int(header["entries"])
        crc = int(header["crc32"], 16)
    except ValueError as exc:
        raise TableError(f"{name}: a header value is not a number ({exc})") from None
    if n is not None and table_n != n:
        raise TableError(f"{name} is for a disc of N = {table_n}, the reader has N = {n}")
    if not 2 <= table_n <= 24 or count != entries(table_n):
        raise TableError(f"{name}: N = {table_n} needs {entries(table_n)} entries, "
                         f"the header says {count}")
    data = [line.strip() for line in lines[len(keys):] if line.strip()]
    if len(data) != count:
        raise TableError(f"{name} has {len(data)} corrections, N = {table_n} needs {count}")
    words = np.zeros(count, dtype=np.int64)
    for i, word in enumerate(data):
        if len(word) != 4:
            raise TableError(f"{name}, data line {i + 1}: '{word}' is not a 4-digit hex word")
        try:
            words[i] = int(word, 16)
        except ValueError:
            raise TableError(f"{name}, data line {i + 1}: '{word}' is not hex") from None
    c = np.where(words >= 1 << 15, words - (1 << 16), words)
    table = Table(table_n, c)
    if table.crc32() != crc:
        raise TableError(f"{name}: the CRC is {table.crc32():08x}, the header says {crc:08x}: "
                         "the file is corrupt")
    return table


def read(path: str | os.PathLike, n: int | None = None) -> Table:
    """Read and check a table file (see `parse`)."""
    path = Path(path)
    if not path.is_file():
        raise TableError(f"calibration table {path}: no such file")
    return parse(path.read_text(), name=f"calibration table {path}", n=n)
