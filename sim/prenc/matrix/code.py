# SPDX-License-Identifier: Apache-2.0
"""Matrix codes: generation, windows and the window-to-address bit order.

A matrix code of order n is a cyclic sequence of L columns; column x holds the cells
of the n tracks at angular position x. Every n x n window (n consecutive columns)
appears exactly once per turn.

Bit order (the ROM address of a window, and the RTL's):
- A column's value c is sum over tracks t = 0..n-1 of cell(t) * 2^(n-1-t): track 0
  (the outermost on a disc, the top row of the image) is the most significant bit.
- The window at position p is columns p .. p+n-1 (indices mod L); its address is
  sum over i = 0..n-1 of data(p+i) * 2^(b*(n-1-i)), where data is the column's
  b data bits: the first column is the most significant, as for the main disc.
- Plain code: b = n, data = the column, L = 2^(n*n).
- Checksum code: track n-1 carries the even parity of tracks 0..n-2 in every
  column, so b = n-1 and a column is data * 2 + parity(data). A misread of any one
  cell (of any odd number of cells in a column) breaks that column's parity and is
  detected. The price: n bits of resolution, L = 2^(n*(n-1)) positions.

The sequence of data symbols is the lexicographically least de Bruijn sequence of
order n over 2^b symbols, from the FKM algorithm (concatenating in order the Lyndon
words whose length divides n); rtl/matrix/prenc_matrix_fkm.v generates the same one.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterator, Sequence

import numpy as np

MIN_ORDER = 2
MAX_ORDER = 4  # 2^16 positions: a 64 Ki-word table; n = 5 would need 2^25 words


def check_order(n: int) -> int:
    if not isinstance(n, int) or not MIN_ORDER <= n <= MAX_ORDER:
        raise ValueError(f"matrix order n = {n!r} is out of range {MIN_ORDER}..{MAX_ORDER}")
    return n


def prenecklaces(k: int, n: int) -> Iterator[tuple[list[int], int]]:
    """Every prenecklace a[0..n-1] over k symbols in lexicographic order, with the
    length p of its longest Lyndon prefix (Ruskey's iterative FKM step).

    This is the loop rtl/matrix/prenc_matrix_fkm.v runs: find the last symbol that is not
    k-1, increment it, fill the rest periodically from the prefix."""
    a = [0] * n
    p = 1
    yield list(a), p
    while True:
        i = n - 1
        while i >= 0 and a[i] == k - 1:
            i -= 1
        if i < 0:
            return
        a[i] += 1
        for j in range(i + 1, n):
            a[j] = a[j - i - 1]
        p = i + 1
        yield list(a), p


def fkm(k: int, n: int) -> list[int]:
    """The lexicographically least de Bruijn sequence of order n over k symbols:
    the Lyndon words of length dividing n, concatenated in lexicographic order."""
    if k < 2 or n < 1:
        raise ValueError(f"a de Bruijn sequence needs k >= 2 symbols and order n >= 1 (k={k}, n={n})")
    out: list[int] = []
    for a, p in prenecklaces(k, n):
        if n % p == 0:
            out.extend(a[:p])
    return out


def parity(value: int) -> int:
    return bin(value).count("1") & 1


def windows_once(symbols: Sequence[int], n: int, k: int) -> bool:
    """True when every n-window over k symbols appears exactly once in the cyclic
    sequence (the definition, checked by counting)."""
    length = len(symbols)
    if length != k ** n:
        return False
    seen = np.zeros(k ** n, dtype=np.int64)
    ext = list(symbols) + list(symbols[: n - 1])
    for p in range(length):
        w = 0
        for i in range(n):
            w = w * k + ext[p + i]
        seen[w] += 1
    return bool(np.all(seen == 1))


@dataclass
class MatrixCode:
    """The matrix code of order n, plain or with the parity track."""

    n: int
    checksum: bool = False
    symbols: list[int] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        check_order(self.n)
        self.symbols = fkm(self.alphabet, self.n)

    @property
    def data_bits(self) -> int:
        """Data bits per column: n, or n-1 with the parity track."""
        return self.n - 1 if self.checksum else self.n

    @property
    def alphabet(self) -> int:
        return 1 << self.data_bits

    @property
    def address_bits(self) -> int:
        """Width of a window's ROM address, and of a position."""
        return self.n * self.data_bits

    @property
    def length(self) -> int:
        return 1 << self.address_bits

    def column(self, x: int) -> int:
        """The n-bit column at position x (mod L), track 0 the MSB."""
        d = self.symbols[x % self.length]
        return (d << 1) | parity(d) if self.checksum else d

    @property
    def columns(self) -> np.ndarray:
        d = np.array(self.symbols, dtype=np.int64)
        if not self.checksum:
            return d
        par = np.array([parity(v) for v in range(self.alphabet)], dtype=np.int64)
        return (d << 1) | par[d]

    def cells(self) -> np.ndarray:
        """The disc as an (n, L) array of cells: row t is track t."""
        cols = self.columns
        return np.array([(cols >> (self.n - 1 - t)) & 1 for t in range(self.n)], dtype=np.uint8)

    def address(self, p: int) -> int:
        """The ROM address of the window at position p."""
        w = 0
        for i in range(self.n):
            w = (w << self.data_bits) | self.symbols[(p + i) % self.length]
        return w

    @property
    def positions(self) -> np.ndarray:
        """The conversion table: positions[address(p)] = p for every p."""
        s = np.array(self.symbols, dtype=np.int64)
        addr = np.zeros(self.length, dtype=np.int64)
        for i in range(self.n):
            addr = (addr << self.data_bits) | np.roll(s, -i)
        table = np.full(self.length, -1, dtype=np.int64)
        table[addr] = np.arange(self.length)
        if np.any(table < 0):
            raise AssertionError("the sequence misses a window")  # fkm guarantees it
        return table

    def window_matrix(self, p: int) -> np.ndarray:
        """The n x n window at position p: rows are tracks, columns positions."""
        cells = self.cells()
        idx = [(p + i) % self.length for i in range(self.n)]
        return cells[:, idx]

    def address_of_matrix(self, matrix: np.ndarray) -> int | None:
        """The address of an n x n cell matrix, or None when a column fails its parity."""
        w = 0
        for i in range(self.n):
            col = 0
            for t in range(self.n):
                col = (col << 1) | int(matrix[t, i])
            if self.checksum:
                if parity(col):
                    return None
                col >>= 1
            w = (w << self.data_bits) | col
        return w


def build_clocks(n: int, checksum: bool = False) -> int:
    """Clocks from reset to `ready` of rtl/matrix/prenc_matrix_table.v with TABLE = "generator":
    the FKM generator emits one symbol per clock and spends one clock on each step to
    the next prenecklace (P of them, the last step finding none); N-1 closing zeros
    follow, then ready registers."""
    b = n - 1 if checksum else n
    k = 1 << b
    prenecklace_count = sum(1 for _ in prenecklaces(k, n))
    return k ** n + prenecklace_count + (n - 1) + 1


def cost(n: int) -> dict:
    """What the parity track costs at order n."""
    plain, check = MatrixCode(n).length, MatrixCode(n, checksum=True).length
    return {"n": n, "plain_positions": plain, "checksum_positions": check,
            "bits_lost": n, "plain_bits": n * n, "checksum_bits": n * (n - 1)}
