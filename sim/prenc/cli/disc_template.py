# SPDX-License-Identifier: Apache-2.0
"""`prenc disc template`: where the heads go, drawn at 1:1 for the dual-track disc.

    prenc disc template [--bits N] [dimensions of prenc disc dual] [--no-ring-b]
                        [--slit MM] [--sensor-width MM] -o template.svg [--png template.png]

The drawing has the disc's outline, its rings' edges and its hole, and for every head a
dark patch with a clear slit where the head reads (a slit `--slit` mm wide across the
ring). Printed on paper it is a template to mark the sensors' places on the board; printed
on film with the disc, the patches are a slit mask to lay between a sensor and the disc
(docs/guide/building-the-encoder.md). The caption gives each head's place (angle and x, y
from the disc's centre, millimetres, y towards the index mark) and checks the slit.

Placement (the datasheet, docs/encoder-disc.md; angles clockwise from the index mark, as
seen from the heads' side, where the code runs clockwise):

- head 1 reads track 1 (and its inverted copy, for a differential head) at 0 degrees;
- head 2 reads track 2 (and its copy) at 180 degrees, half a turn away;
- the sync heads read A and B beside head 1 at 0 degrees, on rings A and B, or a whole
  number of slots clockwise of it (`--sync-offset K`: the room that sensors' bodies
  need; the reader's outputs are the same, sim/tests/cli/test_disc_template.py); a disc
  without ring B (`--no-ring-b`) is read by two heads on ring A, B's (k + 1/4) slots
  counter-clockwise from A's, k the fewest whole slots that put the two `--sensor-width`
  apart.

The slit: the sync track's light and dark cells are half a slot long, and a slit as wide
sees them only as a blur; so the slit must be under half a slot on every ring it reads
(an error otherwise), and a quarter of a slot (the default) keeps the edge where it is
printed when the comparator's threshold drifts (a drift of x of the light moves the edge
by x times the slit's width).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .disc import Drawing, Ring


@dataclass
class Head:
    name: str
    ring: Ring
    angle_deg: float       # clockwise from the index mark

    @property
    def radius(self) -> float:
        return (self.ring.r_in + self.ring.r_out) / 2

    def xy(self) -> tuple[float, float]:
        a = math.radians(self.angle_deg)
        return self.radius * math.sin(a), self.radius * math.cos(a)


@dataclass
class Template:
    bits: int
    outer: float
    hole: float
    rings: list[Ring]
    heads: list[Head]
    slit: float
    caption: list[str]


def slot_mm(ring: Ring, bits: int, radius: float | None = None) -> float:
    """A slot's length along the ring at `radius` (its inner edge by default), mm."""
    return 2 * math.pi * (ring.r_in if radius is None else radius) / (1 << bits)


def template(disc: Drawing, bits: int, slit: float | None = None, sensor_width: float = 4.0,
             sync_offset: int = 0) -> Template:
    """The heads' places on `disc` (prenc.cli.disc.dual_disc's drawing of an N = `bits` disc)."""
    rings = {r.name: r for r in disc.rings}
    ring_b = "sync_b" in rings
    outer, hole = disc.outer, disc.hole
    narrowest = min(slot_mm(r, bits) for r in disc.rings)
    if slit is None:
        slit = narrowest / 4
    if not 0 < slit < narrowest / 2:
        raise ValueError(f"--slit {slit} mm: a slit must be under half the narrowest slot ({narrowest / 2:.4f} mm "
                         f"of the {narrowest * 1000:.0f} um slot on the innermost ring), or it never sees the "
                         "sync track's half-slot cells whole; a larger --outer-radius or a smaller N widens the slots")
    if not 0 <= sync_offset < (1 << bits):
        raise ValueError(f"--sync-offset {sync_offset}: whole slots, 0..{(1 << bits) - 1}")
    degrees = 360.0 / (1 << bits)          # a slot
    sync = sync_offset * degrees
    heads = [Head("head 1", rings["track1"], 0.0), Head("head 1, inverted", rings["track1_inverted"], 0.0),
             Head("head 2", rings["track2"], 180.0), Head("head 2, inverted", rings["track2_inverted"], 180.0),
             Head("sync A", rings["sync_a"], sync)]
    if ring_b:
        heads.append(Head("sync B", rings["sync_b"], sync))
        b_note = "sync B on ring B beside sync A"
    else:
        ring = rings["sync_a"]
        slot = slot_mm(ring, bits, (ring.r_in + ring.r_out) / 2)
        k = max(0, math.ceil(sensor_width / slot - 0.25))
        heads.append(Head("sync B", ring, sync - (k + 0.25) * degrees))
        b_note = (f"sync B on ring A, {k + 0.25:g} slots counter-clockwise of sync A "
                  f"({(k + 0.25) * slot:.3f} mm apart, sensors {sensor_width} mm wide)")
    if sync_offset:
        b_note += f"; the sync pair {sync_offset} slots clockwise of head 1"
    caption = [f"prenc head template: N={bits}, the disc of prenc disc dual with the same dimensions "
               f"(outer radius {outer} mm); 1:1, millimetres",
               f"slits {slit * 1000:.0f} um wide (the narrowest slot {narrowest * 1000:.0f} um; a slit must be "
               f"under half a slot); {b_note}"]
    for h in heads:
        x, y = h.xy()
        caption.append(f"{h.name:<17} ring {h.ring.name:<16} r {h.radius:6.2f} mm at {h.angle_deg:8.3f} deg: "
                       f"x {x:+7.3f}, y {y:+7.3f} mm")
    return Template(bits, outer, hole, list(disc.rings), heads, slit, caption)


