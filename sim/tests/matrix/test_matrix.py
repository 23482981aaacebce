# SPDX-License-Identifier: Apache-2.0
"""2-D matrix codes: generation, graph G, counting, the paper's example, ROMs, the
parity track, the sensor model and the reader model, `prenc matrix` and `prenc disc`.

Expected values come from the definitions (every window once, counted directly;
arcs of G from Definition 3), from the paper (20736 cycles for n = 2; its cycle
B1, B5, ...) and from the closed formula for de Bruijn sequences.
"""

from __future__ import annotations

import itertools
import json
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from prenc.cli.main import main
from prenc.matrix.code import MatrixCode, build_clocks, cost, fkm, prenecklaces, windows_once
from prenc.matrix.graph import (adjacency, columns_of_cycle, count_hamiltonian_cycles, debruijn_count,
                                hamiltonian_cycle, matrix_code_count, successors)
from prenc.matrix.paper import NUMBERINGS, PAPER_CYCLE, check_cycle, matrix_of, table_one, tracks_of_cycle
from prenc.matrix.reader import read_frame
from prenc.matrix.rom import rom_bytes
from prenc.matrix.sensor import Geometry, Optics, default_geometry, render, truth


def windows_of_cells(cells: np.ndarray, n: int) -> list[bytes]:
    """Every n x n window of an (n, L) cell array, cyclically, as bytes."""
    L = cells.shape[1]
    ext = np.concatenate([cells, cells[:, : n - 1]], axis=1)
    return [ext[:, p:p + n].tobytes() for p in range(L)]


@pytest.mark.parametrize("n", [2, 3, 4])
@pytest.mark.parametrize("checksum", [False, True])
def test_every_window_appears_once(n, checksum):
    code = MatrixCode(n, checksum)
    wins = windows_of_cells(code.cells(), n)
    assert len(wins) == code.length == 2 ** (n * (n - 1 if checksum else n))
    assert len(set(wins)) == code.length  # each of the L windows differs from the others
    if not checksum:
        assert code.length == 2 ** (n * n)  # ... and there are 2^(n*n): all of them
    else:  # every column has even parity, and all even-parity windows appear
        assert all(int(c).bit_count() % 2 == 0 for c in code.columns)


@pytest.mark.parametrize("k, n", [(2, 3), (2, 8), (3, 4), (4, 2), (8, 3), (16, 4)])
def test_fkm_is_a_de_bruijn_sequence(k, n):
    s = fkm(k, n)
    assert len(s) == k ** n and windows_once(s, n, k)
    assert s[:n] == [0] * n


def test_fkm_matches_a_brute_force_lexicographic_search():
    # the least de Bruijn sequence of order 3 over 2 symbols, known in closed form
    assert fkm(2, 3) == [0, 0, 0, 1, 0, 1, 1, 1]
    assert fkm(3, 2) == [0, 0, 1, 0, 2, 1, 1, 2, 2]


