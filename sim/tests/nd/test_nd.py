# SPDX-License-Identifier: Apache-2.0
"""(n,d)-sequences: searches, constructions, bounds, table, phasing, decoder, imaging.

Expected values come from the definition (brute force over every cyclic sequence for
small n, the independent pairwise check) and from the paper (Table 1 entries the
exhaustive search recomputes quickly; its two open entries must be beaten).
"""

from __future__ import annotations

import itertools
import json

import numpy as np
import pytest

from prenc.cli.main import main
from prenc.nd.algorithm1 import algorithm1
from prenc.nd.beam import sequence_of_length
from prenc.nd.bounds import upper_bound
from prenc.nd.correlator import decode, rom_windows, score_all, starts
from prenc.nd.exact import exact_search
from prenc.nd.imaging import Camera, Cylinder, Noise
from prenc.nd.lfsr_codes import best_lfsr
from prenc.nd.phasing import best_phasing, dual_track, evaluate, summed_matrix
from prenc.nd.sequence import min_distance, windows
from prenc.nd.table import PAPER_OPEN, entry

# Maximum lengths for n = 3..8, d = 1..4, proven by the exhaustive search (and, for
# n <= 5, by brute force over every cyclic binary string below).
TABLE1 = {
    3: (8, 3, 2, 1), 4: (16, 4, 2, 2), 5: (32, 10, 3, 2), 6: (64, 15, 7, 3),
    7: (128, 31, 14, 7), 8: (256, 63, 16, 8),
}


def brute_force_max(n: int, d: int, max_len: int) -> int:
    best = 0
    for k in range(1, max_len + 1):
        for bits in itertools.product((0, 1), repeat=k):
            if min_distance(np.array(bits, dtype=np.uint8), n) >= d:
                best = k
                break
    return best


def test_min_distance_is_the_pairwise_minimum():
    seq = "0001011100"
    w = [int("".join(seq[(i + j) % 10] for j in range(4)), 2) for i in range(10)]
    want = min(bin(a ^ b).count("1") for a, b in itertools.combinations(w, 2))
    assert min_distance(seq, 4) == want
    assert list(windows(seq, 4)) == w


@pytest.mark.parametrize("n", [3, 4])
@pytest.mark.parametrize("d", [2, 3])
def test_exact_search_agrees_with_brute_force(n, d):
    assert exact_search(n, d).length == brute_force_max(n, d, 11) == TABLE1[n][d - 1]


@pytest.mark.parametrize("n", sorted(TABLE1))
@pytest.mark.parametrize("d", [1, 2, 3, 4])
def test_table1_exact_entries(n, d):
    e = entry(n, d, time_limit=60, max_n=8)
    assert e.exact
    assert e.length == TABLE1[n][d - 1]
    assert min_distance(e.sequence, n) >= d and len(e.sequence) == e.length


def test_algorithm1_and_exact_search_agree():
    for n, d in [(5, 2), (6, 2), (6, 3), (7, 3), (7, 4), (8, 4)]:
        a, e = algorithm1(n, d), exact_search(n, d)
        assert a.exact and e.exact and a.length == e.length == TABLE1[n][d - 1]
        assert e.nodes < a.nodes


@pytest.mark.parametrize("n, d", [(9, 2), (10, 2)])
def test_the_papers_open_entries_are_beaten(n, d):
    built = best_lfsr(n, d)
    assert built.length > PAPER_OPEN[(n, d)]
    assert min_distance(built.sequence, n) >= d


@pytest.mark.parametrize("n", range(4, 13))
@pytest.mark.parametrize("d", [2, 3, 4])
def test_lfsr_constructions_keep_their_claim(n, d):
    built = best_lfsr(n, d)
    if built is None:
        return
    assert len(built.sequence) == built.length == (1 << max(built.taps)) - 1
    assert min_distance(built.sequence, n) >= d