def _rectangle(h: Head, half_t: float, r0: float, r1: float) -> list[tuple[float, float]]:
    """Corners (x, y, y up) of a patch at the head's angle: tangential +-half_t, radial r0..r1."""
    a = math.radians(h.angle_deg)
    c, s = math.cos(a), math.sin(a)
    return [(r * s + t * c, r * c - t * s) for t, r in ((-half_t, r0), (half_t, r0), (half_t, r1), (-half_t, r1))]


def _shapes(tp: Template) -> list[tuple[str, list[tuple[float, float]]]]:
    """('ink' | 'clear', polygon) in drawing order: each head's patch, then its slit."""
    out = []
    for h in tp.heads:
        gap = 0.15
        out.append(("ink", _rectangle(h, 1.0, h.ring.r_in - gap, h.ring.r_out + gap)))
    for h in tp.heads:
        out.append(("clear", _rectangle(h, tp.slit / 2, h.ring.r_in, h.ring.r_out)))
    return out


def _labels(tp: Template) -> list[tuple[str, float]]:
    """The heads' names (not the inverted copies') grouped by angle, to the nearest 2 degrees."""
    groups: dict[int, list[Head]] = {}
    for h in tp.heads:
        if "inverted" not in h.name:
            groups.setdefault(round(h.angle_deg / 2), []).append(h)
    return [(", ".join(h.name for h in g), sum(h.angle_deg for h in g) / len(g)) for g in groups.values()]