@pytest.mark.parametrize("n", [2, 3, 4])
def test_table_inverts_the_windows(n):
    for checksum in (False, True):
        code = MatrixCode(n, checksum)
        table = code.positions
        assert sorted(table.tolist()) == list(range(code.length))
        for p in range(0, code.length, max(1, code.length // 500)):
            assert table[code.address(p)] == p
            assert code.address_of_matrix(code.window_matrix(p)) == code.address(p)


def test_address_bit_order_is_documented():
    # n = 2: window at p = columns p, p+1; first column most significant, track 0 its MSB
    code = MatrixCode(2)
    for p in range(16):
        m = code.window_matrix(p)
        assert code.address(p) == (m[0, 0] << 3) | (m[1, 0] << 2) | (m[0, 1] << 1) | m[1, 1]


@pytest.mark.parametrize("n", [2, 3])
def test_hamiltonian_search_cross_checks_fkm(n):
    lex = hamiltonian_cycle(n, "lexicographic", time_limit=60)
    assert lex.cycle is not None
    assert columns_of_cycle(lex.cycle, n) == fkm(1 << n, n)
    warn = hamiltonian_cycle(n, "warnsdorff", time_limit=60)
    assert warn.cycle is not None and len(set(warn.cycle)) == 1 << (n * n)
    for a, b in zip(warn.cycle, warn.cycle[1:] + warn.cycle[:1]):
        assert b in successors(a, n)  # every step is an arc of G
    assert windows_once(columns_of_cycle(warn.cycle, n), n, 1 << n)
    assert columns_of_cycle(warn.cycle, n) != fkm(1 << n, n)  # a second, independent code


def test_count_of_hamiltonian_cycles_for_n2_is_20736():
    assert count_hamiltonian_cycles(2) == 20736
    assert debruijn_count(4, 2) == 20736 == matrix_code_count(2)


def test_formula_gives_the_known_small_counts():
    # (k!)^(k^(n-1)) / k^n against the known numbers of binary and ternary de Bruijn sequences
    assert debruijn_count(2, 3) == 2 and debruijn_count(2, 4) == 16 and debruijn_count(3, 2) == 24


def test_formula_for_n3():
    value = matrix_code_count(3)
    assert value == math.factorial(8) ** 64 // 8 ** 3
    assert len(str(value)) == 293  # about 1.1067e292


def test_graph_g_arcs_follow_definition_3():
    adj = adjacency(2)
    for a, b in itertools.product(range(16), repeat=2):
        ma = np.array([[(a >> 3) & 1, (a >> 1) & 1], [(a >> 2) & 1, a & 1]])
        mb = np.array([[(b >> 3) & 1, (b >> 1) & 1], [(b >> 2) & 1, b & 1]])
        assert adj[a][b] == int(np.array_equal(ma[:, 1:], mb[:, :-1]))
    assert all(sum(row) == 4 for row in adj)


def test_the_papers_cycle_holds_with_row_major_numbering_only():
    verdict = {name: check_cycle(PAPER_CYCLE, name).holds for name in NUMBERINGS}
    assert verdict == {"row-major, MSB first": True, "row-major, LSB first": False,
                       "column-major, MSB first": False, "column-major, LSB first": False}
    c = check_cycle(PAPER_CYCLE, "row-major, MSB first")
    assert c.visits_each_once and c.closed and not c.bad_steps
    # read backwards, the LSB-first numbering gives a cycle too (the mirror image)
    assert check_cycle(PAPER_CYCLE[::-1], "row-major, LSB first").holds


def test_table_one_is_a_correct_16_position_disc():
    rows = table_one()
    tracks = tracks_of_cycle(PAPER_CYCLE, "row-major, MSB first")
    assert tracks.shape == (2, 16)
    assert len(set(windows_of_cells(tracks, 2))) == 16
    assert [r.number for r in rows] == list(PAPER_CYCLE[:-1])
    assert rows[0].angle_from == 0.0 and rows[-1].angle_to == 360.0
    assert all(r.angle_to - r.angle_from == 22.5 for r in rows)
    for r in rows:
        m = matrix_of(r.number, "row-major, MSB first")
        assert r.matrix == f"{m[0, 0]}{m[0, 1]}/{m[1, 0]}{m[1, 1]}"


@pytest.mark.parametrize("n", [2, 3, 4])
def test_checksum_detects_every_single_misread_cell(n):
    code = MatrixCode(n, checksum=True)
    step = 1 if n < 4 else 37
    for p in range(0, code.length, step):
        m = code.window_matrix(p)
        assert code.address_of_matrix(m) == code.address(p)
        for t, i in itertools.product(range(n), repeat=2):
            bad = m.copy()
            bad[t, i] ^= 1
            assert code.address_of_matrix(bad) is None


def test_cost_of_the_parity_track():
    assert [(c["plain_positions"], c["checksum_positions"]) for c in map(cost, (2, 3, 4))] == \
        [(16, 4), (512, 64), (65536, 4096)]


def test_build_clocks_of_the_self_built_table():
    # one clock per symbol, one per prenecklace step, n-1 closing zeros, one for ready
    assert build_clocks(4) == 65536 + sum(1 for _ in prenecklaces(16, 4)) + 3 + 1
    assert build_clocks(4) == 83356


@pytest.mark.parametrize("fmt", ["hex", "bin", "mif", "coe", "mem"])
def test_rom_formats(fmt):
    code = MatrixCode(3)
    text = rom_bytes(code, fmt).decode()
    table = code.positions
    if fmt == "hex":
        assert [int(v, 16) for v in text.split()] == table.tolist()
    if fmt == "bin":
        lines = text.split()
        assert all(len(v) == 9 for v in lines) and [int(v, 2) for v in lines] == table.tolist()
    if fmt == "mif":
        assert "WIDTH=9;" in text and "DEPTH=512;" in text
    if fmt == "mem":
        assert "#Depth=512" in text and "#Width=9" in text


@pytest.mark.parametrize("n", [2, 3, 4])
def test_model_reader_reads_sensor_images_as_the_truth(n):
    rng = np.random.default_rng(n)
    for checksum in (False, True):
        code, g = MatrixCode(n, checksum), default_geometry(n)
        for _ in range(120):
            p = int(rng.integers(0, code.length))
            theta = p - (int(rng.integers(0, g.cell)) + rng.uniform(-0.25, 0.25)) / g.cell
            img = render(code, theta, g, Optics(radial=rng.uniform(-0.3, 0.3)), rng)
            r = read_frame(img, g, code)
            assert r.ok and (r.position, r.phase) == truth(theta, g, code.length), (p, theta, r)


def test_model_reader_flags_what_it_cannot_trust():
    code, g = MatrixCode(3, checksum=True), default_geometry(3)
    rng = np.random.default_rng(9)
    flat = np.full((g.height, g.width), 100)
    assert read_frame(flat, g, code).low_contrast
    img = render(code, 10.0, g, Optics(noise=0), rng, flip=(1, 11))
    r = read_frame(img, g, code)
    assert r.checksum_error and not r.ok


def test_geometry_is_checked():
    with pytest.raises(ValueError, match="width"):
        Geometry(4, cell=3, width=14)
    with pytest.raises(ValueError, match="cell"):
        Geometry(2, cell=2)
    with pytest.raises(ValueError, match="order"):
        MatrixCode(5)


def test_cli_count(capsys):
    assert main(["matrix", "count", "--n", "2"]) == 0
    assert capsys.readouterr().out.strip() == "20736"
    assert main(["matrix", "count", "--n", "3", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["formula"] == str(math.factorial(8) ** 64 // 512) and "enumerated" not in out


def test_cli_generate_and_cross_check(capsys):
    assert main(["matrix", "generate", "--n", "3", "--format", "json", "--cross-check"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["length"] == 512 and out["cross_check"]["lexicographic_search_equals_fkm"]
    assert out["cross_check"]["warnsdorff_cycle_is_a_code"]
    assert main(["matrix", "generate", "--n", "2"]) == 0
    lines = capsys.readouterr().out.split()
    assert len(lines) == 2 and all(len(line) == 16 for line in lines)


def test_cli_example(capsys):
    assert main(["matrix", "example"]) == 0
    out = capsys.readouterr().out
    assert "row-major, MSB first     a Hamiltonian cycle of G" in out
    assert "337.5 ..  360.0 deg" in out


def test_cli_rom(tmp_path):
    path = tmp_path / "m.hex"
    assert main(["matrix", "rom", "--n", "2", "--checksum", "-o", str(path)]) == 0
    assert [int(v, 16) for v in path.read_text().split()] == MatrixCode(2, True).positions.tolist()
    assert main(["matrix", "rom", "--n", "2", "-o", str(tmp_path / "no" / "x.hex")]) == 1


@pytest.mark.parametrize("kind, args, rings", [
    ("dual", ["--bits", "6"], ["track1", "track1_inverted", "track2", "track2_inverted", "sync_a", "sync_b"]),
    ("matrix", ["--n", "2"], ["track0", "track1"]),
    ("nd", ["--sequence", "00010111", "--sequence", "00010111", "--n", "3"], ["track0", "track1"]),
])
def test_disc_svg_and_png(tmp_path, kind, args, rings):
    svg, png = tmp_path / "d.svg", tmp_path / "d.png"
    assert main(["disc", kind, *args, "-o", str(svg), "--png", str(png)]) == 0
    root = ET.parse(svg).getroot()
    assert root.get("width").endswith("mm")
    ids = [e.get("id") for e in root.iter() if e.get("id")]
    assert ids == rings
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_disc_ink_matches_the_code():
    from prenc.codes.debruijn import Code
    from prenc.cli.disc import _runs, dual_disc

    d = dual_disc(bits=6)
    code = Code(6)
    track1 = d.rings[0].cells
    assert track1.tolist() == list(code.sequence)
    assert (d.rings[1].cells == 1 - track1).all()
    ink = np.zeros(len(track1), dtype=bool)
    for s, n in _runs(track1):
        ink[[(s + i) % len(track1) for i in range(n)]] = True
    assert (ink == (track1 == 0)).all()
    a, b = d.rings[4].cells, d.rings[5].cells  # quarters of slot 0: A 0011, B 1001
    assert a[:4].tolist() == [0, 0, 1, 1] and b[:4].tolist() == [1, 0, 0, 1]


def test_disc_rejects_rings_inside_the_hole(capsys):
    assert main(["disc", "dual", "--outer-radius", "5", "-o", "-"]) == 1
    assert "inside the" in capsys.readouterr().err
