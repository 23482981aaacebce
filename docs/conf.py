# SPDX-License-Identifier: Apache-2.0
"""Sphinx configuration of the prenc documentation (`make docs` -> build/docs/html).

Markdown pages through MyST; timing diagrams written in WaveDrom's JSON and rendered to
SVG at build time by wavedrompy (no JavaScript in the pages); the register map is
docs/registers.md, generated from rtl/bus/prenc_wb.rdl by scripts/regmap.py; one
reference page per RTL module, generated at build time from the module's source by
docs/_ext/prenc_modules.py.
"""

from __future__ import annotations

import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
REPO = DOCS.parent
sys.path.insert(0, str(DOCS / "_ext"))

project = "prenc"
author = "the prenc authors"
copyright = "the prenc authors, Apache-2.0"
release = version = (REPO / "VERSION").read_text().strip()

extensions = [
    "myst_parser",
    "sphinxcontrib.wavedrom",
    "prenc_modules",
]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "_ext", "Thumbs.db", ".DS_Store"]
myst_enable_extensions = ["colon_fence"]
myst_heading_anchors = 4

# WaveDrom: rendered to SVG images by the Python wavedrom package while building.
render_using_wavedrompy = True
wavedrom_html_jsinline = False

# Furo, as cocotb's documentation: a readable measure of text, a navigation tree that
# shows where a page is, a light and a dark scheme, and pages that fit a phone.
html_theme = "furo"
html_title = f"prenc {release}"
html_static_path: list[str] = []