@pytest.mark.parametrize("n, d", [(4, 2), (5, 3), (6, 4), (7, 3), (8, 3), (10, 4), (12, 3)])
def test_upper_bounds_are_sound(n, d):
    bound, _ = upper_bound(n, d)
    assert bound >= exact_search(n, d, time_limit=5).length
    if n <= 8:
        assert bound >= TABLE1[n][d - 1]


def test_sequences_of_a_given_length():
    for n, d, k in [(10, 1, 170), (8, 1, 170), (10, 2, 170), (7, 3, 14), (8, 2, 40)]:
        seq = sequence_of_length(n, d, k)
        assert seq is not None and len(seq) == k and min_distance(seq, n) >= d
    assert exact_search(7, 3, target=13).sequence is None  # none exists: 14 does


def test_phasing_maximises_equation_1():
    seq = exact_search(6, 3).sequence
    best = best_phasing([seq, seq], 6)
    k = len(seq)
    brute = max(evaluate(summed_matrix([seq, seq], 6, (0, p)), (0, p)).min_distance for p in range(k))
    assert best.min_distance == brute >= 2 * 3
    three = best_phasing([seq] * 3, 6)
    assert three.min_distance >= best.min_distance


def test_dual_track_disc():
    r = dual_track(6)
    # two heads 180 degrees apart read W(p) and W(p + N - 1): the windows share a bit
    assert r.head_offset == 5
    assert r.at_line_sensor.min_distance == int(r.by_offset[r.track_shift])
    assert r.best.min_distance == int(r.by_offset.max()) >= r.at_heads.min_distance


def _reading(seqs, n, phases, theta, c=0.0, seed=0):
    cam = Camera(Cylinder(tuple(seqs), tuple(phases)), n)
    return cam, cam.sample(cam.render(theta, Noise(c), np.random.default_rng(seed)))


def test_clean_images_decode_to_the_truth():
    seq = sequence_of_length(10, 1, 170)
    for theta in np.linspace(0, 2 * np.pi, 40, endpoint=False) + 0.013:
        cam, smp = _reading([seq], 10, [0], theta)
        got = starts(smp[None], rom_windows([seq], 10), 8)[0]
        truth = cam.truth_start(theta)
        assert abs((got - truth + 85) % 170 - 85) <= 1.0


def test_hard_decision_corrects_up_to_two_errors():
    seq = exact_search(7, 3, target=14).sequence
    phases = best_phasing([seq, seq], 7).phases
    w = rom_windows([seq, seq], 7, phases)
    for k in range(14):
        clean = w[k, :, :7].reshape(14)
        for errors in itertools.combinations(range(14), 2):
            word = clean.copy()
            word[list(errors)] ^= 1
            d = decode((word * 15).reshape(2, 7, 1), w, 4, hard=True)
            assert d.position == k and d.score == 12


def test_soft_score_is_the_correlation():
    rng = np.random.default_rng(3)
    seq = sequence_of_length(6, 1, 20)
    w = rom_windows([seq], 6)
    x = rng.integers(0, 256, size=(1, 6, 2))
    scores = score_all(x, w, 8)
    k, f = 7, 1
    want = 0
    for i in range(6):
        for q in range(2):
            bit = w[k, 0, i + (1 if q + f >= 2 else 0)]
            want += (2 * x[0, i, q] - 255) * (1 if bit else -1)
    assert scores[k, f] == want


def test_cli_search_json_and_errors(capsys):
    assert main(["nd", "search", "--n", "7", "--d", "3", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["length"] == 14 and out["exact"] and min_distance(out["sequence"], 7) >= 3
    assert main(["nd", "search", "--n", "7", "--d", "9"]) == 1
    assert "out of range" in capsys.readouterr().err


def test_cli_table_json_shape(capsys):
    assert main(["nd", "table", "--max-n", "5", "--json", "--quiet"]) == 0
    table = json.loads(capsys.readouterr().out)
    assert sorted(table) == ["3", "4", "5"]
    for n, row in table.items():
        assert sorted(row) == ["1", "2", "3", "4"]
        for d, e in row.items():
            assert e["length"] == TABLE1[int(n)][int(d) - 1] and e["exact"] is True
            assert len(e["sequence"]) == e["length"]
