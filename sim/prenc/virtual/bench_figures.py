# SPDX-License-Identifier: Apache-2.0
"""The figures of `make bench`, drawn from the same run as its tables.

scripts/bench.py collects what sections 4b (the core's goals), 9 (the fine position and
the velocity) and 10 (the calibration) measure into one dictionary; `write` keeps it in
docs/figures/bench.json and draws three SVG pictures from it:

- accuracy.svg: the position and the velocity error (RMS) against the speed, log axes,
  of ours and each baseline, on the ideal disc, the printed disc without a table and the
  printed disc with its calibration table (section 9's and 10's steady rows);
- calibration.svg: the table's error against the disc's true edges after K turns of a
  calibration run (section 10a);
- availability.svg: the core's share of valid clocks against the plain reader's, per
  scenario, beside the goal (section 4b, FILTER = 0).

The JSON also holds a digest of the model sources that the numbers come from (SOURCES);
a test (sim/tests/virtual/test_bench_figures.py) redraws the pictures from the JSON and
finds them equal to the committed ones, and finds the digest equal to today's sources,
so that a change of a model without a new bench run fails: `scripts/bench.py figures`
runs the three sections and writes the figures again.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

REPO = Path(__file__).resolve().parents[3]
FIGURES = REPO / "docs" / "figures"

# The sources that the figures' numbers come from (relative to the repository).
SOURCES = ("sim/prenc/fine/*.py", "sim/prenc/cal/*.py", "sim/prenc/core/*.py",
           "sim/prenc/virtual/fine_bench.py", "sim/prenc/virtual/cal_bench.py",
           "sim/prenc/virtual/previous_velocity.py", "sim/prenc/virtual/printing.py",
           "sim/prenc/virtual/edge_timing.py", "sim/prenc/virtual/trajectory.py",
           "sim/prenc/virtual/encoder.py", "sim/prenc/virtual/faults.py",
           "sim/prenc/virtual/goals.py", "sim/prenc/virtual/scenarios.py",
           "sim/prenc/virtual/plain_reader.py")

ESTIMATORS = ("ours", "ours, EDGE_TOLERANCE", "0.11", "period", "mixed", "count")
BASELINE_NAMES = ("coarse", "0.11", "period", "mixed", "count")   # drawn faded beside a table
COLOURS = {"ours": "tab:blue", "ours, EDGE_TOLERANCE": "tab:cyan", "0.11": "tab:purple", "period": "tab:green",
           "mixed": "tab:orange", "count": "tab:brown", "coarse": "0.6"}


def source_digest() -> str:
    """SHA-256 over the SOURCES' paths and contents, in path order."""
    h = hashlib.sha256()
    for path in sorted({p for pattern in SOURCES for p in REPO.glob(pattern)}):
        h.update(path.relative_to(REPO).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # Deterministic SVG: fixed element ids, no date.
    plt.rcParams["svg.hashsalt"] = "prenc-bench"
    plt.rcParams["svg.fonttype"] = "path"
    return plt


def _save(fig, path: Path) -> None:
    fig.savefig(path, format="svg", metadata={"Date": None})


def accuracy(data: dict, path: Path) -> None:
    """Position and velocity error (RMS) against speed: ideal, printed, calibrated."""
    plt = _pyplot()
    acc = data["accuracy"]
    panels = (("ideal disc", "ideal", None), ("printed disc, no table", "printed", None),
              ("printed disc, calibrated (ours with its table)", "calibrated", "printed"))
    fig, axes = plt.subplots(2, 3, figsize=(12, 6.6), sharex=True, sharey="row")
    for col, (title, key, faded) in enumerate(panels):
        ax_p, ax_v = axes[:, col]
        rows = acc[key]
        for name in ("coarse",) + ESTIMATORS:
            series = rows.get(name) or (acc[faded].get(name) if faded and name in BASELINE_NAMES else None)
            if not series:
                continue
            dim = name not in rows
            rpm = [r[0] for r in series]
            style = {"color": COLOURS[name], "marker": "o", "ms": 3.5, "lw": 2.2 if name.startswith("ours") else 1.2,
                     "alpha": 0.35 if dim else 1.0}
            label = {"coarse": "the quarter alone",
                     "ours, EDGE_TOLERANCE": f"ours, EDGE_TOLERANCE = {acc.get('edge_tolerance')}"}.get(name, name) \
                + (" (no table)" if dim else "")
            ax_p.plot(rpm, [r[1] for r in series], label=label, **style)
            if name != "coarse":
                ax_v.plot(rpm, [max(r[2], 1e-4) for r in series], label=label, **style)
        ax_p.set_title(title, fontsize=10)
        ax_v.set_xlabel("speed, rpm")
        for ax in (ax_p, ax_v):
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.grid(True, which="major", color="0.9")
        ax_p.axhline(1 / 256, color="0.4", lw=0.8, ls="--")
        ax_v.axhline(0.05, color="0.4", lw=0.8, ls="--")
    axes[0, 0].text(1.2, 1 / 256 * 1.15, "goal: 1/256 slot", fontsize=7, color="0.3")
    axes[1, 0].text(1.2, 0.05 * 1.15, "goal: 0.05 %", fontsize=7, color="0.3")
    axes[0, 0].set_ylabel("position error, slots RMS")
    axes[1, 0].set_ylabel("velocity error, % RMS")
    legend: dict[str, object] = {}
    for ax in (axes[0, 1], axes[1, 1]):   # every series once, as the printed disc's panel has it
        for handle, label in zip(*ax.get_legend_handles_labels()):
            legend.setdefault(label, handle)
    axes[0, 2].legend(list(legend.values()), list(legend), fontsize=7, loc="upper left",
                      bbox_to_anchor=(1.02, 1.0))
    axes[1, 2].text(0.03, 0.03, "faded: the others, without a table", transform=axes[1, 2].transAxes,
                    fontsize=7, color="0.3")
    fig.suptitle(f"Fine position and velocity against the true angle at the instant read, steady speeds "
                 f"(make bench 9 and 10; N = {data['n']}, {data['clk_mhz']:.0f} MHz)", fontsize=10)
    fig.tight_layout()
    _save(fig, path)
    plt.close(fig)


def calibration(data: dict, path: Path) -> None:
    """The calibration table's error against the turns of its run."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(9.5, 4.4))
    for run in data["calibration"]["runs"]:
        ax.plot([p[0] for p in run["turns"]], [p[1] for p in run["turns"]], marker="o", ms=3.5,
                label=run["name"])
    ax.axhline(1 / 128, color="0.4", lw=0.8, ls="--")
    ax.text(data["calibration"]["runs"][0]["turns"][0][0], 1 / 128 * 1.12, "goal: 1/128 slot", fontsize=7,
            color="0.3")
    ax.axhline(data["calibration"]["no_table"], color="0.6", lw=1.2)
    ax.text(data["calibration"]["runs"][0]["turns"][-1][0], data["calibration"]["no_table"] * 0.8,
            "no table: the printed disc's own edge errors", fontsize=7, color="0.3", ha="right", va="top")
    ax.set_yscale("log")
    ax.set_xticks([p[0] for p in data["calibration"]["runs"][0]["turns"]])
    ax.set_xlabel("turns of the calibration run")
    ax.set_ylabel("table's error against the true edges, slots RMS")
    ax.grid(True, which="major", color="0.9")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    ax.set_title("Self-calibration of the printed disc (make bench 10a; prenc.cal.calibrate)", fontsize=10)
    fig.tight_layout()
    _save(fig, path)
    plt.close(fig)


def availability(data: dict, path: Path) -> None:
    """The core's valid share against the plain reader's, per scenario, with the goal."""
    plt = _pyplot()
    rows = data["availability"]
    fig, ax = plt.subplots(figsize=(8.5, 5.0))
    y = list(range(len(rows)))[::-1]
    h = 0.38
    ax.barh([v + h / 2 for v in y], [r["core"] for r in rows], height=h, color="tab:blue", label="the core")
    ax.barh([v - h / 2 for v in y], [r["plain"] for r in rows], height=h, color="0.65",
            label="a plain verifying reader")
    for v, r in zip(y, rows):
        ax.plot([r["goal"], r["goal"]], [v - 0.45, v + 0.45], color="k", lw=1.5)
    ax.plot([], [], color="k", lw=1.5, label="the goal")
    ax.set_yticks(y, [r["scenario"].replace("_", " ") for r in rows], fontsize=8)
    ax.set_xlim(0, 1)
    ax.set_xlabel("share of clocks with a valid position (0 wrong valid positions in every scenario)")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=3)
    ax.set_title(f"The core against a plain reader (make bench 4b; N = {data['n']}, FILTER = 0)", fontsize=10)
    fig.tight_layout()
    _save(fig, path)
    plt.close(fig)


DRAWINGS = {"accuracy.svg": accuracy, "calibration.svg": calibration, "availability.svg": availability}


def draw(data: dict, out_dir: Path) -> list[Path]:
    out_dir.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, fn in DRAWINGS.items():
        fn(data, out_dir / name)
        paths.append(out_dir / name)
    return paths


def write(data: dict, out_dir: Path = FIGURES) -> list[Path]:
    """Keep `data` (with the sources' digest) in bench.json and draw the pictures."""
    data = dict(data, sources=source_digest())
    out_dir.mkdir(parents=True, exist_ok=True)
    (out_dir / "bench.json").write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")
    return [out_dir / "bench.json", *draw(data, out_dir)]


def load(out_dir: Path = FIGURES) -> dict:
    return json.loads((out_dir / "bench.json").read_text())