def to_svg(tp: Template) -> str:
    margin, line = 4.0, 3.2
    size = 2 * tp.outer + 2 * margin
    width, height = size + 40.0, size + line * (len(tp.caption) + 1)
    cx = cy = margin + tp.outer

    def pt(x: float, y: float) -> str:
        return f"{cx + x:.4f},{cy - y:.4f}"

    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.3f}mm" height="{height:.3f}mm" '
           f'viewBox="0 0 {width:.3f} {height:.3f}">',
           f"<title>prenc head template N={tp.bits}</title>",
           '<rect width="100%" height="100%" fill="white"/>',
           f'<circle cx="{cx:.4f}" cy="{cy:.4f}" r="{tp.outer:.4f}" fill="none" stroke="black" stroke-width="0.1"/>',
           f'<circle cx="{cx:.4f}" cy="{cy:.4f}" r="{tp.hole / 2:.4f}" fill="none" stroke="black" '
           'stroke-width="0.1"/>',
           f'<path d="M{cx - 2:.4f},{cy:.4f}h4M{cx:.4f},{cy - 2:.4f}v4" stroke="black" stroke-width="0.1"/>',
           f'<path d="M{cx:.4f},{cy - tp.outer - 0.2:.4f}l-0.8,-1.6h1.6Z" fill="black"/>']
    for r in tp.rings:
        for radius in (r.r_in, r.r_out):
            out.append(f'<circle cx="{cx:.4f}" cy="{cy:.4f}" r="{radius:.4f}" fill="none" stroke="grey" '
                       'stroke-width="0.04" stroke-dasharray="0.5,0.5"/>')
    for kind, poly in _shapes(tp):
        fill = "black" if kind == "ink" else "white"
        out.append(f'<path fill="{fill}" d="M{" L".join(pt(x, y) for x, y in poly)}Z"/>')
    for names, angle in _labels(tp):
        a = math.radians(angle)
        r = tp.outer + 3
        x, y = r * math.sin(a), r * math.cos(a)
        out.append(f'<text x="{cx + x:.3f}" y="{cy - y:.3f}" font-family="sans-serif" font-size="2.2" '
                   f'text-anchor="{"start" if x > 0.5 else "end" if x < -0.5 else "middle"}">{names}</text>')
    text_y = margin + 2 * tp.outer + margin + 2
    for i, text in enumerate(tp.caption):
        out.append(f'<text x="{margin}" y="{text_y + line * i:.3f}" font-family="monospace" '
                   f'font-size="2.0" xml:space="preserve">{text}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def to_png(tp: Template, path, pixels: int = 1000) -> None:
    """A preview of the template (not for printing), with an inset of the heads at 0 degrees."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Polygon

    fig, (ax, zoom) = plt.subplots(1, 2, figsize=(10, 5.8), dpi=pixels / 10, width_ratios=[1, 1])
    for axis in (ax, zoom):
        axis.add_patch(Circle((0, 0), tp.outer, fill=False, lw=0.8))
        axis.add_patch(Circle((0, 0), tp.hole / 2, fill=False, lw=0.8))
        for r in tp.rings:
            for radius in (r.r_in, r.r_out):
                axis.add_patch(Circle((0, 0), radius, fill=False, lw=0.4, ls=":", color="0.5"))
        for kind, poly in _shapes(tp):
            axis.add_patch(Polygon(poly, closed=True, color="black" if kind == "ink" else "white", lw=0))
        axis.set_aspect("equal")
    lim = tp.outer * 1.25
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.plot([0], [tp.outer * 1.03], marker="v", color="black", markersize=5)
    for names, angle in _labels(tp):
        a = math.radians(angle)
        r = tp.outer * 1.13
        x, y = r * math.sin(a), r * math.cos(a)
        ax.text(x, y, names, fontsize=7, va="center", ha="left" if x > 0.5 else "right" if x < -0.5 else "center")
    ax.set_title(f"the heads' places (N = {tp.bits}, 1:1 in the SVG)", fontsize=9, pad=14)
    r_lo = min(r.r_in for r in tp.rings) - 0.6
    r_hi = tp.outer + 0.6
    zoom.set_xlim(-(r_hi - r_lo) / 2 - 1.5, (r_hi - r_lo) / 2 + 1.5)
    zoom.set_ylim(r_lo, r_hi)
    for r in tp.rings:
        zoom.text((r_hi - r_lo) / 2 + 1.4, (r.r_in + r.r_out) / 2, r.name, fontsize=7, ha="right", va="center")
    zoom.set_title(f"at the index mark: the slits ({tp.slit * 1000:.0f} um) over the rings", fontsize=9)
    zoom.set_xlabel("mm")
    import textwrap

    fig.text(0.01, 0.01, "\n".join(textwrap.fill(line, 140) for line in tp.caption[:2]), fontsize=7,
             va="bottom", family="monospace")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    fig.savefig(path)
    plt.close(fig)


def beside(*svgs: str, gap: float = 10.0) -> str:
    """One SVG with the drawings of `svgs` (each in millimetres, as prenc disc writes
    them) side by side, `gap` mm apart, at the same scale: the disc and its slit masks on
    one sheet of film."""
    parts, x, height = [], 0.0, 0.0
    for svg in svgs:
        head = re.search(r'<svg[^>]*width="([\d.]+)mm" height="([\d.]+)mm"[^>]*>', svg)
        body = svg[head.end():svg.rindex("</svg>")].replace('<rect width="100%" height="100%" fill="white"/>', "")
        parts.append(f'<g transform="translate({x:.3f},0)">{body}</g>')
        x += float(head.group(1)) + gap
        height = max(height, float(head.group(2)))
    width = x - gap
    return "\n".join(['<?xml version="1.0" encoding="UTF-8"?>',
                      f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.3f}mm" height="{height:.3f}mm" '
                      f'viewBox="0 0 {width:.3f} {height:.3f}">',
                      '<rect width="100%" height="100%" fill="white"/>', *parts, "</svg>"]) + "\n"


def write(tp: Template, svg_path: str, png_path: str | None, disc_svg: str | None = None) -> None:
    """The template's SVG (with `disc_svg`, the disc's beside it on one sheet) and PNG."""
    from ..codes.rom import write_atomically

    text = to_svg(tp) if disc_svg is None else beside(disc_svg, to_svg(tp))
    write_atomically(svg_path, lambda: text.encode())
    if png_path:
        to_png(tp, png_path)
