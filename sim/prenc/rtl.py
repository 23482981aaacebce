# SPDX-License-Identifier: Apache-2.0
"""Where the RTL is, and its file lists: rtl/<subsystem>/<top>.f names a top's sources,
the one list that tests, lint, synthesis and the LiteX integration (prenc.bus.litex)
share; a line `-F other.f` includes another top's list."""

from __future__ import annotations

from pathlib import Path

RTL = Path(__file__).resolve().parents[2] / "rtl"


class FileListError(Exception):
    """A file list that is missing or names a file that does not exist."""


def list_file(toplevel: str) -> Path:
    """The file list of a top: rtl/<subsystem>/<toplevel>.f."""
    found = sorted(RTL.glob(f"*/{toplevel}.f"))
    if len(found) != 1:
        raise FileListError(f"{toplevel}: expected one file list rtl/*/{toplevel}.f, found {len(found)}")
    return found[0]


def read_file_list(listing: Path) -> list[Path]:
    """Sources named by a .f file, relative to its folder (`//` comments). A line
    `-F other.f` includes that list, whose paths are relative to its own folder (as
    Verilator's -F). Each source once, in order of first mention."""
    listing = Path(listing).resolve()
    if not listing.is_file():
        raise FileListError(f"{listing}: file list not found")
    paths: list[Path] = []
    for line in listing.read_text().splitlines():
        line = line.split("//", 1)[0].strip()
        if not line:
            continue
        if line.startswith("-F"):
            included = read_file_list(listing.parent / line[2:].strip())
        else:
            source = (listing.parent / line).resolve()
            if not source.is_file():
                raise FileListError(f"{listing}: names {line}, which does not exist")
            included = [source]
        paths += [p for p in included if p not in paths]
    return paths


def file_list(toplevel: str) -> list[Path]:
    """Sources of a top, from rtl/<subsystem>/<toplevel>.f."""
    return read_file_list(list_file(toplevel))
