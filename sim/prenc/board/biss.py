# SPDX-License-Identifier: Apache-2.0
"""BiSS-C, point to point, single-cycle sensor data: the master's side.

Written from the protocol's description (docs/biss-c.md), not from the slave
(rtl/board/prenc_biss.v), so that a test of the slave against it means something:

- idle: MA and SLO high; the master starts a frame with a falling edge of MA;
- the slave answers the second rising edge of MA with Ack (SLO low), then a start
  bit (high), then CDS (a control-data bit, 0 here), then the data, MSB first:
  multi-turn, single-turn, nE (0: error), nW (0: warning), then CRC-6 inverted;
- CRC-6: polynomial x^6 + x + 1, start value 0, over the data bits with nE and nW,
  MSB first, sent inverted (the table-driven CRC of the BiSS application notes);
- the master compensates the line delay: it measures how long after a rising edge
  of MA the start bit arrives and samples every later bit that long after its
  rising edge, half a period into the bit;
- after the last bit the master leaves MA high; SLO stays low for the slave's
  timeout and returns high when the slave is ready for the next frame.
"""

from __future__ import annotations

from dataclasses import dataclass

CRC_POLY = 0x03  # x^6 + x + 1, the x^6 term implied
CRC_BITS = 6


def crc6(bits) -> int:
    """CRC-6 of the bits, MSB first, start value 0 (not inverted)."""
    crc = 0
    for bit in bits:
        feedback = ((crc >> 5) & 1) ^ (bit & 1)
        crc = (crc << 1) & 0x3F
        if feedback:
            crc ^= CRC_POLY
    return crc


def to_bits(value: int, width: int) -> list[int]:
    if not 0 <= value < 1 << width:
        raise ValueError(f"{value} does not fit in {width} bits")
    return [(value >> (width - 1 - i)) & 1 for i in range(width)]


def from_bits(bits) -> int:
    value = 0
    for bit in bits:
        value = value << 1 | (bit & 1)
    return value


@dataclass(frozen=True)
class Reading:
    """One frame as the master decodes it."""

    turns: int
    position: int
    error: bool    # nE was 0: the position must not be used
    warning: bool  # nW was 0
    crc_ok: bool


def payload_bits(turns: int, position: int, mt_bits: int, st_bits: int,
                 error: bool, warning: bool) -> list[int]:
    """The bits the CRC covers: multi-turn, single-turn, nE, nW."""
    return (to_bits(turns, mt_bits) + to_bits(position, st_bits)
            + [0 if error else 1, 0 if warning else 1])


def frame_bits(turns: int, position: int, mt_bits: int, st_bits: int,
               error: bool, warning: bool) -> list[int]:
    """Every bit after the start bit: CDS (0), the payload, the CRC inverted."""
    payload = payload_bits(turns, position, mt_bits, st_bits, error, warning)
    crc = crc6(payload)
    return [0] + payload + [1 - b for b in to_bits(crc, CRC_BITS)]


def decode(bits, mt_bits: int, st_bits: int) -> Reading:
    """A Reading from the bits after the start bit (CDS first)."""
    need = 1 + mt_bits + st_bits + 2 + CRC_BITS
    if len(bits) != need:
        raise ValueError(f"{len(bits)} bits for a frame of {need} (CDS, {mt_bits} + {st_bits} data, "
                         f"nE, nW, CRC)")
    payload = list(bits[1:1 + mt_bits + st_bits + 2])
    crc = from_bits(1 - b for b in bits[-CRC_BITS:])
    return Reading(turns=from_bits(payload[:mt_bits]),
                   position=from_bits(payload[mt_bits:mt_bits + st_bits]),
                   error=payload[-2] == 0, warning=payload[-1] == 0,
                   crc_ok=crc == crc6(payload))


def clock_pulses(mt_bits: int, st_bits: int) -> int:
    """MA pulses a master sends for one frame: 2 to reach Ack, the start bit, the
    frame's bits after it, and one more that puts SLO into its timeout (low)."""
    return 2 + 1 + (1 + mt_bits + st_bits + 2 + CRC_BITS) + 1


class FrameError(ValueError):
    """The line did not show a BiSS frame (no Ack, no start bit, or too few bits)."""


