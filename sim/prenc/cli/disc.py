# SPDX-License-Identifier: Apache-2.0
"""Printable discs: every code of the project as an SVG to print on film, with a PNG preview.

    prenc disc dual   [--bits N] [--taps a,b] [--shift D] [dimensions] -o disc.svg [--png disc.png]
    prenc disc matrix [--n N] [--checksum] [dimensions] -o disc.svg [--png disc.png]
    prenc disc template [--bits N] [dimensions] [--slit MM] -o template.svg [--png template.png]
                      (where the heads go: prenc.cli.disc_template)
    prenc disc nd     [--sequence S ...] [--phases a,b] [--n 10 --d 2 --length 170 --tracks 2]
                      [--circumference MM] [--height MM] -o strip.svg [--png strip.png]

Conventions, shared with the datasheet (docs/encoder-disc.md):
- Ink (black) is opaque; a cell that reads 1 is light (transparent), so ink marks 0.
- The disc is seen from the side the heads read; slot 0 starts at the index mark at
  12 o'clock and the code runs clockwise, as the angle theta increases.
- Sizes are millimetres; the SVG's width and height carry "mm", so a film printer
  prints it at scale. Every ring's radii are in the caption.

The dual-track disc, from the rim inwards: track 1, its inverted copy, track 2
(shifted by D slots), its inverted copy (for differential scanning: each head reads
a track and its complement and compares), then the sync track as two rings A and B
(A light in the second half of each slot, B light from a quarter before to a quarter
after the slot boundary: the datasheet's quadrature). A board that reads A and B from
one ring with two heads a quarter slot apart can leave ring B out (--no-ring-b).

The matrix disc has n rings, track 0 at the rim. The strip is a rectangle to wrap
around a cylinder: the parallel (n,d)-sequences as rows, track 0 on top.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from typing import Sequence

import numpy as np


@dataclass
class Ring:
    """A ring of equal cells: ink where the pattern is 0 (cells of 1 are light)."""

    name: str
    r_in: float
    r_out: float
    cells: np.ndarray  # 0/1 per cell, cell k spans [k, k+1) * 360 / len degrees
    sub: int = 1       # sub-cells per slot (the sync track has 4 per slot)


@dataclass
class Drawing:
    title: str
    rings: list[Ring] = field(default_factory=list)
    hole: float = 0.0          # centre hole diameter, mm
    outer: float = 0.0         # disc outline radius, mm
    strip: tuple[float, float] | None = None  # (width, height) for a strip, mm
    caption: list[str] = field(default_factory=list)


def _runs(cells: np.ndarray) -> list[tuple[int, int]]:
    """Runs of ink (cells == 0) as (start, length), merged across the wrap."""
    ink = cells == 0
    n = len(ink)
    if ink.all():
        return [(0, n)]
    if not ink.any():
        return []
    start = int(np.argmin(ink))  # a light cell: runs never cross it
    runs = []
    k = 0
    while k < n:
        i = (start + k) % n
        if ink[i]:
            length = 0
            while k < n and ink[(start + k) % n]:
                length += 1
                k += 1
            runs.append((i, length))
        else:
            k += 1
    return runs


def _polar(r: float, angle_deg: float, cx: float, cy: float) -> tuple[float, float]:
    a = math.radians(angle_deg)  # clockwise from 12 o'clock; SVG y points down
    return cx + r * math.sin(a), cy - r * math.cos(a)


def _sector_path(r0: float, r1: float, a0: float, a1: float, cx: float, cy: float) -> str:
    if a1 - a0 >= 360.0 - 1e-9:  # a whole ring: two half arcs each way
        return (_sector_path(r0, r1, 0.0, 180.0, cx, cy) + " "
                + _sector_path(r0, r1, 180.0, 360.0, cx, cy))
    large = 1 if a1 - a0 > 180.0 else 0
    x0, y0 = _polar(r1, a0, cx, cy)
    x1, y1 = _polar(r1, a1, cx, cy)
    x2, y2 = _polar(r0, a1, cx, cy)
    x3, y3 = _polar(r0, a0, cx, cy)
    return (f"M{x0:.4f},{y0:.4f}A{r1:.4f},{r1:.4f} 0 {large} 1 {x1:.4f},{y1:.4f}"
            f"L{x2:.4f},{y2:.4f}A{r0:.4f},{r0:.4f} 0 {large} 0 {x3:.4f},{y3:.4f}Z")


def to_svg(d: Drawing) -> str:
    margin, line = 4.0, 3.2
    if d.strip is None:
        size = 2 * d.outer + 2 * margin
        width, height = size, size + line * (len(d.caption) + 1)
        cx = cy = margin + d.outer
    else:
        width = d.strip[0] + 2 * margin
        height = d.strip[1] + 2 * margin + line * (len(d.caption) + 1)
    out = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.3f}mm" height="{height:.3f}mm" '
        f'viewBox="0 0 {width:.3f} {height:.3f}">',
        f"<title>{d.title}</title>",
        '<rect width="100%" height="100%" fill="white"/>',
    ]
    if d.strip is None:
        out.append(f'<circle cx="{cx:.4f}" cy="{cy:.4f}" r="{d.outer:.4f}" fill="none" '
                   'stroke="black" stroke-width="0.05"/>')
        for ring in d.rings:
            step = 360.0 / len(ring.cells)
            paths = [_sector_path(ring.r_in, ring.r_out, s * step, (s + n) * step, cx, cy)
                     for s, n in _runs(ring.cells)]
            out.append(f'<path id="{ring.name}" fill="black" d="{" ".join(paths)}"/>')
        if d.hole:
            out.append(f'<circle cx="{cx:.4f}" cy="{cy:.4f}" r="{d.hole / 2:.4f}" fill="none" '
                       'stroke="black" stroke-width="0.05"/>')
        # index mark: slot 0 starts here
        r = d.outer
        out.append(f'<path d="M{cx:.4f},{cy - r - 0.2:.4f}l-0.8,-1.6h1.6Z" fill="black"/>')
        text_y = margin + 2 * d.outer + margin
    else:
        w, h = d.strip
        out.append(f'<rect x="{margin}" y="{margin}" width="{w:.4f}" height="{h:.4f}" fill="none" '
                   'stroke="black" stroke-width="0.05"/>')
        for ring in d.rings:  # rows: r_in/r_out are y offsets from the top
            step = w / len(ring.cells)
            rects = [f"M{margin + s * step:.4f},{margin + ring.r_in:.4f}h{n * step:.4f}"
                     f"v{ring.r_out - ring.r_in:.4f}h{-n * step:.4f}Z" for s, n in _runs(ring.cells)
                     if s + n <= len(ring.cells)]
            wrap = [(s, n) for s, n in _runs(ring.cells) if s + n > len(ring.cells)]
            for s, n in wrap:  # a run across the seam: draw both pieces
                first = len(ring.cells) - s
                rects.append(f"M{margin + s * step:.4f},{margin + ring.r_in:.4f}h{first * step:.4f}"
                             f"v{ring.r_out - ring.r_in:.4f}h{-first * step:.4f}Z")
                rects.append(f"M{margin:.4f},{margin + ring.r_in:.4f}h{(n - first) * step:.4f}"
                             f"v{ring.r_out - ring.r_in:.4f}h{-(n - first) * step:.4f}Z")
            out.append(f'<path id="{ring.name}" fill="black" d="{"".join(rects)}"/>')
        text_y = margin + d.strip[1] + margin
    for i, text in enumerate(d.caption):
        out.append(f'<text x="{margin}" y="{text_y + line * i:.3f}" font-family="sans-serif" '
                   f'font-size="2.2">{text}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def to_png(d: Drawing, path, pixels: int = 1000) -> None:
    """A preview of the same shapes with matplotlib (not for printing)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Circle, Rectangle, Wedge

    patches = []
    if d.strip is None:
        fig = plt.figure(figsize=(5, 5 + 0.25 * len(d.caption)), dpi=pixels / 5)
        ax = fig.add_axes((0, 0.05 * len(d.caption) / 2, 1, 1 - 0.05 * len(d.caption) / 2))
        for ring in d.rings:
            step = 360.0 / len(ring.cells)
            for s, n in _runs(ring.cells):
                a0, a1 = s * step, (s + n) * step
                patches.append(Wedge((0, 0), ring.r_out, 90 - a1, 90 - a0, width=ring.r_out - ring.r_in))
        ax.add_collection(PatchCollection(patches, facecolor="black", edgecolor="none", linewidth=0))
        ax.add_patch(Circle((0, 0), d.outer, fill=False, linewidth=0.5))
        if d.hole:
            ax.add_patch(Circle((0, 0), d.hole / 2, fill=False, linewidth=0.5))
        ax.plot([0], [d.outer * 1.03], marker="v", color="black", markersize=5)
        lim = d.outer * 1.06
        ax.set_xlim(-lim, lim)
        ax.set_ylim(-lim, lim)
    else:
        w, h = d.strip
        fig = plt.figure(figsize=(10, 10 * (h / w) + 0.4 + 0.2 * len(d.caption)), dpi=pixels / 10)
        ax = fig.add_axes((0.01, 0.3, 0.98, 0.65))
        for ring in d.rings:
            step = w / len(ring.cells)
            for s, n in _runs(ring.cells):
                for s0, n0 in ([(s, n)] if s + n <= len(ring.cells)
                               else [(s, len(ring.cells) - s), (0, s + n - len(ring.cells))]):
                    patches.append(Rectangle((s0 * step, h - ring.r_out), n0 * step, ring.r_out - ring.r_in))
        ax.add_collection(PatchCollection(patches, facecolor="black", edgecolor="none", linewidth=0))
        ax.add_patch(Rectangle((0, 0), w, h, fill=False, linewidth=0.5))
        ax.set_xlim(-1, w + 1)
        ax.set_ylim(-1, h + 1)
    ax.set_aspect("equal")
    ax.axis("off")
    fig.text(0.02, 0.01, "\n".join(d.caption), fontsize=7, va="bottom", family="sans-serif")
    fig.savefig(path)
    plt.close(fig)


