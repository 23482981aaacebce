# SPDX-License-Identifier: Apache-2.0
"""prenc_wb: the reader core behind its Wishbone registers, driven by a Wishbone bus
model from PyPI (cocotbext-wishbone) through the Python register access that PeakRDL
generates from the map (rtl/bus/prenc_wb.rdl, by scripts/regmap.py).

- Every register after reset: constants and reset values from the RDL, the parameters
  from the build; every writable field written and read back; read-only registers and
  unmapped offsets ignore writes.
- While the virtual encoder turns (misreads, reversals): each read returns what the
  core showed on the clock the access was sampled, and the position, valid and mode
  are the model's (prenc.core.reader.Reader) on that clock. Snapshots taken at random
  times hold the position, status, count, timestamp, fine position and velocity of one
  clock, the clock after the write, while the live registers move on. (The fine
  position and velocity themselves are held to their models in tb/fine/prenc_fine and
  to the truth in tb/bus/prenc_wb's velocity test below.)
- Interrupts through a missed-state run: a status bit is set one clock after its event
  (pos_valid falls, mode changes, prenc_health's warning rises) and at no other time,
  falls only when written 1, and irq = |(status & enable) on every clock, whatever the
  mask. (N = 6 is built with WARN_SLOTS = 1, WARN_BURST = 1: the run's corrections
  raise warnings; prenc_health itself is held to its model in tb/health.)

The clock of a read: the slave samples cyc & stb on the edge before ack rises and
returns the values of the clock before that edge; the monitor logs every clock.
"""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import cocotb
import pytest
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

from common import PERIOD_NS, drive_events, rng, to_int_x_as_zero
from prenc.codes.debruijn import Code
from prenc.codes.lfsr import taps_mask
from prenc.cal.table import Table
from prenc.core.reader import Reader
from prenc.virtual.edge_timing import true_corrections
from prenc.virtual.fine_bench import PRINTED
from prenc.virtual.encoder import Disc, VirtualEncoder
from prenc.virtual.scenarios import scenarios
from prenc.virtual.trajectory import Trajectory
from runner import REPO, SIM_BUILD, rom_file, run

TOPLEVEL = "prenc_wb"
RESET = 4
PINS = ("head1", "head2", "sync_a", "sync_b")
WB_SIGNALS = {"cyc": "cyc_i", "stb": "stb_i", "we": "we_i", "adr": "adr_i", "datwr": "dat_i",
              "datrd": "dat_o", "ack": "ack_o", "sel": "sel_i"}
MAP_END = 0x80  # the slave decodes wb_adr_i[4:0]: 32 words


@dataclass
class Outputs:
    """What the core and the interrupt logic showed after one rising edge."""
    ack: int
    valid: int
    hyb: int
    abs: int
    mode: int
    position: int
    incremental: int
    direction: int
    t1pos: int
    t1valid: int
    t2pos: int
    t2valid: int
    t1err: int
    t2err: int
    syncerr: int
    timestamp: int
    irq_status: int
    irq_enable: int
    irq: int
    resolution: int
    fine: int
    vword: int
    vvalid: int
    warnings: int

    @property
    def w1(self) -> int:
        return self.warnings & 1

    @property
    def w2(self) -> int:
        return self.warnings >> 1 & 1

    @property
    def wsync(self) -> int:
        return self.warnings >> 2 & 1


