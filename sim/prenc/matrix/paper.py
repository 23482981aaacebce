# SPDX-License-Identifier: Apache-2.0
"""The paper's 16-position example (n = 2), checked against Definition 3.

The paper lists the Hamiltonian cycle
    B1, B5, B9, B2, B3, B6, B15, B13, B10, B4, B8, B12, B7, B14, B16, B11, B1
of its graph G on the sixteen 2 x 2 matrices B1..B16. Which matrix B_i is depends on
how the matrices are numbered, so every plausible numbering is tried: B_i is the
matrix whose four cells, read in a given order, spell i - 1 in binary.

For each numbering, `check_cycle` reports whether the list visits all sixteen
matrices once and whether each step is an arc of G (Definition 3: the second column
of one matrix is the first column of the next). `table_one` turns a valid cycle into
the disc it describes: the two tracks, and for each position the window and its
angular sector (Table I of the paper).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

PAPER_CYCLE = (1, 5, 9, 2, 3, 6, 15, 13, 10, 4, 8, 12, 7, 14, 16, 11, 1)

# Reading orders of the cells (row, column) of a 2 x 2 matrix, most significant first.
NUMBERINGS = {
    "row-major, MSB first": ((0, 0), (0, 1), (1, 0), (1, 1)),
    "row-major, LSB first": ((1, 1), (1, 0), (0, 1), (0, 0)),
    "column-major, MSB first": ((0, 0), (1, 0), (0, 1), (1, 1)),
    "column-major, LSB first": ((1, 1), (0, 1), (1, 0), (0, 0)),
}


def matrix_of(number: int, numbering: str) -> np.ndarray:
    """B_number as a 2 x 2 array (rows are tracks, columns are positions)."""
    m = np.zeros((2, 2), dtype=np.uint8)
    value = number - 1
    for i, (r, c) in enumerate(NUMBERINGS[numbering]):
        m[r, c] = (value >> (3 - i)) & 1
    return m


def number_of(matrix: np.ndarray, numbering: str) -> int:
    value = 0
    for r, c in NUMBERINGS[numbering]:
        value = (value << 1) | int(matrix[r, c])
    return value + 1


def is_arc(a: np.ndarray, b: np.ndarray) -> bool:
    """Definition 3: A -> B when columns 2..n of A are columns 1..n-1 of B."""
    return bool(np.array_equal(a[:, 1:], b[:, :-1]))


def adjacency(numbering: str) -> np.ndarray:
    """G's 16 x 16 adjacency matrix in the paper's B-numbering (row i, column j:
    1 when B_(i+1) -> B_(j+1))."""
    mats = [matrix_of(i, numbering) for i in range(1, 17)]
    return np.array([[int(is_arc(a, b)) for b in mats] for a in mats], dtype=np.uint8)


@dataclass
class CycleCheck:
    numbering: str
    visits_each_once: bool
    closed: bool
    bad_steps: list[tuple[int, int]]  # (B_i, B_j) pairs that are not arcs

    @property
    def holds(self) -> bool:
        return self.visits_each_once and self.closed and not self.bad_steps


def check_cycle(cycle=PAPER_CYCLE, numbering: str = "row-major, MSB first") -> CycleCheck:
    body = list(cycle[:-1])
    closed = cycle[0] == cycle[-1]
    once = sorted(body) == list(range(1, 17))
    bad = [(a, b) for a, b in zip(cycle, cycle[1:])
           if not is_arc(matrix_of(a, numbering), matrix_of(b, numbering))]
    return CycleCheck(numbering, once, closed, bad)


def tracks_of_cycle(cycle, numbering: str) -> np.ndarray:
    """The two tracks (2 x 16 cells) of the disc whose window at position p is the
    cycle's p-th matrix: column p is the first column of that matrix."""
    body = cycle[:-1] if cycle[0] == cycle[-1] else cycle
    return np.array([matrix_of(b, numbering)[:, 0] for b in body], dtype=np.uint8).T


@dataclass
class Row:
    position: int
    matrix: str  # "ab/cd": track 0 cells, then track 1 cells
    number: int  # B_i
    angle_from: float  # degrees
    angle_to: float


def table_one(cycle=PAPER_CYCLE, numbering: str = "row-major, MSB first") -> list[Row]:
    """Table I: for each of the 16 positions the window the sensor sees and the
    angular sector (22.5 degrees each) where it sees it."""
    tracks = tracks_of_cycle(cycle, numbering)
    size = tracks.shape[1]
    rows = []
    for p in range(size):
        win = tracks[:, [p, (p + 1) % size]]
        text = "/".join("".join(str(int(v)) for v in row) for row in win)
        step = 360.0 / size
        rows.append(Row(p, text, number_of(win, numbering), p * step, (p + 1) * step))
    return rows
