"""The event-level reference reader against the truth, and the campaign generator."""

from __future__ import annotations

import pytest

from prenc.campaign import campaign
from prenc.core_demo import demo_run, unprotected
from prenc.debruijn import Code
from prenc.mode_fsm import Mode
from prenc.reader import Reader, Step, events_from_run
from prenc.scenarios import scenarios, sync_tolerance
from prenc.track_monitor import TrackMonitor


@pytest.mark.parametrize("filter_len", [0, 2])
@pytest.mark.parametrize("n", [6, 10])
def test_reference_never_outputs_a_wrong_valid_position(n, filter_len):
    for name, sc in scenarios(n, filter_len, seed=11).items():
        enc = sc.run(n)
        tol = sync_tolerance(enc) + filter_len
        reader = Reader(Code(n))
        valid_steps = 0
        for ev in events_from_run(enc, filter_len):
            out = reader.event(ev)
            if isinstance(ev, Step) and out.valid:
                valid_steps += 1
                k = ev.clock - 2 - filter_len
                near = {int(enc.hybrid[min(max(k + d, 0), len(enc) - 1)]) for d in range(-tol, tol + 1)}
                assert out.pos_hyb in near, f"{name}: wrong valid position at clock {ev.clock}"
        if name.startswith(("start", "reversals", "accelerate")):
            assert valid_steps > 0, f"{name}: never valid"


def test_start_up_takes_3n_minus_1_slots_on_a_clean_disc():
    n = 10
    sc = scenarios(n, 0, seed=3)["start_moving_ccw"]
    reader = Reader(Code(n))
    for ev in events_from_run(sc.run(n), 0):
        reader.event(ev)
        if reader.fsm.valid:
            break
    assert reader.strobes == 3 * n  # N to form the word, 2N checks: 3N - 1 slots moved


def test_contaminated_track_stays_reduced_and_a_one_time_misread_returns_to_normal():
    modes = {}
    for name in ("contaminated_track1", "transient_misread"):
        reader = Reader(Code(8))
        reader.run(events_from_run(scenarios(8, 0, seed=2)[name].run(8), 0))
        modes[name] = [c.mode for c in reader.checks]
    assert modes["contaminated_track1"][-1] == Mode.REDUCED_2
    seen = modes["transient_misread"]
    assert Mode.REDUCED_1 in seen or Mode.REDUCED_2 in seen
    assert seen[-1] == Mode.NORMAL


def test_track_monitor_counts_new_slots_only():
    m = TrackMonitor(4)
    for slot in (5, 6, 5, 6, 5):  # jitter over two slots: never 4 slots
        run = m.next(False, True, False, slot)
        m.commit()
    assert not run.run_n
    for slot in (7, 8):
        run = m.next(False, True, False, slot)
        m.commit()
    assert run.run_n and not run.run_long
    assert not m.next(False, True, True, 9).run_n  # a disagreement empties it


def test_track_monitor_ignores_the_slots_that_fed_the_word():
    m = TrackMonitor(4)
    for slot in (10, 11, 12, 13):
        m.feed(slot, word_empty=slot == 10)
    for slot in (13, 12, 11, 10, 9, 8, 7):
        run = m.next(False, True, False, slot)
        m.commit()
    assert not run.run_n  # only 9, 8, 7 are evidence
    run = m.next(False, True, False, 6)
    assert run.run_n


def test_campaign_small_is_reproducible_and_clean():
    a = campaign(6, 20_000, 5_000, seed=4)
    b = campaign(6, 20_000, 5_000, seed=4)
    assert a == b
    assert a.strobes >= 20_000 and a.wrong_valid == 0 and a.valid_events > 0
    assert sum(a.faults.values()) > 0


def test_unprotected_reader_outputs_wrong_positions_in_the_demo():
    enc, _ = demo_run()
    strobes, wrong = unprotected(enc)
    assert strobes > 100 and wrong > 0