def _rings_inward(specs: Sequence[tuple[str, np.ndarray]], outer: float, width: float,
                  gap: float) -> list[Ring]:
    rings, r = [], outer
    for name, cells in specs:
        rings.append(Ring(name, r - width, r, cells))
        r -= width + gap
    return rings


def dual_disc(bits: int = 10, taps=None, shift: int | None = None, outer: float = 30.0,
              width: float = 1.2, gap: float = 0.3, hole: float = 6.0, ring_b: bool = True) -> Drawing:
    from ..codes.debruijn import Code
    from ..virtual.encoder import default_shift
    from ..codes.lfsr import check_bits

    code = Code(check_bits(bits, 2, 16), taps)
    d = default_shift(code.n) if shift is None else shift
    if not 0 <= d < code.length:
        raise ValueError(f"track shift D = {d} is out of range 0..{code.length - 1}")
    s = np.asarray(code.sequence, dtype=np.uint8)
    t2 = np.roll(s, -d)
    # sync: 4 quarters per slot; A light for q = 2, 3; B light for q = 3, 0
    q = np.tile(np.arange(4), code.length)
    a = (q >= 2).astype(np.uint8)
    b = ((q == 3) | (q == 0)).astype(np.uint8)
    specs = [("track1", s), ("track1_inverted", 1 - s), ("track2", t2), ("track2_inverted", 1 - t2),
             ("sync_a", a)] + ([("sync_b", b)] if ring_b else [])
    rings = _rings_inward(specs, outer, width, gap)
    _check_fits(rings, hole)
    slot_um = 2 * math.pi * rings[-1].r_in / code.length * 1000
    caption = [
        f"prenc dual-track disc: N={code.n}, taps {','.join(map(str, code.taps))}, D={d}, "
        f"{code.length} slots; ink = 0",
        *_ring_lines(rings),
        f"index mark at slot 0, code clockwise; narrowest slot {slot_um:.0f} um; hole {hole} mm",
    ]
    return Drawing(f"prenc dual-track disc N={code.n}", rings, hole, outer, None, caption)


