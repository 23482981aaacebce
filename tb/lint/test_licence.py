# SPDX-License-Identifier: Apache-2.0
"""The licence: LICENSE at the root, pyproject's licence field, and an SPDX line at the
top of every source file of rtl/, sim/, tb/, scripts/, constraints/, formal/ and sw/
(issue 17)."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SPDX = "SPDX-License-Identifier: Apache-2.0"
FOLDERS = ("rtl", "sim", "tb", "scripts", "constraints", "formal", "sw")
SOURCES = {".v", ".vh", ".f", ".py", ".pcf", ".lpf", ".md", ".sby", ".core", ".rdl", ".c", ".h"}


def sources() -> list[Path]:
    """The tracked files of FOLDERS (git), or their source files on disk without git."""
    try:
        out = subprocess.run(["git", "ls-files", *FOLDERS], cwd=ROOT, capture_output=True,
                             text=True, check=True).stdout.split()
        if out:
            return [ROOT / name for name in out]
    except (OSError, subprocess.CalledProcessError):
        pass
    return [p for f in FOLDERS for p in (ROOT / f).rglob("*")
            if p.suffix in SOURCES and "sim_build" not in p.parts and "__pycache__" not in p.parts]


def test_the_licence_is_apache_2():
    text = (ROOT / "LICENSE").read_text()
    assert "Apache License" in text and "Version 2.0, January 2004" in text
    assert "END OF TERMS AND CONDITIONS" in text
    pyproject = (ROOT / "pyproject.toml").read_text()
    assert re.search(r'^license = "Apache-2.0"$', pyproject, re.M), "pyproject.toml: no licence"


def test_every_source_file_carries_an_spdx_line():
    files = sources()
    assert len(files) > 100, "the source tree was not found"
    missing = [str(p.relative_to(ROOT)) for p in files
               if not any(SPDX in line for line in p.read_text().splitlines()[:3])]
    assert not missing, f"no '{SPDX}' in the first three lines of: {missing}"
