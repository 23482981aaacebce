# SPDX-License-Identifier: Apache-2.0
"""prenc_board's warning (prenc_health), read by a BiSS-C master as nW while the disc
turns at 30,000 rpm (N = 10 at 30 MHz, 58.6 clocks a slot).

- A clean disc with a real sensor's noise: crossing jitter of 0.01 slot RMS on all four
  signals and the rise and fall times of an Omron EE-SX1041 (4 us). Over three turns
  the warning never rises: every frame has nW = 1, and the position is valid in every
  frame after the first lock.
- A disc getting dirty: from clock 50,000 one more slot of track 1 reads inverted every
  4,000 clocks (68 slots of travel). The warning rises, and frames carry nW = 0, while
  the reader is still in its normal mode with both tracks (before it has to drop
  track 1) and the position is valid in every frame. An SSI master reads beside it
  (the board built with SSI_WARNING = 1): the frame's last bit is the warning, 0 in
  every frame that starts before it rises and 1 in every frame after.

In both, every clock the board's warnings equal prenc.health.Health's fed with the
core's own corrections and steps of the clock before (the block itself is held to the
model in tb/health).
"""

from __future__ import annotations

import cocotb
import numpy as np
from cocotb.triggers import ReadOnly, RisingEdge, Timer
from cocotb.utils import get_sim_time

from biss_master import Master
from board_harness import CHUNK, drive_encoder, start_board
from common import PERIOD_NS
from prenc.health.health import Health
from prenc.virtual.encoder import Disc
from prenc.virtual.faults import GrowingDirt
from prenc.virtual.sensors import CrossingJitter, EdgeDelay
from runner import rom_file, run

TOPLEVEL = "prenc_board"
N, FILTER, CLK_HZ = 10, 2, 30_000_000
MT_BITS, ST_BITS = 12, N + 2
RPM = 30_000
SLOTS_PER_CLOCK = RPM * (1 << N) / 60 / CLK_HZ
DIRT_START, DIRT_EVERY = 50_000, 4_000


def now() -> int:
    return round(get_sim_time("ns") / PERIOD_NS)


class Watch:
    """Every clock: the board's warnings against the model's, and what the BiSS-C frame
    would latch (the mode, valid, the warning)."""

    def __init__(self, dut):
        self.dut = dut
        self.model = Health()
        self.first_warning: int | None = None
        self.mode_at_warning: int | None = None
        self.first_valid: int | None = None
        self.reduced = 0
        self.first_reduced: int | None = None
        cocotb.start_soon(self._watch())

    async def _watch(self) -> None:
        dut = self.dut
        while True:
            await RisingEdge(dut.clk)
            await ReadOnly()
            got = [int(dut.warnings.value) >> k & 1 for k in range(3)]
            assert got == self.model.warnings, (now(), got, self.model.warnings, self.model.levels)
            self.model.clock(int(dut.sync_step.value), int(dut.track1_error.value),
                             int(dut.track2_error.value), int(dut.sync_illegal.value))
            mode = int(dut.u_core.mode.value)
            if any(got) and self.first_warning is None:
                self.first_warning, self.mode_at_warning = now(), mode
            if int(dut.u_core.pos_valid.value) and self.first_valid is None:
                self.first_valid = now()
            self.reduced += mode in (2, 3)
            if mode in (2, 3) and self.first_reduced is None:
                self.first_reduced = now()


async def read_frames(dut, watch: Watch, end: int) -> tuple[int, int]:
    """BiSS-C frames until clock `end`: (frames after the first lock, those with nW = 0).
    Every frame after the first lock must carry a valid position and a good CRC."""
    master = Master(dut, 5_000_000, CLK_HZ, ma="biss_ma", slo="biss_slo")
    frames = warned = 0
    while now() < end:
        reading, _ = await master.read(mt_bits=MT_BITS, st_bits=ST_BITS)
        assert reading.crc_ok, (now(), reading)
        if watch.first_valid is not None and now() > watch.first_valid + 2_000:
            assert not reading.error, (now(), reading)
            frames += 1
            warned += reading.warning
        await Timer(master.timeout_ns(), unit="ns")
    return frames, warned