class Bench:
    """Clock, reset, the pins from a virtual-encoder run, the bus master, the per-clock
    log, and the generated register access."""

    def __init__(self, dut):
        self.dut = dut
        self.log: list[Outputs] = []
        self.ack_edges: list[int] = []
        self.consumed = 0
        self.master = None
        self.regs = register_access(self)

    async def start(self, enc=None, quiet_clocks: int = 0):
        """Clock, rst for RESET clocks, and (in the background) the run's pins from clock
        0, as tb/core/prenc_core drives them; returns once rst is low."""
        dut = self.dut
        cocotb.start_soon(Clock(dut.clk, PERIOD_NS, unit="ns").start(start_high=False))
        events = enc.events() if enc is not None else [(0, 0, 0, 0, 1)]
        for pin, value in zip(PINS, events[0][1:]):
            getattr(dut, pin).value = value
        dut.rst.value = 1
        cocotb.start_soon(self._monitor())
        await RisingEdge(dut.clk)
        await FallingEdge(dut.clk)  # ends clock 0: drive_events counts from clock 1
        # The bus master, idle, during reset: on Icarus its immediate writes at time 0
        # leave the inputs' continuous assignments X.
        from cocotbext.wishbone.driver import WishboneMaster

        self.master = WishboneMaster(dut, "wb", dut.clk, width=32, timeout=64, signals_dict=WB_SIGNALS)
        if enc is not None:
            cocotb.start_soon(drive_events(dut, PINS, [(c - 1, *v) for c, *v in events[1:]],
                                           len(enc) + quiet_clocks))
        await self.clocks(RESET - 1)
        dut.rst.value = 0

    async def _monitor(self):
        dut, core = self.dut, self.dut.u_core
        while True:
            await RisingEdge(dut.clk)
            await ReadOnly()
            k = len(self.log)
            # X (Icarus: registers without a reset, e.g. a track's word before it is
            # known) reads as 0 here and in the bus data alike.
            signals = (dut.wb_ack_o, dut.pos_valid, dut.pos_hyb, core.pos_abs, core.mode, core.position,
                       core.incremental, core.direction, core.track1_pos, core.track1_valid,
                       core.track2_pos, core.track2_valid, core.track1_errors, core.track2_errors,
                       core.sync_errors, dut.timestamp, dut.irq_status, dut.irq_enable, dut.irq,
                       dut.resolution, dut.fine_word, dut.velocity, dut.velocity_valid, dut.warnings)
            row = Outputs(*(to_int_x_as_zero(s.value) for s in signals))
            self.log.append(row)
            if row.ack:
                self.ack_edges.append(k)

    async def access(self, offset: int, data: int | None = None) -> tuple[int | None, int]:
        """One bus access at a byte offset; (read data, the clock whose values it saw)."""
        from cocotbext.wishbone.driver import WBOp

        result = await self.master.send_cycle([WBOp(adr=offset >> 2, dat=data)])
        edge = self.ack_edges[self.consumed]
        self.consumed += 1
        value = None if data is not None else to_int_x_as_zero(result[0].datrd)
        return value, edge - 1

    async def clocks(self, count: int):
        for _ in range(count):
            await RisingEdge(self.dut.clk)
        await FallingEdge(self.dut.clk)


def register_access(bench: Bench):
    """PeakRDL-python's register model of the map, on the bus master."""
    sys.path.insert(0, os.environ["PRENC_REGMAP"])
    from prenc_wb.lib import AsyncCallbackSet
    from prenc_wb.reg_model.prenc_wb import prenc_wb_cls

    async def read(addr: int, width: int, accesswidth: int) -> int:
        value, _ = await bench.access(addr)
        return value

    async def write(addr: int, width: int, accesswidth: int, data: int) -> None:
        await bench.access(addr, data)

    return prenc_wb_cls(callbacks=AsyncCallbackSet(read_callback=read, write_callback=write))


def field_value(reg, name: str, word: int) -> int:
    field = next(f for f in reg.fields if f.inst_name == name)
    return (word >> field.lsb) & ((1 << (field.msb - field.lsb + 1)) - 1)


# Which of the core's outputs each field of the map shows (the field positions come from
# the RDL, through the generated register model).
STATUS_FIELDS = {"valid": "valid", "mode": "mode", "direction": "direction",
                 "track1_valid": "t1valid", "track2_valid": "t2valid", "velocity_valid": "vvalid",
                 "warn_track1": "w1", "warn_track2": "w2", "warn_sync": "wsync"}
SOURCES = {
    "CTRL": {"resolution": "resolution", "clear_errors": None, "snapshot": None},
    "STATUS": STATUS_FIELDS,
    "POSITION": {"position": "position"},
    "POS_ABS": {"pos_abs": "abs"},
    "POS_HYB": {"pos_hyb": "hyb"},
    "INCREMENTAL": {"count": "incremental"},
    "TRACK1": {"pos": "t1pos", "valid": "t1valid"},
    "TRACK2": {"pos": "t2pos", "valid": "t2valid"},
    "TRACK_ERRORS": {"track1": "t1err", "track2": "t2err"},
    "SYNC_ERRORS": {"sync": "syncerr"},
    "TIMESTAMP": {"time": "timestamp"},
    "SNAP_POS_HYB": {"pos_hyb": "hyb"},
    "SNAP_STATUS": STATUS_FIELDS,
    "SNAP_INCREMENTAL": {"count": "incremental"},
    "SNAP_TIME": {"time": "timestamp"},
    "FINE_POS": {"fine_pos": "fine"},
    "VELOCITY": {"velocity": "vword"},
    "SNAP_FINE_POS": {"fine_pos": "fine"},
    "SNAP_VELOCITY": {"velocity": "vword"},
}


