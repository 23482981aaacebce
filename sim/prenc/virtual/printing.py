# SPDX-License-Identifier: Apache-2.0
"""A printed disc's imperfections: where the edges of A and B really are.

The datasheet's disc is ideal: A rises at p + 0.5 and falls at p + 1, B falls at
p + 0.25 and rises at p + 0.75, and the disc turns about its centre. A disc printed on
film and glued to a hub is not (issue 37, item 5):

- edge_error: every edge of A and B sits off its place by a fixed error of its own,
  drawn once (seeded), uniform in [-edge_error, +edge_error] slots;
- phase_deg: B's edges are shifted against A's by this many electrical degrees
  (360 degrees = one slot); positive: B later (CW);
- duty_a, duty_b: the share of a slot each signal is high (0.5 ideal), each high
  interval keeping its centre (A: p + 0.75, B: p);
- eccentricity: the disc turns off-centre, so a head reads the angle
  theta + e * sin(2 pi theta / L + eccentricity_phase) (slots at the tracks' radius);
  head 2, 180 degrees away, reads theta - e * sin(...). The sync track is read
  beside head 1.

    printing = Printing(edge_error=0.05, phase_deg=10, duty_a=0.45, duty_b=0.55,
                        eccentricity=0.2, seed=3)
    disc = Disc(10, printing=printing)

The truth stays the shaft's angle theta: what a printed disc makes a reader see is
the error that calibration (issue 38) removes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

# The nominal place of each edge inside slot p, in slots past p.
A_RISE, A_FALL = 0.5, 1.0     # A high over [p + 0.5, p + 1)
B_RISE, B_FALL = 0.75, 1.25   # B high over [p + 0.75, p + 1.25)


@dataclass(frozen=True)
class Printing:
    """The imperfections of a printed disc (all zero: the datasheet's ideal disc)."""

    edge_error: float = 0.0
    phase_deg: float = 0.0
    duty_a: float = 0.5
    duty_b: float = 0.5
    eccentricity: float = 0.0
    eccentricity_phase: float = 0.0
    seed: int = 1

    def __post_init__(self) -> None:
        for name in ("duty_a", "duty_b"):
            duty = getattr(self, name)
            if not 0.3 <= duty <= 0.7:
                raise ValueError(f"{name} = {duty!r} is out of range 0.3..0.7")
        if not 0 <= self.edge_error <= 0.1:
            raise ValueError(f"edge_error = {self.edge_error!r} is out of range 0..0.1 slot")
        if not -30 <= self.phase_deg <= 30:
            raise ValueError(f"phase_deg = {self.phase_deg!r} is out of range -30..30 degrees")
        if not 0 <= self.eccentricity <= 0.3:
            raise ValueError(f"eccentricity = {self.eccentricity!r} is out of range 0..0.3 slot")

    def edges(self, length: int) -> dict[str, np.ndarray]:
        """Each slot's four edges, in slots past the slot's start: a_rise, a_fall,
        b_rise, b_fall (b_fall belongs to the B interval that rises in the slot)."""
        rng = np.random.default_rng(self.seed)
        error = {name: rng.uniform(-self.edge_error, self.edge_error, length)
                 for name in ("a_rise", "a_fall", "b_rise", "b_fall")}
        widen_a = (self.duty_a - 0.5) / 2
        widen_b = (self.duty_b - 0.5) / 2
        shift_b = self.phase_deg / 360.0
        return {
            "a_rise": A_RISE - widen_a + error["a_rise"],
            "a_fall": A_FALL + widen_a + error["a_fall"],
            "b_rise": B_RISE - widen_b + shift_b + error["b_rise"],
            "b_fall": B_FALL + widen_b + shift_b + error["b_fall"],
        }

    def seen(self, theta, length: int, head: int = 1) -> np.ndarray:
        """The angle a head reads on this disc (eccentricity), in slots."""
        theta = np.asarray(theta, dtype=np.float64)
        if self.eccentricity == 0:
            return theta
        sign = 1.0 if head == 1 else -1.0
        return theta + sign * self.eccentricity * np.sin(2 * math.pi * theta / length
                                                         + self.eccentricity_phase)

    def sync(self, theta, length: int) -> tuple[np.ndarray, np.ndarray]:
        """A and B at the shaft angle theta (uint8 arrays)."""
        seen = self.seen(theta, length, head=1)
        edges = self.edges(length)
        p = np.floor(seen).astype(np.int64)

        def high(rise: str, fall: str) -> np.ndarray:
            # The intervals that can cover `seen`: those that rise in slot p or p - 1.
            out = np.zeros(seen.shape, dtype=bool)
            for k in (p - 1, p):
                i = k % length
                out |= (k + edges[rise][i] <= seen) & (seen < k + edges[fall][i])
            return out.astype(np.uint8)

        return high("a_rise", "a_fall"), high("b_rise", "b_fall")