def matrix_disc(n: int = 3, checksum: bool = False, outer: float = 30.0, width: float = 2.0,
                gap: float = 0.0, hole: float = 6.0) -> Drawing:
    from ..matrix.code import MatrixCode

    code = MatrixCode(n, checksum)
    cells = code.cells()
    rings = _rings_inward([(f"track{t}", cells[t]) for t in range(n)], outer, width, gap)
    _check_fits(rings, hole)
    cell_um = 2 * math.pi * rings[-1].r_in / code.length * 1000
    caption = [
        f"prenc matrix-code disc: n={n}{' with parity track' if checksum else ''}, "
        f"{code.length} positions, every {n}x{n} window once; ink = 0",
        *_ring_lines(rings),
        f"index mark at position 0, code clockwise; narrowest cell {cell_um:.1f} um; hole {hole} mm",
    ]
    if cell_um < 20:
        sys.stderr.write(f"warning: the narrowest cell is {cell_um:.1f} um: too fine for film; "
                         "use a larger --outer-radius or a smaller n\n")
    return Drawing(f"prenc matrix-code disc n={n}", rings, hole, outer, None, caption)


def nd_strip(sequences: Sequence[str] | None = None, phases: Sequence[int] | None = None,
             n: int = 10, d: int = 2, length: int = 170, tracks: int = 2,
             circumference: float | None = None, height: float = 12.0) -> Drawing:
    from ..nd.phasing import best_phasing
    from ..nd.sequence import as_bits, check

    if sequences:
        seqs = [as_bits(s) for s in sequences]
        if len({len(s) for s in seqs}) != 1:
            raise ValueError("all sequences of a strip must have the same length")
    else:
        from ..nd.beam import sequence_of_length

        seq = sequence_of_length(n, d, length)
        if seq is None:
            raise ValueError(f"no ({n},{d})-sequence of length {length} found")
        seqs = [as_bits(seq)] * tracks
    dist = [check(s, n, 1) for s in seqs]
    if phases is None:
        phases = best_phasing(seqs, n).phases if len(seqs) > 1 else [0]
    if len(phases) != len(seqs):
        raise ValueError("give one phase per sequence")
    k = len(seqs[0])
    circumference = 2 * math.pi * 55.0 if circumference is None else circumference
    row = height / len(seqs)
    rings = []
    for j, (s, ph) in enumerate(zip(seqs, phases)):
        bits = np.array([int(c) for c in s], dtype=np.uint8)
        rings.append(Ring(f"track{j}", j * row, (j + 1) * row, np.roll(bits, -int(ph))))
    caption = [
        f"prenc (n,d)-sequence strip: {len(seqs)} tracks of K={k} bits, n={n}, phases "
        f"{','.join(map(str, phases))}; min window distance per track {','.join(map(str, dist))}; ink = 0",
        f"{circumference:.2f} x {height:.2f} mm: wraps once around a cylinder of radius "
        f"{circumference / (2 * math.pi):.2f} mm; bit pitch {circumference / k * 1000:.0f} um; track 0 on top",
    ]
    return Drawing("prenc (n,d)-sequence strip", rings, 0.0, 0.0, (circumference, height), caption)


