# SPDX-License-Identifier: Apache-2.0
"""prenc: reference model and tools for the pseudorandom absolute encoder reader.

Plain Python (numpy), no simulator imports: the cocotb testbenches in tb/ import
this package, never the other way round. One subpackage per concern, as rtl/:

- codes    the disc's code: LFSR, de Bruijn sequence, ROM tables, lock-depth arithmetic
- core     models of rtl/core/, module for module (quadrature, track_word, mode_fsm, ...)
- board    models of rtl/board/ (multi-turn, SSI, BiSS-C, frames) and the host side
- virtual  the virtual encoder: disc, heads, motion, faults, scenarios, campaigns
- nd       error-tolerant (n,d) sequences and their correlator (rtl/nd/)
- matrix   2-D matrix codes and their reader (rtl/matrix/)
- cli      the `prenc` command

Imports go one way: codes <- core, virtual <- board <- cli; nd and matrix use codes.
"""

from importlib import metadata as _metadata
from pathlib import Path as _Path


def _version() -> str:
    """The project's one version: the repository's VERSION file, else the installed one."""
    here = _Path(__file__).resolve().parents[2] / "VERSION"
    if here.is_file():
        return here.read_text().strip()
    return _metadata.version("prenc")


__version__ = _version()
