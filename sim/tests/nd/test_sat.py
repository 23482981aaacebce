# SPDX-License-Identifier: Apache-2.0
"""The SAT back end of the (n,d)-sequence search (`prenc.nd.sat`).

Expected values come from the exhaustive depth-first search (`prenc.nd.exact`, itself
checked against brute force over every cyclic string in test_nd.py) and from the
definition: every sequence the solver returns passes the independent pairwise check,
and an UNSAT answer is backed by a DRAT proof that a separate checker replays.
"""

from __future__ import annotations

import json

import pytest

from prenc.cli.main import main
from prenc.nd.bounds import upper_bound
from prenc.nd.exact import exact_search
from prenc.nd.records import RECORDS
from prenc.nd.sat import Instance, check_drat, encode, settle, solve
from prenc.nd.sequence import check
from prenc.nd.table import PAPER_OPEN, build_table, entry, to_markdown
from test_nd import TABLE1  # the maxima for n = 3..8, proven by the exhaustive search




@pytest.mark.parametrize("n,d", [(n, d) for n in range(3, 8) for d in range(1, 5) if d <= n])
def test_at_least_the_maximum_is_sat_and_one_more_is_unsat(n, d):
    best = TABLE1[n][d - 1]
    found = solve(Instance(n, d, best, at_least=True))
    assert found.status == "sat" and len(found.sequence) == best
    assert check(found.sequence, n, d) >= d
    if best < upper_bound(n, d)[0]:
        assert solve(Instance(n, d, best + 1, at_least=True)).status == "unsat"
    else:  # the bound proves it, and a longer question is refused
        with pytest.raises(ValueError, match="none longer exists"):
            Instance(n, d, best + 1, at_least=True)


@pytest.mark.parametrize("n,d", [(4, 1), (4, 2), (5, 1), (5, 2), (5, 3), (6, 2), (6, 3)])
@pytest.mark.parametrize("symmetry", [True, False])
def test_every_exact_length_agrees_with_the_exhaustive_search(n, d, symmetry):
    """Existence is not monotone in the length: each K is asked on its own."""
    for k in range(1, upper_bound(n, d)[0] + 1):
        want = exact_search(n, d, target=k).sequence is not None
        got = solve(Instance(n, d, k, symmetry=symmetry))
        assert (got.status == "sat") == want, f"({n},{d}) length {k}"
        if want:
            assert len(got.sequence) == k and check(got.sequence, n, d) >= d


def test_table1_entry_8_2_is_reproduced():
    """(8,2) = 63: the largest exact entry the SAT back end proves in seconds."""
    assert solve(Instance(8, 2, 63, at_least=True)).status == "sat"
    assert solve(Instance(8, 2, 64, at_least=True)).status == "unsat"


