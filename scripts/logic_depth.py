#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Logic depth of a synthesized iCE40 netlist: how many LUT levels feed each flip-flop.

    python scripts/synth.py --core ice40-hx8k            # writes build/synth/ice40-hx8k/prenc_core.json
    python scripts/logic_depth.py build/synth/ice40-hx8k/prenc_core.json
    python scripts/logic_depth.py NETLIST --min 6 --paths 3

Fmax on the iCE40 is set by LUT levels (about 1.0 to 1.5 ns each once placed) more
than by anything else, but nextpnr reports one path per clock, and the seed moves
which one. This counts, on the Yosys netlist before placement, every flip-flop and
block-RAM input: LUT = 1 level, a carry stage = 0.12 (a carry chain's ripple), so
an input at 6 levels is a path that 120 MHz cannot afford on the HX8K. It prints how
many inputs sit at each depth, then the deepest registers (a register's bits
together) with the nets of one path: kept nets (`(* keep *)`) keep their RTL names.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path

LUT, CARRY = 1.0, 0.12
SINKS = {"D", "E", "R", "S"}                               # flip-flop inputs
RAM_SINKS = {"RADDR", "WADDR", "WDATA", "WE", "RE", "MASK"}  # SB_RAM40_4K inputs


class Netlist:
    """The top module of a Yosys JSON netlist, as drivers and depths of its bits."""

    def __init__(self, data: dict, top: str | None = None):
        modules = data.get("modules", {})
        if top is None:
            tops = [n for n, m in modules.items() if m.get("attributes", {}).get("top")]
            top = tops[0] if tops else next(iter(modules), None)
        if top not in modules:
            raise ValueError(f"no module {top!r} in the netlist (has: {', '.join(modules) or 'none'})")
        self.module = modules[top]
        self.cells = self.module.get("cells", {})
        self.names: dict[int, str] = {}
        for name, net in self.module.get("netnames", {}).items():
            for i, bit in enumerate(net["bits"]):
                if not isinstance(bit, int):
                    continue
                label = name if len(net["bits"]) == 1 else f"{name}[{i}]"
                old = self.names.get(bit)
                if old is None or (old.startswith("$") and not name.startswith("$")) or \
                        (old.startswith("$") == name.startswith("$") and len(label) < len(old)):
                    self.names[bit] = label
        self.driver: dict[int, str] = {}
        for name, cell in self.cells.items():
            for port, bits in cell["connections"].items():
                if cell.get("port_directions", {}).get(port) == "output":
                    for bit in bits:
                        if isinstance(bit, int):
                            self.driver[bit] = name
        self.depth: dict[int, float] = {}
        self.via: dict[int, int | None] = {}

    def level(self, bit) -> float:
        """LUT levels from the nearest register, block RAM or input to this bit."""
        if not isinstance(bit, int):
            return 0.0
        stack = [bit]
        while stack:  # iterative: carry chains and deep cones would overflow recursion
            b = stack[-1]
            if b in self.depth:
                stack.pop()
                continue
            cell = self.cells.get(self.driver.get(b, ""))
            kind = cell["type"] if cell else ""
            if kind not in ("SB_LUT4", "SB_CARRY"):
                self.depth[b], self.via[b] = 0.0, None  # a register, RAM, input or constant
                stack.pop()
                continue
            ports = ("I0", "I1", "I2", "I3") if kind == "SB_LUT4" else ("I0", "I1", "CI")
            ins = [x for p in ports for x in cell["connections"].get(p, []) if isinstance(x, int)]
            todo = [x for x in ins if x not in self.depth]
            if todo:
                stack.extend(todo)
                continue
            best, via = 0.0, None
            step = LUT if kind == "SB_LUT4" else CARRY
            for x in ins:
                if self.depth[x] + step > best:
                    best, via = self.depth[x] + step, x
            self.depth[b], self.via[b] = (best if ins else 0.0), via
            stack.pop()
        return self.depth[bit]

    def endpoints(self) -> list[tuple[float, str, int]]:
        """(levels, register input, bit) for every flip-flop and block-RAM input."""
        out = []
        for name, cell in self.cells.items():
            kind = cell["type"]
            if kind.startswith("SB_DFF"):
                q = cell["connections"].get("Q", [None])[0]
                reg = self.names.get(q, name) if isinstance(q, int) else name
                ports = SINKS
            elif kind == "SB_RAM40_4K":
                reg, ports = name, RAM_SINKS
            else:
                continue
            for port in sorted(ports & set(cell["connections"])):
                for bit in cell["connections"][port]:
                    if isinstance(bit, int):
                        out.append((round(self.level(bit), 2), f"{reg}.{port}", bit))
        return sorted(out, key=lambda e: -e[0])

    def path(self, bit: int) -> list[str]:
        """The nets of the deepest path into `bit`, from its source."""
        nets = []
        while isinstance(bit, int):
            nets.append(self.names.get(bit, f"${bit}"))
            bit = self.via.get(bit)
        return nets[::-1]


def report(net: Netlist, minimum: float, paths: int, top: int) -> str:
    ends = net.endpoints()
    lines = [f"{len(ends)} register inputs; LUT levels (carry stage = {CARRY}):"]
    histogram = Counter(int(levels) for levels, _, _ in ends)
    for levels in sorted(histogram):
        lines.append(f"  {levels:2d} levels: {histogram[levels]}")
    deep = [e for e in ends if e[0] >= minimum]
    lines.append(f"{len(deep)} inputs at {minimum:g} levels or more:")
    groups: dict[str, list[float]] = defaultdict(list)
    for levels, name, _ in deep:
        groups[re.sub(r"\[\d+\]", "", name)].append(levels)
    for name, levels in sorted(groups.items(), key=lambda kv: (-max(kv[1]), kv[0]))[:top]:
        lines.append(f"  {max(levels):5.2f}  {len(levels):3d} bit(s)  {name}")
    shown = set()
    for levels, name, bit in deep:
        key = re.sub(r"\[\d+\]", "", name)
        if len(shown) >= paths:
            break
        if key in shown:
            continue
        shown.add(key)
        lines.append(f"path into {name} ({levels:.2f}):")
        lines += [f"    {n}" for n in net.path(bit)]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("netlist", type=Path, help="Yosys JSON of an iCE40 synthesis (synth.py writes one)")
    parser.add_argument("--top", help="module (default: the netlist's top)")
    parser.add_argument("--min", type=float, default=6.0, help="list inputs this deep or deeper (default 6)")
    parser.add_argument("--paths", type=int, default=0, help="print the nets of this many deepest paths")
    parser.add_argument("--groups", type=int, default=40, help="at most this many registers listed (40)")
    args = parser.parse_args(argv)
    try:
        data = json.loads(args.netlist.read_text())
        net = Netlist(data, args.top)
    except (OSError, ValueError) as err:
        print(f"logic_depth: error: {err}", file=sys.stderr)
        return 1
    if not any(c["type"] == "SB_LUT4" for c in net.cells.values()):
        print(f"logic_depth: error: {args.netlist} has no SB_LUT4: not an iCE40 netlist", file=sys.stderr)
        return 1
    print(report(net, args.min, args.paths, args.groups))
    return 0


if __name__ == "__main__":
    sys.exit(main())
