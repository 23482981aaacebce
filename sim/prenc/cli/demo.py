# SPDX-License-Identifier: Apache-2.0
"""`prenc demo`: the default ROM and the virtual encoder on a short trajectory.

Until the reader core exists this shows the ground it will stand on: the
conversion ROM of the default disc, the four signals the reader's pins will see,
and the true position beside them, for a short motion with a reversal exactly at a
sampling instant. At each mid-slot A edge it prints the code word W(p) that a
correct reader holds there and what the ROM converts it to.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..virtual.encoder import Disc, VirtualEncoder
from ..codes.rom import write_rom
from ..virtual.trajectory import Trajectory

CLK_HZ = 1e6  # a slow clock keeps the picture readable: 50 clocks per slot


def demo_trajectory() -> Trajectory:
    """CW from 100.3 to exactly 104.5 (A rises there), then CCW to 101.2, then rest."""
    return (
        Trajectory(clk_hz=CLK_HZ, start=100.3)
        .rest(20e-6)
        .move_to(104.5, speed=2e4)
        .move_to(101.2, speed=2e4)
        .rest(20e-6)
    )


def mid_slot_edges(run) -> list[tuple[int, str]]:
    """Clocks where A changes with B low: A rising is the CW sampling instant,
    A falling the CCW one (datasheet, Synchronization track)."""
    a, b = run.a.astype(int), run.b.astype(int)
    out = []
    for c in (np.flatnonzero(a[1:] != a[:-1]) + 1).tolist():
        if b[c] == 0:
            out.append((c, "CW" if a[c] else "CCW"))
    return out


def waveform(values: np.ndarray, step: int) -> str:
    return "".join("\u2580" if v else "_" for v in values[::step])


def run_demo(out_dir: str | Path) -> None:
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    disc = Disc(10)
    code = disc.code

    rom_path = out / "prenc_rom_n10.hex"
    write_rom(rom_path, 10, (10, 3), "hex")
    rom = [int(line, 16) for line in rom_path.read_text().split()]
    print(f"ROM   {rom_path}: {len(rom)} words (address w(p) -> data p), N=10, taps 10,3")
    print(f"      line 512 (W(0) = 1000000000) holds {rom[512]}, line 0 holds {rom[0]}, "
          f"line 1 holds {rom[1]}")

    traj = demo_trajectory()
    run = VirtualEncoder(disc).run(traj)
    print(f"\nTrajectory: {len(run)} clocks at {CLK_HZ / 1e6:g} MHz, theta 100.3 -> 104.5 (CW) "
          f"-> 101.2 (CCW), reversal exactly at mid-slot 104.5")

    step = 4
    print(f"\nSignals (one column = {step} clocks)")
    slot_row = "".join(str(p % 10) for p in run.slot[::step])
    print(f"  slot p mod 10 {slot_row}")
    for name in ("a", "b", "head1", "head2"):
        print(f"  {name:<13} {waveform(run.signals[name], step)}")

    print("\nSampling instants: the word a reader holds there and what the ROM gives")
    print("  clock  dir  theta    p   q  head1 head2  W(p)        ROM[W(p)]")
    for clock, direction in mid_slot_edges(run):
        p = int(run.slot[clock])
        word = code.window(p)
        print(f"  {clock:5d}  {direction:<3}  {run.theta[clock]:7.3f} {p:4d}  {int(run.quarter[clock])}"
              f"    {int(run.head1[clock])}     {int(run.head2[clock])}    "
              f"{word:010b}  {rom[word]:4d}")

    png = out / "virtual_encoder.png"
    plot(run, png)
    print(f"\nPlot  {png}")


def plot(run, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = np.arange(len(run))
    fig, axes = plt.subplots(5, 1, figsize=(11, 7), sharex=True,
                             gridspec_kw={"height_ratios": [3, 1, 1, 1, 1]})
    axes[0].plot(t, run.theta, color="black", linewidth=1)
    axes[0].set_ylabel("theta\n(slots)")
    for k in range(int(np.floor(run.theta.min())), int(np.ceil(run.theta.max())) + 1):
        axes[0].axhline(k, color="0.85", linewidth=0.5)
        axes[0].axhline(k + 0.5, color="0.85", linewidth=0.5, linestyle=":")
    for clock, direction in mid_slot_edges(run):
        for ax in axes:
            ax.axvline(clock, color="tab:red" if direction == "CW" else "tab:blue", linewidth=0.6)
    names = {"a": "A", "b": "B", "head1": "head 1", "head2": "head 2"}
    for ax, (key, label) in zip(axes[1:], names.items()):
        ax.step(t, run.signals[key], where="post", linewidth=1)
        ax.set_ylim(-0.2, 1.2)
        ax.set_yticks([0, 1])
        ax.set_ylabel(label)
    axes[-1].set_xlabel("clock (1 MHz); red: CW sampling instant (A rises), blue: CCW (A falls)")
    axes[0].set_title("Virtual encoder, default disc (N=10, taps 10,3): true angle and the four signals")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
