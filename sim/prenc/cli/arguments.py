# SPDX-License-Identifier: Apache-2.0
"""Argument types shared by the `prenc` subcommands (argparse `type=` callables)."""

from __future__ import annotations

import argparse


def taps_arg(text: str) -> list[int]:
    try:
        taps = [int(t) for t in text.replace(" ", "").split(",") if t]
    except ValueError:
        raise argparse.ArgumentTypeError(f"taps must be integers separated by commas, got {text!r}") from None
    if not taps:
        raise argparse.ArgumentTypeError("taps must not be empty")
    return taps


def bits_arg(text: str) -> int:
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"N must be an integer, got {text!r}") from None