def expected_word(reg, row: Outputs) -> int:
    """The word a register must read when the core shows `row`: each field's source at
    the field's place in the map (write-only pulses read 0)."""
    sources = SOURCES[reg.inst_name]
    assert {f.inst_name for f in reg.fields} == set(sources), reg.inst_name
    return sum(getattr(row, sources[f.inst_name]) << f.lsb for f in reg.fields if sources[f.inst_name])


@cocotb.test()
async def registers_after_reset_and_writes(dut):
    n, filter_len = len(dut.pos_hyb) - 2, int(dut.FILTER.value)
    bench = Bench(dut)
    await bench.start()
    regs = bench.regs
    await bench.clocks(5)
    # Constants and reset values: the RDL's (the register model's defaults).
    for reg in regs.get_registers():
        word, _ = await bench.access(reg.address)
        for field in reg.fields:
            if field.default is not None:
                got = field_value(reg, field.inst_name, word)
                assert got == field.default, f"{reg.inst_name}.{field.inst_name} = {got}, RDL reset {field.default}"
    assert await regs.PARAMS.n.read() == n
    assert await regs.PARAMS.filter.read() == filter_len
    assert await regs.PARAMS.fine.read() == int(dut.FINE.value)
    assert await regs.PARAMS.fine_bits.read() == int(dut.FINE_BITS.value)
    assert await regs.PARAMS.cal.read() == int(dut.CAL.value)
    assert await regs.STATUS.valid.read() == 0 and await regs.STATUS.mode.read() == 0
    for name in ("SNAP_POS_HYB", "SNAP_STATUS", "SNAP_INCREMENTAL", "SNAP_TIME", "SNAP_FINE_POS",
                 "SNAP_VELOCITY", "TRACK_ERRORS"):
        assert await getattr(regs, name).read() == 0, name
    # The timestamp counts clocks.
    t0, s0 = await bench.access(regs.TIMESTAMP.address)
    t1, s1 = await bench.access(regs.TIMESTAMP.address)
    assert t1 - t0 == s1 - s0 > 0
    # Writable fields, written and read back.
    for value in (0, 1, 0, 1):
        await regs.CTRL.resolution.write(value)
        assert await regs.CTRL.resolution.read() == value
    for value in (3, 1, 2, 0):
        await regs.IRQ_ENABLE.write(value)
        assert await regs.IRQ_ENABLE.read() == value
    await regs.IRQ_STATUS.write(7)  # write 1 to clear: nothing to set
    assert await regs.IRQ_STATUS.read() == 0
    # Write-1 pulses read back 0.
    await regs.CTRL.write(0b111)
    assert await regs.CTRL.read() == 1
    # Read-only registers and unmapped offsets ignore writes.
    before = {reg.inst_name: (await bench.access(reg.address))[0] for reg in regs.get_registers()
              if reg.inst_name in ("ID", "VERSION", "PARAMS", "STATUS", "POS_HYB", "SNAP_TIME")}
    for reg in regs.get_registers():
        if reg.inst_name in before:
            await bench.access(reg.address, 0xFFFF_FFFF)
    for name, value in before.items():
        assert (await bench.access(getattr(regs, name).address))[0] == value, name
    # CAL_ADDR: read back with the calibration table (CAL = 1), 0 without; CAL_DATA reads 0.
    cal = int(dut.CAL.value)
    assert await regs.PARAMS.cal.read() == cal
    for value in (0x2_5A5A, 7, 0):
        await regs.CAL_ADDR.write(value)
        assert await regs.CAL_ADDR.read() == (value if cal else 0)
    await regs.CAL_DATA.write(0x1234)
    assert (await bench.access(regs.CAL_DATA.address))[0] == 0
    assert await regs.CAL_ADDR.read() == (1 if cal else 0)
    for offset in range(0x68, MAP_END, 4):
        await bench.access(offset, 0xFFFF_FFFF)
        assert (await bench.access(offset))[0] == 0, f"offset {offset:#x}"
    assert int(dut.wb_err_o.value) == 0


def model_rows(enc, n: int, filter_len: int):
    return Reader(Code(n), filter_len).run(enc, RESET)


