# SPDX-License-Identifier: Apache-2.0
"""The documentation: `make docs` builds with no warning (warnings are errors), the pages
hold the rendered timing diagrams, the register map and a page per RTL module; every
module states its latency; the README stays a front door."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest

from runner import REPO

sys.path.insert(0, str(REPO / "docs" / "_ext"))
import prenc_modules  # noqa: E402

MODULES = sorted(REPO.glob("rtl/*/prenc_*.v"))


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    out = tmp_path_factory.mktemp("docs") / "html"
    proc = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-b", "html", "-q",
                           str(REPO / "docs"), str(out)], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-5000:]
    return out


def test_the_docs_build_without_a_warning(site):
    assert (site / "index.html").is_file()


@pytest.mark.parametrize("page,diagrams", [("interfaces/ssi.html", 1), ("biss-c.html", 1),
                                           ("host-protocol.html", 2), ("interfaces/strobe-timing.html", 1),
                                           ("fine.html", 2), ("interfaces/as5047.html", 1)])
def test_the_timing_diagrams_are_rendered_at_build_time(site, page, diagrams):
    html = (site / page).read_text()
    images = re.findall(r'<img[^>]+src="([^"]*wavedrom[^"]*\.svg)"', html)
    assert len(images) == diagrams, images
    for src in images:
        svg = (site / page).parent / src
        assert svg.read_text().lstrip().startswith("<svg") or "<svg" in svg.read_text()[:500]


def test_the_register_map_is_in_the_site(site):
    html = (site / "registers.html").read_text()
    for register in ("SNAP_VELOCITY", "CAL_DATA", "IRQ_STATUS"):
        assert register in html


def test_every_rtl_module_has_a_reference_page(site):
    for source in MODULES:
        page = site / "reference" / "modules" / f"{source.stem}.html"
        assert page.is_file(), source
    core = (site / "reference" / "modules" / "prenc_core.html").read_text()
    assert "ROM_FILE" in core and "pos_valid" in core and "6 + FILTER" in core


@pytest.mark.parametrize("source", MODULES, ids=[m.stem for m in MODULES])
def test_every_module_states_its_latency(source):
    comment = prenc_modules.header_comment(source.read_text())
    assert prenc_modules.latency(comment), f"{source.relative_to(REPO)}: no 'Latency' paragraph"


def test_a_module_without_a_latency_is_found():
    assert prenc_modules.latency(["prenc_x: a block.", "", "Ports", "  a  an input"]) is None


def test_the_readme_is_a_front_door():
    lines = (REPO / "README.md").read_text().splitlines()
    assert len(lines) <= 250, len(lines)


def test_the_navigation_has_one_changelog_entry(site):
    links = re.findall(r'href="changelog\.html[^"]*"', (site / "fine.html").read_text())
    assert len(links) == 1, links


def _wavedrom_blocks():
    for page in sorted(REPO.glob("docs/**/*.md")):
        for block in re.findall(r"```\{wavedrom\}\n(.*?)```", page.read_text(), re.S):
            yield page.relative_to(REPO), block


# The SVG's head and foot are centred text of 11 pt; this wide a character (Helvetica's
# widest average) is what the test assumes.
CAPTION_CHAR_PX = 7.5


@pytest.mark.parametrize("page,block", list(_wavedrom_blocks()),
                         ids=[f"{p}-{i}" for i, (p, _) in enumerate(_wavedrom_blocks())])
def test_the_timing_diagrams_captions_fit_their_picture(page, block):
    import wavedrom

    svg = wavedrom.render(block).tostring()
    width = float(re.search(r'<svg[^>]*width="([\d.]+)"', svg).group(1))
    lanes = re.search(r'id="lanes_0" transform="translate\(([\d.]+),', svg)
    left = float(lanes.group(1)) if lanes else 0.0
    for x, text in re.findall(r'<text[^>]*text-anchor="middle" x="([\d.-]+)"[^>]*><tspan>([^<]*)</tspan>', svg):
        centre = left + float(x)
        room = 2 * min(centre, width - centre)
        assert CAPTION_CHAR_PX * len(text) <= room, f"{page}: '{text}' is too long for its {width:.0f}-px picture"


@pytest.mark.parametrize("page,figures", [("measurements.html", ["availability.svg", "accuracy.svg"]),
                                          ("fine.html", ["accuracy.svg"]),
                                          ("calibration.html", ["calibration.svg"])])
def test_the_benchs_figures_are_in_the_site(site, page, figures):
    html = (site / page).read_text()
    for name in figures:
        assert re.search(rf'<img[^>]+src="[^"]*{re.escape(name)}"', html), name
        assert (site / "_images" / name).read_text().lstrip().startswith("<?xml")
