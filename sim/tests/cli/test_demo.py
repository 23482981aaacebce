# SPDX-License-Identifier: Apache-2.0
"""`prenc demo` runs from nothing and shows what the README promises."""

from __future__ import annotations

from prenc.cli.main import main


def test_demo_writes_rom_and_plot_and_prints_the_reading(tmp_path, capsys):
    assert main(["demo", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "line 512 (W(0) = 1000000000) holds 0, line 0 holds 1, line 1 holds 2" in out
    # the reversal exactly at mid-slot 104.5: a CW instant, then a CCW one on the next clock
    assert "231  CW   104.500  104" in out and "232  CCW" in out
    assert (tmp_path / "prenc_rom_n10.hex").read_text().splitlines()[512] == "000"
    png = (tmp_path / "virtual_encoder.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000