@cocotb.test()
async def reads_and_snapshots_while_the_encoder_moves(dut):
    n, filter_len = len(dut.pos_hyb) - 2, int(dut.FILTER.value)
    r = rng()
    enc = scenarios(n, filter_len, r.randrange(1 << 30))["random_misreads"].run(n)
    model = model_rows(enc, n, filter_len)
    bench = Bench(dut)
    await bench.start(enc)
    regs = bench.regs
    live = ["STATUS", "POSITION", "POS_ABS", "POS_HYB", "INCREMENTAL", "TRACK1", "TRACK2",
            "TRACK_ERRORS", "SYNC_ERRORS", "TIMESTAMP", "CTRL", "FINE_POS", "VELOCITY"]
    checked = valid_reads = snapshots_moved = 0
    while len(bench.log) < len(enc) - 200:
        choice = r.random()
        if choice < 0.05:  # the resolution, which POSITION follows
            await regs.CTRL.resolution.write(r.randrange(2))
        elif choice < 0.15:  # a snapshot, read back while the disc moves
            ctrl, _ = await bench.access(regs.CTRL.address)
            _, s = await bench.access(regs.CTRL.address, ctrl | 0b100)
            await bench.clocks(r.randrange(1, 60))
            snap = bench.log[s + 1]  # latched on the edge after the write's
            got = {name: await getattr(regs, name).read()
                   for name in ("SNAP_POS_HYB", "SNAP_STATUS", "SNAP_INCREMENTAL", "SNAP_TIME",
                                "SNAP_FINE_POS", "SNAP_VELOCITY")}
            want = {name: expected_word(getattr(regs, name), snap) for name in got}
            assert got == want, f"snapshot of clock {s + 1}: {got} != {want}"
            m = model[s + 1]
            assert (snap.valid, snap.mode) == (m.valid, m.mode), f"clock {s + 1}: core vs model"
            if m.valid:
                assert snap.hyb == m.pos_hyb
            again = await regs.SNAP_POS_HYB.read()
            now, _ = await bench.access(regs.POS_HYB.address)
            assert again == got["SNAP_POS_HYB"], "a snapshot changed without a new write"
            snapshots_moved += now != again
        else:
            name = r.choice(live)
            reg = getattr(regs, name)
            word, s = await bench.access(reg.address)
            row = bench.log[s]
            assert word == expected_word(reg, row), f"{name} at clock {s}: {word:#x}"
            m = model[s]
            assert (row.valid, row.mode) == (m.valid, m.mode), f"clock {s}: core {row.valid}/{row.mode}"
            if m.valid:
                assert (row.hyb, row.abs) == (m.pos_hyb, m.pos_abs), f"clock {s}: not the model's position"
                valid_reads += 1
            if name == "POSITION":
                assert word == (row.hyb if row.resolution else row.abs)
            checked += 1
        await bench.clocks(r.randrange(0, 8))
    # The error counters count, and clear_errors zeroes them.
    assert bench.log[-1].t1err + bench.log[-1].t2err > 0, "the misreads were not counted"
    await regs.CTRL.write((await regs.CTRL.read()) | 0b010)
    e = bench.ack_edges[bench.consumed - 1]
    await bench.clocks(4)
    assert any(c.t1err == c.t2err == c.syncerr == 0 for c in bench.log[e:e + 4]), "clear_errors"
    dut._log.info("%d reads checked (%d while valid), %d snapshots differed from the live position",
                  checked, valid_reads, snapshots_moved)
    assert checked > 300 and valid_reads > 100 and snapshots_moved > 10


