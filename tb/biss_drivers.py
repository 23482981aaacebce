# SPDX-License-Identifier: Apache-2.0
"""BiSS-C masters as two drives' firmware runs them, for testbenches: the clocking,
sampling, frame layout and checks of each, read from its source. (moteus reads any
layout with its data_bits and needs no master of its own here: tb/biss_master.py's
line-delay-compensated master decodes as it does.)

- OnStepX (hjd1964/OnStepX, src/lib/encoder/bissc/Bissc.cpp): MA bit-banged at
  BISSC_CLOCK_RATE_KHZ (4,000), SLO read in MA's low phase, half-way; up to 20 clocks
  for the Ack (SLO low), 20 for the Start (high), then CDS must be low; then the
  layout's multi-turn and single-turn bits, the error and warning bits and the CRC-6
  (x^6 + x + 1, inverted); MA low for two bit times, then high. A read fails on a missing
  Ack, Start or CDS, a bad CRC, or the error bit: 1 for the Broadcom AS37-H39B
  (encoderErrInvert = false), 0 for the others. Layouts: AS37_H39B_B 16 + 23, JTW_24BIT
  0 + 24, JTW_26BIT 0 + 26.
- VESC (vedderb/bldc, encoder/enc_bissc.c): hardware SPI in mode 3 (MA idles high, SLO
  sampled on rising edges), 64 clocks at 84 MHz / 32 = 2.6 MHz, single-turn only:
  `enc_res` (VESC Tool's "Encoder Counts") bits. The 64 bits are aligned on their first
  1, two bits dropped, the frame taken from the next 1 (the Start) as Start, CDS,
  `enc_res` bits, error, warning, CRC; the CRC checked, the error bit not.
"""

from __future__ import annotations

from cocotb.triggers import Timer
from cocotb.utils import get_sim_time

from common import PERIOD_NS
from prenc.board import biss


def _vesc_table() -> list[int]:
    """enc_bissc_init's table: POLY = 0x43."""
    table = []
    for i in range(64):
        crc = i
        for _ in range(6):
            crc = ((crc << 1) ^ 0x43) if crc & 0x20 else crc << 1
        table.append(crc & 0x3F)
    return table


VESC_CRC6 = _vesc_table()


class _Clocked:
    def __init__(self, dut, rate_hz: float, clk_hz: float, ma: str = "biss_ma", slo: str = "biss_slo"):
        self.ma, self.slo = getattr(dut, ma), getattr(dut, slo)
        self.half_ps = round(clk_hz / rate_hz / 2 * PERIOD_NS * 1000)
        self.ma.value = 1

    def _slo(self) -> int:
        return int(self.slo.value)


class OnStepX(_Clocked):
    LAYOUTS = {"AS37_H39B_B": (16, 23, True), "JTW_24BIT": (0, 24, False), "JTW_26BIT": (0, 26, False)}

    def __init__(self, dut, clk_hz: float, layout: str, rate_hz: float = 4e6, **kw):
        super().__init__(dut, rate_hz, clk_hz, **kw)
        self.mt, self.st, self.error_high = self.LAYOUTS[layout]

    async def _pulse(self) -> int:
        """MA low; SLO read half-way through the low phase; MA high."""
        self.ma.value = 0
        await Timer(self.half_ps // 2, unit="ps")
        bit = self._slo()
        await Timer(self.half_ps - self.half_ps // 2, unit="ps")
        self.ma.value = 1
        await Timer(self.half_ps, unit="ps")
        return bit

    async def read(self, on_start=None) -> tuple[bool, int, int, float]:
        """(good, turns, count, the time of MA's first falling edge in ns)."""
        started = get_sim_time("ns")
        if on_start:
            on_start()
        found_ack = found_start = found_cds = False
        for _ in range(20):
            if await self._pulse() == 0:
                found_ack = True
                break
        if found_ack:
            for _ in range(20):
                if await self._pulse() == 1:
                    found_start = True
                    break
        bits: list[int] = []
        if found_start:
            found_cds = await self._pulse() == 0
            if found_cds:
                for _ in range(self.mt + self.st + 2 + 6):
                    bits.append(await self._pulse())
        self.ma.value = 0               # "send a CDM (invert)"
        await Timer(4 * self.half_ps, unit="ps")
        self.ma.value = 1
        if not (found_ack and found_start and found_cds):
            return False, 0, 0, started
        data = bits[:self.mt + self.st + 2]
        crc = 0
        for b in bits[-6:]:
            crc = crc << 1 | b
        error_bit = data[-2]
        good = (~biss.crc6(data) & 0x3F) == crc and (error_bit == 0 if self.error_high else error_bit == 1)
        value = 0
        for b in data[:-2]:
            value = value << 1 | b
        return good, value >> self.st, value & ((1 << self.st) - 1), started


class Vesc(_Clocked):
    def __init__(self, dut, clk_hz: float, enc_res: int, rate_hz: float = 84e6 / 32, **kw):
        super().__init__(dut, rate_hz, clk_hz, **kw)
        self.enc_res = enc_res

    async def read(self, on_start=None) -> tuple[bool, int, int, float]:
        """(CRC good, the frame's nE bit (which VESC ignores), position, the time of MA's
        first falling edge in ns)."""
        started = get_sim_time("ns")
        if on_start:
            on_start()
        raw = 0
        for _ in range(64):
            self.ma.value = 0
            await Timer(self.half_ps, unit="ps")
            self.ma.value = 1
            raw = raw << 1 | self._slo()   # sampled on the rising edge
            await Timer(self.half_ps, unit="ps")
        return (*self.decode(raw), started)

    def decode(self, raw: int) -> tuple[bool, int, int]:
        """compute_bissc_callback's arithmetic, on 64 bits: (CRC good, nE, position)."""
        n = self.enc_res
        if raw == 0:
            return False, 0, 0
        raw = (raw << (64 - raw.bit_length())) & (2**64 - 1)
        raw &= 0x3FFFFFFFFFFFFFFF
        bits = raw.bit_length()
        if bits >= n + 10:
            raw >>= bits - (n + 10)
        crc_rx = raw & 0x3F
        data = (raw >> 6) & ((1 << (n + 2)) - 1)
        position = (data >> 2) & ((1 << n) - 1)
        crc = data >> 30 & 0x03       # its table-driven CRC, six bits at a time
        for shift in (24, 18, 12, 6, 0):
            crc = VESC_CRC6[((data >> shift) & 0x3F) ^ crc]
        crc = 0x3F & ~crc             # "CRC is output inverted"
        return crc == crc_rx, data >> 1 & 1, position