def sample(rises: list[float], slo_edges: list[tuple[float, int]], period: float,
           count: int) -> tuple[list[int], float]:
    """The `count` bits after the start bit, as a master with line-delay compensation
    samples them, and the measured delay.

    rises      times of MA's rising edges in the frame, in order (the first is 1)
    slo_edges  (time, level) of every change of SLO from the frame's start on
    period     MA's period
    """

    def level_at(t: float) -> int:
        level = 1
        for when, value in slo_edges:
            if when > t:
                break
            level = value
        return level

    if len(rises) < 2:
        raise FrameError("fewer than two rising edges of MA")
    ack = next((t for t, v in slo_edges if v == 0 and t > rises[1]), None)
    if ack is None:
        raise FrameError("no Ack: SLO never went low after the second rising edge")
    start = next((t for t, v in slo_edges if v == 1 and t > ack), None)
    if start is None:
        raise FrameError("no start bit after the Ack")
    cause = max(i for i, t in enumerate(rises) if t < start)  # the rising edge that sent it
    delay = start - rises[cause]
    if cause + count >= len(rises):
        raise FrameError(f"MA has {len(rises)} rising edges; the frame needs {cause + count + 1}")
    bits = [level_at(rises[cause + 1 + i] + delay + period / 2) for i in range(count)]
    return bits, delay


def bit_names(mt_bits: int, st_bits: int) -> list[str]:
    """The frame's bits from CDS on, as the diagrams name them."""
    return (["CDS"] + [f"M{mt_bits - 1 - i}" for i in range(mt_bits)]
            + [f"S{st_bits - 1 - i}" for i in range(st_bits)] + ["nE", "nW"]
            + [f"C{CRC_BITS - 1 - i}" for i in range(CRC_BITS)])


def timing_diagram(turns: int, position: int, mt_bits: int, st_bits: int,
                   error: bool = False, warning: bool = False) -> str:
    """A frame as text (docs/biss-c.md): MA, the rising edges' numbers, SLO and the
    bits' names. SLO is drawn changing just after each rising edge; X marks a bit
    boundary without a change of level."""
    bits = frame_bits(turns, position, mt_bits, st_bits, error, warning)
    names = bit_names(mt_bits, st_bits)
    pulses = clock_pulses(mt_bits, st_bits)
    period, lead, tail = 5, 4, 14
    width = lead + period * pulses + tail
    after = {1: (1, ""), 2: (0, "Ack"), 3: (1, "St"), pulses: (0, "timeout")}
    after.update({4 + i: (b, names[i]) for i, b in enumerate(bits)})
    ma, rise, slo, label = ["‾"] * width, [" "] * width, [], [" "] * width
    changes = {}
    for k in range(1, pulses + 1):
        fall = lead + period * (k - 1)
        ma[fall:fall + 4] = ["\\", "_", "_", "/"]
        rise[fall + 3:fall + 3 + len(str(k))] = list(str(k))
        changes[fall + 4] = after[k][0]
        for j, ch in enumerate(after[k][1]):
            label[fall + 4 + j] = ch
    level, first_bit = 1, lead + period * 3 + 4
    for col in range(width):
        if col in changes:
            new = changes[col]
            slo.append("X" if new == level and col >= first_bit else
                       "\\" if new < level else "/" if new > level else ("‾" if level else "_"))
            level = new
        elif col == width - 4:
            slo.append("/" if level == 0 else "‾")
            level = 1
        else:
            slo.append("‾" if level else "_")
    rows = [("MA  ", ma), ("rise", rise), ("SLO ", slo), ("    ", label)]
    return "\n".join((name + " " + "".join(row)).rstrip() for name, row in rows)


def wavedrom(turns: int, position: int, mt_bits: int, st_bits: int,
             error: bool = False, warning: bool = False) -> str:
    """The same frame as timing_diagram, as WaveDrom JSON (docs/biss-c.md renders it):
    one character per half period of MA; SLO drawn changing with each rising edge."""
    bits = frame_bits(turns, position, mt_bits, st_bits, error, warning)
    pulses = clock_pulses(mt_bits, st_bits)
    after = {1: 1, 2: 0, 3: 1, pulses: 0}
    after.update({4 + i: b for i, b in enumerate(bits)})
    ma, slo, level = "1.", "1.", 1
    for k in range(1, pulses + 1):
        ma += "01"  # the falling edge, then the rising edge k
        new = after[k]
        slo += "." + ("." if new == level else str(new))
        level = new
    ma += "...."
    slo += "..1."
    labels = " ".join(["Ack", "Start"] + bit_names(mt_bits, st_bits))
    return ('{ "signal": [\n'
            f'  {{ "name": "MA",  "wave": "{ma}", "node": "..a" }},\n'
            f'  {{ "name": "SLO", "wave": "{slo}" }}\n'
            '  ],\n'
            '  "edge": ["a latch"],\n'
            f'  "foot": {{ "text": "after rising edges 2 to {pulses - 1}: {labels}; then the timeout" }}\n'
            '}')

