# SPDX-License-Identifier: Apache-2.0
"""The AS5047P's masters as the drives' firmware runs them, for testbenches: the command
words, frame pairs, SPI clock, sampling and checks of each, read from its source.

Each driver's `read(master)` returns (angle or None, CSn's falling time in ns of the
frame whose answer carries the angle); None when that firmware would drop the
sample (its parity and EF checks). A driver that checks nothing returns the data
whatever it is; the testbench then knows what that driver takes.

Sources (snapshots read for this file):
- ODrive v3 (odriverobotics/ODrive, Firmware/MotorControl/encoder.cpp,
  ENCODER_MODE_SPI_ABS_AMS): one frame 0xFFFF per control cycle on SPI3, 42 MHz / 16 =
  2.6 MHz; drops a sample with bad parity or EF (`ams_parity(rawVal) || rawVal >> 14 & 1`);
  pos = rawVal & 0x3FFF.
- SimpleFOC (simplefoc/Arduino-FOC, src/sensors/MagneticSensorSPI.cpp, AS5147_SPI):
  1 MHz; 0xFFFF, 1 us, then 0x0000, whose answer it takes; no check.
- SimpleFOC drivers' AS5047 (simplefoc/Arduino-FOC-drivers, src/encoders/as5047):
  8 MHz; getSensorAngle sends 0x7FFE (ANGLEUNC) twice and takes the second answer;
  a register read is its command then 0xFFFF; a write, command then data frame.
  Stores EF, checks nothing.
- Klipper (Klipper3d/klipper, src/sensor_angle.c, as5047d): 1 / 350 ns = 2.86 MHz, two
  bytes per frame; at start 0xFFFC, 0x4001, 0xC000 (clears the errors); then every
  sample 0x7FFE (ANGLEUNC) and 0xC000, taking the second answer; drops it on bad
  parity (SE_CRC) or EF (SE_NO_ANGLE).
- VESC (vedderb/bldc, encoder/enc_as504x.c, driver/spi_bb.c): bit-banged, about 3.5 MHz,
  MISO read just after each rising edge of SCLK (5 reads, a majority); with MOSI
  fitted 0xFFFF twice, the second answer taken; drops it on bad parity or EF.
- moteus (mjbots/moteus, fw/as5047.h, fw/stm32_spi.h): 0xFFFF once per control cycle,
  SPI at aux spi rate_hz (12 MHz asked: 170 MHz / 16 = 10.6 MHz); no check.
"""

from __future__ import annotations

from dataclasses import dataclass

from prenc.board import as5047 as spec
from spi_master import SpiMaster

ANGLE_READ = spec.read_command(spec.ANGLECOM)   # 0xFFFF
ANGLEUNC_READ = spec.read_command(spec.ANGLEUNC)  # 0x7FFE
NOP_READ = spec.read_command(spec.NOP)        # 0xC000


def checked(word: int) -> int | None:
    """The data of an answer that passes the parity and EF checks, else None."""
    a = spec.Answer(word)
    return a.data if a.parity_ok and not a.error else None


@dataclass
class Driver:
    name: str
    rate_hz: float
    checks: bool                     # drops frames with bad parity or EF
    sample_after_rise_ns: float | None = None
    byte_gap_ns: float = 0
    lead_ns: float = 400

    def master(self, dut, clk_hz: float) -> SpiMaster:
        return SpiMaster(dut, self.rate_hz, clk_hz, lead_ns=self.lead_ns,
                         sample_after_rise_ns=self.sample_after_rise_ns, byte_gap_ns=self.byte_gap_ns)

    async def start(self, m: SpiMaster) -> None:
        """What the firmware sends once at start."""

    async def read(self, m: SpiMaster) -> tuple[int | None, float]:
        raise NotImplementedError

    def take(self, word: int) -> int | None:
        return checked(word) if self.checks else word & 0x3FFF


class EveryCycle(Driver):
    """One 0xFFFF per control cycle, the answer being the previous frame's read:
    ODrive, moteus, VESC without MOSI (MOSI held high)."""

    async def read(self, m):
        opened = []
        word = await m.frame(ANGLE_READ, on_open=opened.append)
        return self.take(word), opened[0]


class Pair(Driver):
    """A read command, then a second frame whose answer is taken."""

    def __init__(self, name, rate_hz, checks, first, second, pause_ns=0.0, **kw):
        super().__init__(name, rate_hz, checks, **kw)
        self.first, self.second, self.pause_ns = first, second, pause_ns

    async def read(self, m):
        await m.frame(self.first)
        await m.wait_ns(self.pause_ns)
        opened = []
        word = await m.frame(self.second, on_open=opened.append)
        return self.take(word), opened[0]


class Klipper(Pair):
    async def start(self, m):
        for word in (spec.read_command(spec.DIAAGC), spec.read_command(spec.ERRFL), NOP_READ):
            await m.frame(word)


DRIVERS = {
    "odrive": EveryCycle("odrive", 42e6 / 16, checks=True),
    "simplefoc": Pair("simplefoc", 1e6, False, ANGLE_READ, 0x0000, pause_ns=1000),
    "simplefoc_as5047": Pair("simplefoc_as5047", 8e6, False, ANGLEUNC_READ, ANGLEUNC_READ),
    "klipper": Klipper("klipper", 1 / 350e-9, True, ANGLEUNC_READ, NOP_READ, byte_gap_ns=200),
    "vesc": Pair("vesc", 3.5e6, True, ANGLE_READ, ANGLE_READ, sample_after_rise_ns=60),
    "moteus": EveryCycle("moteus", 170e6 / 32, checks=False, lead_ns=200),
}