@cocotb.test()
async def interrupts_follow_their_events(dut):
    n, filter_len = len(dut.pos_hyb) - 2, int(dut.FILTER.value)
    r = rng()
    enc = scenarios(n, filter_len, r.randrange(1 << 30))["combined"].run(n)
    bench = Bench(dut)
    await bench.start(enc)
    regs = bench.regs
    clear_masks: dict[int, int] = {}
    raised = 0
    await regs.IRQ_ENABLE.write(0b111)
    while len(bench.log) < len(enc) - 100:
        await bench.clocks(r.randrange(20, 300))
        status, s = await bench.access(regs.IRQ_STATUS.address)
        assert status == bench.log[s].irq_status
        if status:
            raised += 1
            mask = status if r.random() < 0.8 else status & r.randrange(8)
            await bench.access(regs.IRQ_STATUS.address, mask)
            edge = bench.ack_edges[bench.consumed - 1]
            clear_masks[edge] = mask
        if r.random() < 0.2:
            await regs.IRQ_ENABLE.write(r.randrange(8))
    log = bench.log
    bits = {f.inst_name: f.lsb for f in regs.IRQ_STATUS.fields}  # the map's, from the RDL
    events = {"lost_valid": 0, "mode_change": 0, "warning": 0}
    for k in range(2, len(log)):
        lost = log[k - 2].valid and not log[k - 1].valid
        changed = log[k - 1].mode != log[k - 2].mode
        warned = bool(log[k - 1].warnings) and not log[k - 2].warnings
        for name, event in (("lost_valid", lost), ("mode_change", changed), ("warning", warned)):
            bit = bits[name]
            was, now = (log[k - 1].irq_status >> bit) & 1, (log[k].irq_status >> bit) & 1
            events[name] += bool(event)
            if event:
                assert now, f"clock {k}: {name} not set after its event"
            elif now and not was:
                raise AssertionError(f"clock {k}: {name} set without an event")
            elif was and not now:
                assert (clear_masks.get(k, 0) >> bit) & 1, f"clock {k}: {name} fell without a write"
        assert log[k].irq == int(bool(log[k].irq_status & log[k].irq_enable)), f"clock {k}: irq"
    dut._log.info("events %s, %d interrupts seen and cleared", events, raised)
    assert events["lost_valid"] > 0 and events["mode_change"] > 0 and raised > 0
    if int(dut.WARN_BURST.value) == 1:
        assert events["warning"] > 0


@cocotb.test()
async def the_snapshot_holds_the_fine_position_and_velocity_of_its_clock(dut):
    """A steady turn (after lock and the velocity's first windows): each snapshot's fine
    position against the true angle at the clock its write was sampled, its velocity
    against the true speed; the goals of issue 37 (1/256 slot RMS, 0.05 %)."""
    n, filter_len, fine_bits = len(dut.pos_hyb) - 2, int(dut.FILTER.value), int(dut.FINE_BITS.value)
    r = rng()
    speed = 0.003 * r.uniform(0.8, 1.2)  # slots per clock
    settle = int((n + 8) / speed) + 16 * 1024
    traj = Trajectory(clk_hz=1, start=r.uniform(0, 1 << n)).constant(speed, settle + 12_000)
    enc = VirtualEncoder(Disc(n)).run(traj)
    bench = Bench(dut)
    await bench.start(enc)
    regs = bench.regs
    await bench.clocks(settle)
    length, errors, v_errors = 1 << n, [], []
    while len(bench.log) < len(enc) - 300:
        ctrl, _ = await bench.access(regs.CTRL.address)
        _, s = await bench.access(regs.CTRL.address, ctrl | 0b100)
        await bench.clocks(r.randrange(1, 40))
        status = await regs.SNAP_STATUS.read()
        fine = await regs.SNAP_FINE_POS.read()
        velocity = await regs.SNAP_VELOCITY.read()
        assert field_value(regs.SNAP_STATUS, "valid", status) and \
            field_value(regs.SNAP_STATUS, "velocity_valid", status), f"clock {s + 1}: {status:#x}"
        truth = traj.theta[s + 1]
        err = fine / (4 << fine_bits) - truth
        errors.append((err + length / 2) % length - length / 2)
        v_errors.append((velocity - (velocity >> 31 << 32)) / 2 ** 32 / (4 * speed) - 1)
        await bench.clocks(r.randrange(50, 400))
    rms = (sum(e * e for e in errors) / len(errors)) ** 0.5
    dut._log.info("%d snapshots: fine position %.5f slot RMS (max %.5f), velocity error max %.4f %%",
                  len(errors), rms, max(map(abs, errors)), 100 * max(map(abs, v_errors)))
    assert len(errors) >= 20
    assert rms <= 1 / 256 and max(map(abs, errors)) <= 1 / 64
    assert max(map(abs, v_errors)) <= 0.0005