async def read_ssi(dut, frames: list, end: int) -> None:
    """An SSI master at 1 MHz (30 clocks a bit), a frame every 60 us until `end`:
    (the clock the frame started, its bits) for each."""
    half_ns = 15 * PERIOD_NS
    width = len(dut.u_ssi.position)
    dut.ssi_gray.value = 0
    while now() < end:
        start, bits = now(), []
        for k in range(width + 4):      # the position, the error and warning bits, the line low
            dut.ssi_clk.value = 0
            if k > 0:
                bits.append(int(dut.ssi_data.value))
            await Timer(half_ns, unit="ns")
            dut.ssi_clk.value = 1
            await Timer(half_ns, unit="ns")
        frames.append((start, bits))
        await Timer(60_000, unit="ns")


def theta_at(clocks: np.ndarray) -> np.ndarray:
    return 17.3 + np.asarray(clocks, dtype=np.float64) * SLOTS_PER_CLOCK


@cocotb.test()
async def a_clean_disc_with_sensor_noise_never_warns(dut):
    await start_board(dut)
    noise = ("a", "b", "head1", "head2")
    cocotb.start_soon(drive_encoder(dut, theta_at, lambda chunk: [
        CrossingJitter(sigma=0.01, signals=noise, seed=chunk), EdgeDelay()], Disc(N)))
    watch = Watch(dut)
    end = now() + 3 * (1 << N) / SLOTS_PER_CLOCK
    frames, warned = await read_frames(dut, watch, end)
    dut._log.info("clean disc: %d frames, %d with nW = 0; track errors %d, %d, sync %d", frames, warned,
                  int(dut.track1_errors.value), int(dut.track2_errors.value), int(dut.sync_errors.value))
    assert frames > 150 and warned == 0 and watch.first_warning is None and watch.reduced == 0


@cocotb.test()
async def a_disc_getting_dirty_warns_before_a_track_is_dropped(dut):
    await start_board(dut)
    start = now()   # drive_encoder's chunks count from here

    def dirt(chunk: int) -> list:
        first = start + chunk * CHUNK
        return [GrowingDirt(track=1, every=DIRT_EVERY, start_clock=DIRT_START - first, seed=7)]

    cocotb.start_soon(drive_encoder(dut, theta_at, dirt, Disc(N)))
    watch = Watch(dut)
    ssi_frames: list = []
    cocotb.start_soon(read_ssi(dut, ssi_frames, start + 240_000))
    frames, warned = await read_frames(dut, watch, start + 250_000)
    spots = GrowingDirt(1, DIRT_EVERY, DIRT_START).spots(watch.first_warning or 0)
    dut._log.info("dirty disc: %d frames, %d with nW = 0; the warning at clock %s with %d dirty slots "
                  "(%.1f %% of track 1), mode %s; a reduced mode first at clock %s (%d clocks in all); "
                  "track 1 errors %d", frames, warned, watch.first_warning, spots, 100 * spots / (1 << N),
                  watch.mode_at_warning, watch.first_reduced, watch.reduced, int(dut.track1_errors.value))
    assert watch.first_warning is not None and watch.mode_at_warning == 1
    assert watch.first_reduced is None or watch.first_warning < watch.first_reduced
    assert warned > 10 and frames - warned > 10
    # SSI: the warning bit, the frame's last but one sampled bit (the last is the line low).
    before = [bits[-2] for s, bits in ssi_frames if s < watch.first_warning - 10]
    after = [bits[-2] for s, bits in ssi_frames if s > watch.first_warning + 10]
    dut._log.info("SSI: %d frames before the warning, %d after", len(before), len(after))
    assert len(before) >= 3 and len(after) > 10 and not any(before) and all(after)
    assert all(bits[-1] == 0 for _, bits in ssi_frames)
    assert all(bits[-3] == 0 for s, bits in ssi_frames if watch.first_valid and s > watch.first_valid + 2_000)


def test_prenc_board_health():
    run(__file__, TOPLEVEL, "verilator",
        parameters={"N": N, "TAPS": sum(1 << (t - 1) for t in Disc(N).taps), "FILTER": FILTER,
                    "ROM_FILE": rom_file(N), "CLK_HZ": CLK_HZ, "BAUD": 3_000_000, "SSI_WARNING": 1})