def test_unsat_answers_come_with_a_drat_proof_that_checks(tmp_path):
    proof = tmp_path / "proof.drat"
    res = solve(Instance(6, 2, 16, at_least=True), proof_path=str(proof), check_proof=True)
    assert res.status == "unsat" and res.proof_checked is True
    lines = proof.read_text().splitlines()
    assert lines and len(lines) == res.proof_lines
    clauses, variables, _, _ = encode(Instance(6, 2, 16, at_least=True))
    # The same proof does not refute a satisfiable question, nor does a truncated proof.
    sat_clauses, sat_vars, _, _ = encode(Instance(6, 2, 15, at_least=True))
    assert not check_drat(sat_clauses, sat_vars, lines)
    assert not check_drat(clauses, variables, lines[: len(lines) // 2])


def test_time_limit_gives_unknown_not_an_answer():
    res = solve(Instance(10, 2, 256, at_least=True), time_limit=1.0)
    assert res.status == "unknown" and res.sequence is None
    assert res.seconds < 30


def test_settle_proves_the_maximum_and_bisects_the_bound():
    res = settle(6, 2)
    assert res.exact and res.lower == res.upper == 15
    assert check(res.sequence, 6, 2) >= 2
    # Half a second per question: "at least 256" runs out of time, then the bound is
    # bisected downward, and only UNSAT answers lower it.
    hard = settle(10, 2, lower=255, time_limit=0.5)
    assert hard.lower == 255 and not hard.exact and hard.sequence is None
    assert hard.tried[0].instance.length == 256 and hard.tried[0].status == "unknown"
    assert all(r.status in ("unknown", "unsat") for r in hard.tried)
    refuted = [r.instance.length for r in hard.tried if r.status == "unsat"]
    assert hard.upper == (min(refuted) - 1 if refuted else upper_bound(10, 2)[0])


def test_bad_questions_are_refused():
    with pytest.raises(ValueError, match="length 17 is out of range 1..16"):
        Instance(4, 1, 17)
    with pytest.raises(ValueError, match="length 300 is out of range 1..256 for"):
        Instance(9, 2, 300, at_least=True)
    with pytest.raises(ValueError, match="distance d = 5"):
        Instance(4, 5, 3)
    with pytest.raises(ValueError, match="solver 'nosuch'"):
        solve(Instance(4, 2, 4), solver="nosuch")
    with pytest.raises(ValueError, match="kissat404 keeps no DRAT proof"):
        solve(Instance(4, 2, 5, at_least=True), solver="kissat404", check_proof=True)


def test_records_are_consistent_and_used_by_the_table():
    for (n, d), rec in RECORDS.items():
        if rec.sequence:
            check(rec.sequence, n, d)
        if rec.upper is not None:
            assert rec.upper < upper_bound(n, d)[0]
            assert rec.upper >= (len(rec.sequence) if rec.sequence else PAPER_OPEN.get((n, d), 0))
            e = entry(n, d, time_limit=0.5)
            assert e.upper == rec.upper and e.upper_reason == rec.upper_how
            assert e.length <= e.upper and check(e.sequence, n, d) >= d


def test_the_table_reads_the_same_on_a_slow_machine():
    """`prenc nd table --max-n 10` with 1 s of search per entry (its default is 20 s: a
    machine 20 times slower or busier): every entry but the open (10,2) is proven, with
    the lengths of the exhaustive search (Table 1's for n <= 8, test_nd.py)."""
    table = build_table(10, time_limit=1.0)
    assert [(n, d) for n, row in table.items() for d, e in row.items() if not e.exact] == [(10, 2)]
    lengths = {n: tuple(e.length for e in row.values()) for n, row in table.items()}
    assert {n: lengths[n] for n in TABLE1} == TABLE1
    assert lengths[9] == (512, 127, 31, 11) and lengths[10] == (1024, 255, 62, 22)


def test_a_time_limit_that_runs_out_is_said():
    assert "the exact search's time limit ran out" in to_markdown(build_table(10, min_n=10, time_limit=0.01))


def test_cli_sat_questions(capsys, tmp_path):
    assert main(["nd", "search", "--n", "6", "--d", "2", "--method", "sat", "--at-least", "16",
                 "--check-proof"]) == 0
    out = capsys.readouterr().out
    assert "none exists (UNSAT; DRAT proof checked)" in out
    cnf = tmp_path / "q.cnf"
    main(["nd", "search", "--n", "7", "--d", "3", "--method", "sat", "--length", "14", "--json",
          "--cnf", str(cnf)])
    out = json.loads(capsys.readouterr().out)
    assert out["status"] == "sat" and out["found_length"] == 14
    check(out["sequence"], 7, 3)
    header = [ln for ln in cnf.read_text().splitlines() if ln.startswith("p cnf")]
    assert header == [f"p cnf {out['variables']} {out['clauses']}"]
    main(["nd", "search", "--n", "7", "--d", "2", "--method", "sat", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert out["exact"] and out["length"] == 31 and out["upper_bound"] == 31
    for bad, msg in ((["--at-least", "3"], "--at-least needs --method sat"),
                     (["--method", "sat", "--length", "3", "--at-least", "3"], "not both"),
                     (["--method", "sat", "--proof", "p"], "need one question")):
        assert main(["nd", "search", "--n", "5", "--d", "2", *bad]) == 1
        assert msg in capsys.readouterr().err