def _ring_lines(rings: list[Ring]) -> list[str]:
    """The rings' radii, three to a caption line."""
    parts = [f"{r.name} {r.r_in:.2f}-{r.r_out:.2f} mm" for r in rings]
    lines = [", ".join(parts[i:i + 3]) for i in range(0, len(parts), 3)]
    return ["rings from the rim: " + lines[0]] + ["    " + line for line in lines[1:]]


def _check_fits(rings: list[Ring], hole: float) -> None:
    if rings[-1].r_in <= hole / 2:
        raise ValueError(f"the rings reach radius {rings[-1].r_in:.2f} mm, inside the "
                         f"{hole} mm hole: use a larger --outer-radius or narrower rings")


def write(drawing: Drawing, svg_path: str, png_path: str | None) -> None:
    from ..codes.rom import write_atomically

    text = to_svg(drawing)
    write_atomically(svg_path, lambda: text.encode())
    if png_path:
        to_png(drawing, png_path)


def _cmd(args) -> None:
    if args.kind == "dual":
        drawing = dual_disc(args.bits, args.taps, args.shift, args.outer_radius, args.ring_width,
                            args.gap, args.hole, not args.no_ring_b)
    elif args.kind == "matrix":
        drawing = matrix_disc(args.n, args.checksum, args.outer_radius, args.ring_width, args.gap,
                              args.hole)
    else:
        drawing = nd_strip(args.sequence, args.phases, args.n, args.d, args.length, args.tracks,
                           args.circumference, args.height)
    write(drawing, args.output, args.png)
    if args.output != "-":
        sys.stderr.write("\n".join(drawing.caption) + "\n")


def _template_cmd(args) -> None:
    from . import disc_template

    disc = dual_disc(args.bits, args.taps, args.shift, args.outer_radius, args.ring_width, args.gap, args.hole,
                     not args.no_ring_b)
    tp = disc_template.template(disc, args.bits, args.slit, args.sensor_width, args.sync_offset)
    disc_template.write(tp, args.output, args.png, to_svg(disc) if args.with_disc else None)
    if args.output != "-":
        sys.stderr.write("\n".join(tp.caption) + "\n")


