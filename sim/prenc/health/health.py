# SPDX-License-Identifier: Apache-2.0
"""prenc_health, clock for clock: the warning before a failure.

The reader corrects what its heads read: a head's reading that disagrees with the
disc's law is a correction (prenc_core's track1_error / track2_error, what the error
counters count), and so is an illegal transition of the sync track (sync_illegal). The
position survives them, but they grow as a disc gets dirty or a head weakens, long
before the reader has to drop a track or the position.

Each source (head 1, head 2, the sync track) has a level, a leaky bucket in quarters of
travel: a correction adds 4 x WARN_SLOTS, each quarter step of the sync track (either
way) takes one off. A source whose corrections come more often than one per WARN_SLOTS
slots of travel fills its bucket, and so does a burst of WARN_BURST corrections; at the
limit (4 x WARN_SLOTS x WARN_BURST) the source warns, and it keeps warning until its
level is back to 0: after the limit, at least WARN_SLOTS x WARN_BURST slots of travel
without a correction. A disc that stands still neither fills nor drains.

    health = Health(warn_slots=128, warn_burst=8)
    health.clock(step, track1_error, track2_error, sync_illegal)
    health.warnings      # (head 1, head 2, sync): each source's warning, registered
    health.warning       # any of them
"""

from __future__ import annotations

from dataclasses import dataclass, field

WARN_SLOTS = 128
WARN_BURST = 8
SOURCES = ("track1", "track2", "sync")


def check_parameters(warn_slots: int, warn_burst: int) -> None:
    """The RTL's parameter checks."""
    if not 1 <= warn_slots <= 4096:
        raise ValueError(f"WARN_SLOTS = {warn_slots} is out of range 1..4096")
    if not 1 <= warn_burst <= 64:
        raise ValueError(f"WARN_BURST = {warn_burst} is out of range 1..64")


@dataclass
class Health:
    warn_slots: int = WARN_SLOTS
    warn_burst: int = WARN_BURST
    levels: list[int] = field(default_factory=lambda: [0, 0, 0])
    warnings: list[int] = field(default_factory=lambda: [0, 0, 0])

    def __post_init__(self) -> None:
        check_parameters(self.warn_slots, self.warn_burst)

    @property
    def weight(self) -> int:
        """What a correction adds: its share of travel, in quarters."""
        return 4 * self.warn_slots

    @property
    def limit(self) -> int:
        return 4 * self.warn_slots * self.warn_burst

    @property
    def warning(self) -> int:
        return int(any(self.warnings))

    def clock(self, step: int, track1_error: int, track2_error: int, sync_illegal: int,
              rst: int = 0) -> None:
        """One rising edge with these inputs (each a one-clock pulse)."""
        for k, event in enumerate((track1_error, track2_error, sync_illegal)):
            total = self.levels[k] + (self.weight if event else 0)
            level = min(total, self.limit)
            if step and level:
                level -= 1
            if total >= self.limit:
                self.warnings[k] = 1
            elif level == 0:
                self.warnings[k] = 0
            self.levels[k] = level
            if rst:
                self.levels[k] = self.warnings[k] = 0
