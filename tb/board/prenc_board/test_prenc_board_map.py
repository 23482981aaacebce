# SPDX-License-Identifier: Apache-2.0
"""`prenc host map` on prenc_board (Verilator), through a pseudo-terminal as the user
runs it, while the disc turns with three contaminated slots on each track: track 1's
at slots 100, 104 and 108, track 2's at 680, 684 and 688 (each reads inverted on
every pass). The map must place every correction of head 1 in the region of the disc
that holds track 1's spots (slots 96-127 of 32 regions) and every correction of head 2
in the one that holds track 2's (672-703), none of the sync track, and the corrections
the map places must be those the board's counters counted.

Before it, `prenc host read --kind health` gives the slot under head 1 (the true
position at the answer's snapshot, as tb/board/prenc_board/test_prenc_board checks
the other kinds) and the board's error counters.
"""

from __future__ import annotations

import json

import cocotb
import numpy as np
from cocotb.triggers import Timer

from board_harness import Bridge, drive_encoder, start_board
from common import PERIOD_NS
from prenc.virtual.encoder import Disc
from prenc.virtual.faults import ContaminatedSlot
from prenc.virtual.scenarios import core_latency
from runner import rom_file, run
from test_prenc_board import host, link_args

TOPLEVEL = "prenc_board"
N, FILTER, CLK_HZ, BAUD = 10, 2, 24_000_000, 3_000_000
SLOT_CLOCKS = 300
SPOTS = {1: (100, 104, 108), 2: (680, 684, 688)}
REGIONS = 32


def theta_at(clocks: np.ndarray) -> np.ndarray:
    return 300.4 + np.asarray(clocks, dtype=np.float64) / SLOT_CLOCKS


@cocotb.test()
async def the_map_shows_where_each_head_is_corrected(dut):
    await start_board(dut)
    spots = [ContaminatedSlot(track, slot) for track, slots in SPOTS.items() for slot in slots]
    cocotb.start_soon(drive_encoder(dut, theta_at, lambda chunk: spots, Disc(N)))
    bridge = Bridge(dut, round(CLK_HZ / BAUD))
    await Timer(60 * SLOT_CLOCKS * PERIOD_NS, unit="ns")
    assert int(dut.pos_valid.value) == 1

    result = await host(bridge, "read", *link_args(bridge), "--kind", "health", "--json")
    assert result.returncode == 0, result.stderr
    record = json.loads(result.stdout)
    clock = bridge.snapshot_of(int(record["seq"])) - core_latency(FILTER)
    slots = {int(s) % (1 << N) for s in np.floor(theta_at(np.arange(clock - FILTER - 2, clock + FILTER + 3)))}
    assert record["kind"] == "health" and record["position"] in slots, (record, sorted(slots))
    assert record["warnings"] == 0 and record["sync_errors"] == 0

    before = [int(dut.track1_errors.value), int(dut.track2_errors.value)]
    result = await host(bridge, "map", *link_args(bridge), "--count", "420", "--json", "--regions", str(REGIONS),
                        timeout_s=600)
    assert result.returncode == 0, result.stderr
    after = [int(dut.track1_errors.value), int(dut.track2_errors.value)]
    found = json.loads(result.stdout)
    rows = found["regions"]
    head1 = {r["region"]: r["head1"] for r in rows if r["head1"]}
    head2 = {r["region"]: r["head2"] for r in rows if r["head2"]}
    dut._log.info("prenc host map: head 1 %s, head 2 %s, skipped %d; the counters gained %s; %s",
                  head1, head2, found["skipped"], [b - a for a, b in zip(before, after)], result.stderr.strip())
    assert set(head1) == {SPOTS[1][0] * REGIONS >> N} and set(head2) == {SPOTS[2][0] * REGIONS >> N}
    assert sum(head1.values()) >= 3 and sum(head2.values()) >= 3
    assert all(r["sync"] == 0 for r in rows) and found["skipped"] == 0
    # What the map placed, the counters counted (they went on counting after its last answer).
    assert sum(head1.values()) <= after[0] - before[0] and sum(head2.values()) <= after[1] - before[1]
    assert after[0] - before[0] - sum(head1.values()) <= 6


def test_prenc_board_map():
    run(__file__, TOPLEVEL, "verilator",
        parameters={"N": N, "FILTER": FILTER, "ROM_FILE": rom_file(N), "CLK_HZ": CLK_HZ, "BAUD": BAUD})