def add_parser(sub) -> None:
    from .arguments import taps_arg

    disc = sub.add_parser("disc", help="draw a code as an SVG to print on film (+ PNG preview)")
    kinds = disc.add_subparsers(dest="kind", required=True, parser_class=type(disc))

    def common(p, outer: float, width: float, gap: float) -> None:
        p.add_argument("--output", "-o", required=True, metavar="FILE.svg", help="SVG to write (- for stdout)")
        p.add_argument("--png", metavar="FILE.png", help="also write a PNG preview")
        if outer:
            p.add_argument("--outer-radius", type=float, default=outer, metavar="MM",
                           help=f"radius of the outermost ring's outer edge (default {outer})")
            p.add_argument("--ring-width", type=float, default=width, metavar="MM",
                           help=f"radial width of each ring (default {width})")
            p.add_argument("--gap", type=float, default=gap, metavar="MM",
                           help=f"clear gap between rings (default {gap})")
            p.add_argument("--hole", type=float, default=6.0, metavar="MM",
                           help="shaft hole diameter, drawn as a circle (default 6)")

    dual = kinds.add_parser("dual", help="the default disc: two code tracks, inverted copies, sync A/B")
    dual.add_argument("--bits", "-n", type=int, default=10, metavar="N", help="code word length (default 10)")
    dual.add_argument("--taps", type=taps_arg, default=None, metavar="a,b,...")
    dual.add_argument("--shift", "-d", type=int, default=None, metavar="D",
                      help="track 2 shift in slots (default 2^(N-1)+N-1)")
    dual.add_argument("--no-ring-b", action="store_true", help="leave out sync ring B")
    common(dual, 30.0, 1.2, 0.3)
    dual.set_defaults(func=_cmd)

    template = kinds.add_parser("template", help="where the heads go on the dual-track disc: a template "
                                "for the board, or a slit mask on film")
    template.add_argument("--bits", "-n", type=int, default=10, metavar="N", help="code word length (default 10)")
    template.add_argument("--taps", type=taps_arg, default=None, metavar="a,b,...")
    template.add_argument("--shift", "-d", type=int, default=None, metavar="D",
                          help="track 2 shift in slots (default 2^(N-1)+N-1)")
    template.add_argument("--no-ring-b", action="store_true", help="the disc has no sync ring B: B read on ring A")
    template.add_argument("--slit", type=float, default=None, metavar="MM",
                          help="each head's slit width (default a quarter of the narrowest slot)")
    template.add_argument("--with-disc", action="store_true",
                          help="the disc beside the template in one SVG: the disc and its slit masks on one film")
    template.add_argument("--sync-offset", type=int, default=0, metavar="K",
                          help="the sync pair K whole slots clockwise of head 1 (default 0)")
    template.add_argument("--sensor-width", type=float, default=4.0, metavar="MM",
                          help="how far apart the two sync sensors must be without ring B (default 4)")
    common(template, 30.0, 1.2, 0.3)
    template.set_defaults(func=_template_cmd)

    matrix = kinds.add_parser("matrix", help="a matrix-code disc of n tracks")
    matrix.add_argument("--n", type=int, default=3, choices=(2, 3, 4), help="tracks (default 3)")
    matrix.add_argument("--checksum", action="store_true", help="the code with the parity track")
    common(matrix, 30.0, 2.0, 0.0)
    matrix.set_defaults(func=_cmd)

    nd = kinds.add_parser("nd", help="a strip of parallel (n,d)-sequences for a cylinder")
    nd.add_argument("--sequence", action="append", help="a track's bits (repeat per track)")
    nd.add_argument("--phases", type=taps_arg, default=None, metavar="a,b,...",
                    help="phase of each track (default: the best phasing of equation 1)")
    nd.add_argument("--n", type=int, default=10, help="window length n (default 10)")
    nd.add_argument("--d", type=int, default=2, help="minimum distance, when generating (default 2)")
    nd.add_argument("--length", type=int, default=170, help="K, when generating (default 170)")
    nd.add_argument("--tracks", type=int, default=2, help="parallel tracks, when generating (default 2)")
    nd.add_argument("--circumference", type=float, default=None, metavar="MM",
                    help="strip length (default: a cylinder of radius 55 mm, 345.58 mm)")
    nd.add_argument("--height", type=float, default=12.0, metavar="MM", help="strip height (default 12)")
    common(nd, 0.0, 0.0, 0.0)
    nd.set_defaults(func=_cmd)