@cocotb.test()
async def a_calibration_table_loaded_over_the_bus_corrects_the_fine_position(dut):
    """A printed disc turning steadily (CAL = 1, the table empty): snapshots of the fine
    position against the true angle, before the table, and after it is written over the
    bus (CAL_ADDR = 0, then its words into CAL_DATA) as a perfect calibration would make
    it from the disc's definition (prenc.virtual.edge_timing), less its zero."""
    if not int(dut.CAL.value):
        dut._log.info("built without the calibration table (CAL = 0): nothing to load")
        return
    n, fine_bits = len(dut.pos_hyb) - 2, int(dut.FINE_BITS.value)
    r = rng()
    c = true_corrections(PRINTED, n)
    table = Table.from_quarters(n, c - c.mean())
    zero = -float(c.mean()) / 4           # the table's zero against the shaft's, slots
    speed = 0.003 * r.uniform(0.8, 1.2)   # slots per clock
    settle = int((n + 8) / speed) + 16 * 1024
    traj = Trajectory(clk_hz=1, start=r.uniform(0, 1 << n)).constant(speed, 2 * settle + 30_000)
    enc = VirtualEncoder(Disc(n, printing=PRINTED)).run(traj)
    bench = Bench(dut)
    await bench.start(enc)
    regs = bench.regs
    length = 1 << n

    async def snapshots(count: int, offset: float) -> list[float]:
        out = []
        for _ in range(count):
            ctrl, _ = await bench.access(regs.CTRL.address)
            _, s = await bench.access(regs.CTRL.address, ctrl | 0b100)
            fine = await regs.SNAP_FINE_POS.read()
            err = fine / (4 << fine_bits) - traj.theta[s + 1] - offset
            out.append((err + length / 2) % length - length / 2)
            await bench.clocks(r.randrange(100, 300))
        return out
    await bench.clocks(settle)
    before = await snapshots(15, 0.0)
    await regs.CAL_ADDR.write(0)
    for word in table.c.tolist():
        await regs.CAL_DATA.write(word & 0xFFFF)
    assert await regs.CAL_ADDR.read() == len(table.c)
    await bench.clocks(settle)           # windows measured with the table
    after = await snapshots(15, zero)
    rms = [(sum(e * e for e in x) / len(x)) ** 0.5 for x in (before, after)]
    dut._log.info("fine position against the truth: %.4f slot RMS without the table, %.5f with it",
                  *rms)
    # Before: the printed disc's errors where the snapshots were taken (the eccentricity's
    # share depends on the stretch of the turn); after: issue 38's goal.
    assert rms[0] > 0.02 and rms[0] > 10 * rms[1], rms
    assert rms[1] <= 1 / 128 and max(map(abs, after)) <= 1 / 64


def wb_parameters(n: int, filter_len: int) -> dict:
    return {"N": n, "TAPS": taps_mask(Code(n).taps), "FILTER": filter_len, "ROM_FILE": rom_file(n)}


def warning_parameters(n: int) -> dict:
    """N = 6 warns at every correction (the interrupt test sees warnings)."""
    return {"WARN_SLOTS": 1, "WARN_BURST": 1} if n == 6 else {}


@contextlib.contextmanager
def regmap_env():
    """The Python register access, generated from the RDL into a folder of this test's own
    (parallel workers must not rewrite each other's), as the environment of the run."""
    sys.path.insert(0, str(REPO / "scripts"))
    import regmap

    SIM_BUILD.mkdir(exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="regmap-", dir=SIM_BUILD) as folder:
        regmap.python_access(regmap.compile_rdl(), Path(folder))
        yield {"PRENC_REGMAP": folder}


@pytest.mark.parametrize("n,filter_len", [(10, 2), (6, 0)])
def test_prenc_wb_verilator(n, filter_len):
    with regmap_env() as env:
        run(__file__, TOPLEVEL, "verilator", parameters=wb_parameters(n, filter_len) | warning_parameters(n),
            extra_env=env)


@pytest.mark.parametrize("simulator", ["verilator", "icarus"])
def test_prenc_wb_with_a_calibration_table(simulator):
    tests = "registers_after_reset_and_writes|a_calibration_table_loaded_over_the_bus_corrects_the_fine_position"
    with regmap_env() as env:
        run(__file__, TOPLEVEL, simulator, parameters=wb_parameters(6, 2) | {"CAL": 1},
            extra_env={**env, "COCOTB_TEST_FILTER": tests if simulator == "verilator"
                       else "registers_after_reset_and_writes"})


def test_prenc_wb_icarus_smoke():
    with regmap_env() as env:
        run(__file__, TOPLEVEL, "icarus", parameters=wb_parameters(8, 2),
            extra_env={**env, "COCOTB_TEST_FILTER": "registers_after_reset_and_writes"})
