# SPDX-License-Identifier: Apache-2.0
"""The virtual encoder: geometry, sync track, trajectories, event stream, faults.

Expected values are written from the datasheet's definitions, not from the
encoder's own helpers.
"""

from __future__ import annotations

import numpy as np
import pytest

from prenc.codes.debruijn import Code
from prenc.virtual.encoder import Disc, Event, VirtualEncoder
from prenc.virtual.printing import Printing
from prenc.virtual.faults import (
    Bounce,
    ContaminatedSlot,
    GrowingDirt,
    DeadHead,
    Glitch,
    MissedQuadratureState,
    RandomGlitches,
    RandomMisreads,
    TransientMisread,
)
from prenc.virtual.trajectory import Trajectory

# Datasheet: (A, B) for quarter q = 0..3.
AB_OF_QUARTER = {0: (0, 1), 1: (0, 0), 2: (1, 0), 3: (1, 1)}


def sweep(start: float, stop: float, speed: float = 0.05) -> Trajectory:
    """clk_hz = 1: speed is in slots per clock."""
    return Trajectory(clk_hz=1, start=start).move_to(stop, speed)


def edges(x: np.ndarray) -> np.ndarray:
    return np.flatnonzero(x[1:] != x[:-1]) + 1


# -- geometry --------------------------------------------------------------------


@pytest.mark.parametrize("n", [4, 10])
def test_heads_read_first_and_last_bit_of_the_window(n):
    disc = Disc(n)
    s = Code(n).sequence
    L = 2**n
    theta = np.arange(L) + 0.3
    head1, head2 = disc.heads(theta)
    for p in range(L):
        assert head1[p] == s[p]
        assert head2[p] == s[(p + n - 1) % L]


def test_track2_is_track1_shifted_by_d():
    disc = Disc(10)
    s = Code(10).sequence
    d = 2**9 + 9
    assert disc.shift == d
    for x in range(0, 1024, 37):
        assert disc.track2[x] == s[(x + d) % 1024]


@pytest.mark.parametrize("q", range(4))
def test_sync_track_quarters(q):
    theta = np.array([7 + (q + f) / 4 for f in (0.0, 0.5, 0.999)])
    a, b = Disc.sync(theta)
    assert [(int(x), int(y)) for x, y in zip(a, b)] == [AB_OF_QUARTER[q]] * 3
    assert Disc(10).hybrid(theta).tolist() == [4 * 7 + q] * 3


def test_cw_motion_has_a_leading_b_and_a_rises_at_mid_slot():
    run = VirtualEncoder(Disc(10)).run(sweep(5.1, 9.1))
    states = [(e.a, e.b) for e in run.events()]
    # CW order: q = 0 (0,1) -> 1 (0,0) -> 2 (1,0) -> 3 (1,1) -> 0 ...
    order = [(0, 1), (0, 0), (1, 0), (1, 1)]
    for s0, s1 in zip(states, states[1:]):
        assert order.index(s1) == (order.index(s0) + 1) % 4
    for c in edges(run.a):
        if run.a[c] == 1:  # A rising: theta just passed p + 0.5
            assert run.theta[c] % 1 >= 0.5 and run.theta[c - 1] % 1 < 0.5
        else:  # A falling going CW: at the slot boundary, with B high
            assert run.slot[c] == (run.slot[c - 1] + 1) % 1024 and run.b[c] == 1


def test_ccw_motion_reverses_the_state_order():
    run = VirtualEncoder(Disc(10)).run(sweep(9.9, 5.9))
    states = [(e.a, e.b) for e in run.events()]
    order = [(0, 1), (0, 0), (1, 0), (1, 1)]
    for s0, s1 in zip(states, states[1:]):
        assert order.index(s1) == (order.index(s0) - 1) % 4


def test_angle_wraps_around_the_disc():
    run = VirtualEncoder(Disc(4)).run(sweep(14.5, 18.5, 0.1))
    assert run.slot[0] == 14 and run.slot[-1] == 2
    assert run.hybrid[-1] == 4 * 2 + 2


# -- trajectories ----------------------------------------------------------------


def test_reversal_exactly_at_the_sampling_instant():
    traj = Trajectory(clk_hz=1, start=20.1).move_to(30.5, 0.03).move_to(25.2, 0.03)
    theta = traj.theta
    k = int(np.argmax(theta))
    assert theta[k] == 30.5  # exactly, not 30.4999...
    run = VirtualEncoder(Disc(10)).run(traj)
    assert run.a[k] == 1 and run.a[k - 1] == 0 and run.a[k + 1] == 0


def test_segments_join_without_jumps_and_keep_their_speeds():
    traj = (
        Trajectory(clk_hz=1e6, start=3.0)
        .rest(1e-4)
        .constant(speed=2e4, seconds=1e-3)
        .accelerate(to_speed=-2e4, seconds=2e-3)
        .move_to(0.5, speed=1e4)
    )
    theta = traj.theta
    assert len(theta) == len(traj)
    assert np.all(theta[:101] == 3.0)
    step = np.diff(theta)
    assert np.max(np.abs(step)) <= 2e4 / 1e6 + 1e-12
    # constant segment: 1000 ticks at 0.02 slots/tick
    assert theta[1100] == pytest.approx(3.0 + 20.0)
    # the acceleration ends symmetric: it came back to where it started the ramp
    assert theta[3100] == pytest.approx(theta[1100], abs=1e-6)
    assert theta[-1] == 0.5


def test_random_walk_is_seeded_bounded_and_reverses():
    a = Trajectory(clk_hz=1, start=0).random_walk(seconds=20000, max_speed=0.2, seed=3).theta
    b = Trajectory(clk_hz=1, start=0).random_walk(seconds=20000, max_speed=0.2, seed=3).theta
    c = Trajectory(clk_hz=1, start=0).random_walk(seconds=20000, max_speed=0.2, seed=4).theta
    assert np.array_equal(a, b) and not np.array_equal(a, c)
    v = np.diff(a)
    assert np.max(np.abs(v)) <= 0.2 + 1e-12
    assert np.any(v > 0) and np.any(v < 0)


def test_bad_trajectory_arguments():
    with pytest.raises(ValueError):
        Trajectory(clk_hz=0)
    with pytest.raises(ValueError):
        Trajectory(clk_hz=1).rest(-1)
    with pytest.raises(ValueError):
        Trajectory(clk_hz=1).move_to(3, 0)


# -- event stream ----------------------------------------------------------------


def test_events_rebuild_the_signals_exactly():
    traj = Trajectory(clk_hz=1, start=100.7).random_walk(5000, max_speed=0.3, seed=1)
    run = VirtualEncoder(Disc(10), faults=[Bounce(("a", "b", "head1"), width=3, seed=2)]).run(traj)
    events = run.events()
    assert events[0].clock == 0
    assert all(e1.clock > e0.clock for e0, e1 in zip(events, events[1:]))
    rebuilt = {k: np.empty(len(run), dtype=np.uint8) for k in ("head1", "head2", "a", "b")}
    bounds = [e.clock for e in events] + [len(run)]
    for e, stop in zip(events, bounds[1:]):
        for k in rebuilt:
            rebuilt[k][e.clock : stop] = getattr(e, k)
    for k in rebuilt:
        assert np.array_equal(rebuilt[k], run.signals[k]), k
    assert isinstance(events[0], Event)


# -- faults ----------------------------------------------------------------------


@pytest.fixture
def back_and_forth():
    """Three passes over slots 40..50: CW, CCW, CW."""
    return (
        Trajectory(clk_hz=1, start=39.2).move_to(50.8, 0.1).move_to(39.2, 0.1).move_to(50.8, 0.1)
    )


def test_transient_misread_hits_one_pass_of_one_head(back_and_forth):
    clean = VirtualEncoder().run(back_and_forth)
    run = VirtualEncoder(faults=[TransientMisread(head=1, slot=45, pass_index=1)]).run(back_and_forth)
    diff = np.flatnonzero(run.head1 != clean.head1)
    passes = np.split(np.flatnonzero(clean.slot == 45), np.flatnonzero(np.diff(np.flatnonzero(clean.slot == 45)) > 1) + 1)
    assert len(passes) == 3
    assert np.array_equal(diff, passes[1])
    assert np.array_equal(run.head2, clean.head2)


def test_contaminated_slot_reads_wrong_on_every_pass(back_and_forth):
    L = 1024
    clean = VirtualEncoder().run(back_and_forth)
    # Track 2 slot x sits under head 2 when the disc is at p = x - L/2.
    run = VirtualEncoder(faults=[ContaminatedSlot(track=2, slot=(47 + L // 2) % L)]).run(back_and_forth)
    diff = run.head2 != clean.head2
    assert np.array_equal(diff, clean.slot == 47)
    assert np.array_equal(run.head1, clean.head1)


def test_growing_dirt_inverts_more_slots_as_time_goes_on():
    """Every `every` clocks one more track slot reads inverted on every pass from then on;
    the slots are distinct, seeded, and head 2 (the other track) is untouched."""
    L, every, start = 1024, 3_000, 1_000
    theta = 3.0 + np.arange(40_000) * 0.02             # 800 slots: most of a turn
    clean = VirtualEncoder().run(theta)
    dirt = GrowingDirt(track=1, every=every, start_clock=start, seed=3)
    run = VirtualEncoder(faults=[dirt]).run(theta)
    assert dirt.spots(start - 1) == 0 and dirt.spots(start) == 1 and dirt.spots(start + every) == 2
    wrong = run.head1 != clean.head1
    assert not wrong[:start].any() and np.array_equal(run.head2, clean.head2)
    # Head 1 reads track 1 slot p at disc position p: the wrong clocks are whole passes
    # of slots, each wrong from the instant its spot appeared (all later ones too).
    spots = {}
    for k in np.flatnonzero(wrong):
        spots.setdefault(int(clean.slot[k]), int(k))
    assert 0 < len(spots) <= dirt.spots(len(theta) - 1)
    for slot, first in spots.items():
        on_slot = np.flatnonzero(clean.slot == slot)
        assert np.all(wrong[on_slot[on_slot >= first]])
        appeared = (first - start) % every == 0            # during a pass over it
        assert appeared or clean.slot[first - 1] != slot   # else from a pass's start
    # In two pieces, the second's start counted from its own first clock: the same dirt.
    cut = 25_000
    first = VirtualEncoder(faults=[dirt]).run(theta[:cut])
    second = VirtualEncoder(faults=[GrowingDirt(1, every, start - cut, seed=3)]).run(theta[cut:])
    assert np.array_equal(np.concatenate([first.head1, second.head1]), run.head1)
    again = VirtualEncoder(faults=[GrowingDirt(1, every, start, seed=3)]).run(theta)
    other = VirtualEncoder(faults=[GrowingDirt(1, every, start, seed=4)]).run(theta)
    assert np.array_equal(again.head1, run.head1) and not np.array_equal(other.head1, run.head1)


@pytest.mark.parametrize("mode, level", [("stuck0", 0), ("stuck1", 1)])
def test_dead_head_stuck(back_and_forth, mode, level):
    clean = VirtualEncoder().run(back_and_forth)
    run = VirtualEncoder(faults=[DeadHead(head=2, mode=mode, start_clock=50)]).run(back_and_forth)
    assert np.all(run.head2[50:] == level)
    assert np.array_equal(run.head2[:50], clean.head2[:50])


def test_dead_head_noise_is_seeded(back_and_forth):
    r1 = VirtualEncoder(faults=[DeadHead(1, "noise", seed=5)]).run(back_and_forth)
    r2 = VirtualEncoder(faults=[DeadHead(1, "noise", seed=5)]).run(back_and_forth)
    r3 = VirtualEncoder(faults=[DeadHead(1, "noise", seed=6)]).run(back_and_forth)
    assert np.array_equal(r1.head1, r2.head1) and not np.array_equal(r1.head1, r3.head1)
    assert 0.4 < r1.head1.mean() < 0.6


def test_glitch_inverts_exactly_its_clocks(back_and_forth):
    clean = VirtualEncoder().run(back_and_forth)
    run = VirtualEncoder(faults=[Glitch("b", clock=77, width=3)]).run(back_and_forth)
    assert np.flatnonzero(run.b != clean.b).tolist() == [77, 78, 79]


def test_random_glitches_have_the_asked_widths(back_and_forth):
    clean = VirtualEncoder().run(back_and_forth)
    run = VirtualEncoder(faults=[RandomGlitches("a", count=5, min_width=2, max_width=2, seed=9)]).run(back_and_forth)
    edges = np.diff(np.concatenate([[0], (run.a != clean.a).astype(int), [0]]))
    starts, stops = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    assert len(starts) == 5  # seed 9: five separate glitches
    assert (stops - starts).tolist() == [2] * 5


def test_missed_quadrature_state_makes_a_and_b_change_together(back_and_forth):
    clean = VirtualEncoder().run(back_and_forth)
    assert len(np.intersect1d(edges(clean.a), edges(clean.b))) == 0
    run = VirtualEncoder(faults=[MissedQuadratureState(count=3, seed=1)]).run(back_and_forth)
    together = np.intersect1d(edges(run.a), edges(run.b))
    assert len(together) == 3
    for c in together:  # a jump of two quarter states: both bits flip at once
        assert run.a[c] != run.a[c - 1] and run.b[c] != run.b[c - 1]


def test_missed_quadrature_states_skipped_are_left_alone(back_and_forth):
    clean = VirtualEncoder().run(back_and_forth)
    drawn = MissedQuadratureState(count=3, seed=1)
    firsts = [c1 for _, c1, _ in drawn.chosen(clean)]
    run = VirtualEncoder(faults=[MissedQuadratureState(count=3, seed=1, skip=frozenset(firsts[1:2]))]).run(back_and_forth)
    all_drawn = VirtualEncoder(faults=[drawn]).run(back_and_forth)
    together = np.intersect1d(edges(run.a), edges(run.b))
    assert len(together) == 2
    assert set(together) < set(np.intersect1d(edges(all_drawn.a), edges(all_drawn.b)))


def test_bounce_keeps_every_settled_level(back_and_forth):
    clean = VirtualEncoder().run(back_and_forth)
    run = VirtualEncoder(faults=[Bounce(("a",), width=6, seed=4)]).run(back_and_forth)
    e = edges(clean.a)
    near = np.zeros(len(clean), dtype=bool)
    for c in e:
        near[max(0, c - 3) : c + 3] = True
    assert np.array_equal(run.a[~near], clean.a[~near])
    assert len(edges(run.a)) > len(e)


def test_faults_compose_in_order(back_and_forth):
    faults = [ContaminatedSlot(1, 44), TransientMisread(1, 44, pass_index=0)]
    clean = VirtualEncoder().run(back_and_forth)
    run = VirtualEncoder(faults=faults).run(back_and_forth)
    # pass 0 is inverted twice (back to clean), passes 1 and 2 once.
    on44 = clean.slot == 44
    wrong = run.head1 != clean.head1
    assert wrong.sum() < on44.sum() and np.all(wrong <= on44) and wrong.any()


def test_fault_arguments_are_checked():
    with pytest.raises(ValueError):
        DeadHead(3)
    with pytest.raises(ValueError):
        DeadHead(1, mode="dead")
    with pytest.raises(ValueError):
        Glitch("c", 1)
    with pytest.raises(ValueError):
        Glitch("a", 1, width=0)
    with pytest.raises(ValueError):
        ContaminatedSlot(track=0, slot=3)
    with pytest.raises(ValueError):
        RandomMisreads(head=1, probability=1.5)
    with pytest.raises(ValueError):
        Bounce(("a", "z"))


def test_random_misreads_hit_whole_passes_with_the_given_probability(back_and_forth):
    clean = VirtualEncoder().run(back_and_forth)
    always = VirtualEncoder(faults=[RandomMisreads(head=2, probability=1.0)]).run(back_and_forth)
    never = VirtualEncoder(faults=[RandomMisreads(head=2, probability=0.0)]).run(back_and_forth)
    assert np.all(always.head2 != clean.head2) and np.array_equal(never.head2, clean.head2)
    half = [VirtualEncoder(faults=[RandomMisreads(2, 0.5, seed=s)]).run(back_and_forth).head2 for s in (1, 1, 2)]
    assert np.array_equal(half[0], half[1]) and not np.array_equal(half[0], half[2])
    wrong = half[0] != clean.head2
    # a pass is misread whole: the wrong clocks are unions of whole slot visits
    edges = np.diff(np.concatenate([[0], wrong.astype(int), [0]]))
    for start, stop in zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)):
        assert start == 0 or clean.slot[start] != clean.slot[start - 1]
        assert stop == len(wrong) or clean.slot[stop] != clean.slot[stop - 1]
    assert 0.3 < wrong.mean() < 0.7
    assert np.array_equal(always.head1, clean.head1)  # the other head is untouched


# -- a printed disc (issue 37, item 5) -------------------------------------------


def test_an_ideal_printing_reads_as_the_datasheet_disc():
    theta = np.linspace(3.0, 40.0, 5001)
    ideal = Disc(6).read(theta)
    printed = Disc(6, printing=Printing()).read(theta)
    for name in ("head1", "head2", "a", "b"):
        assert np.array_equal(ideal[name], printed[name]), name


def crossings(theta: np.ndarray, signal: np.ndarray, level: int) -> np.ndarray:
    """The angles (midpoints) at which `signal` changes to `level` on a CW sweep."""
    c = edges(signal)
    c = c[signal[c] == level]
    return (theta[c] + theta[c - 1]) / 2


def test_printed_edges_sit_where_phase_duty_and_edge_errors_put_them():
    # Written from the definitions: A high over [p + 0.5 - (dA - 0.5)/2, p + 1 + (dA - 0.5)/2),
    # B's interval centred on p + 1 and shifted by phase / 360, each edge off by its own error.
    printing = Printing(edge_error=0.04, phase_deg=10, duty_a=0.45, duty_b=0.55, seed=5)
    disc = Disc(4, printing=printing)
    theta = np.arange(0, 16 * 20000) / 20000 + 0.0000125   # one turn, 1/20000 slot steps
    sig = disc.read(theta)
    rng = np.random.default_rng(5)
    err = {k: rng.uniform(-0.04, 0.04, 16) for k in ("a_rise", "a_fall", "b_rise", "b_fall")}
    p = np.arange(16)
    want_a_rise = p + 0.5 + 0.025 + err["a_rise"]
    want_a_fall = p + 1.0 - 0.025 + err["a_fall"]
    want_b_rise = p + 0.75 - 0.025 + 10 / 360 + err["b_rise"]
    want_b_fall = p + 1.25 + 0.025 + 10 / 360 + err["b_fall"]
    got = {"a_rise": crossings(theta, sig["a"], 1), "a_fall": crossings(theta, sig["a"], 0),
           "b_rise": crossings(theta, sig["b"], 1), "b_fall": crossings(theta, sig["b"], 0)}
    for name, want in (("a_rise", want_a_rise), ("a_fall", want_a_fall),
                       ("b_rise", want_b_rise), ("b_fall", want_b_fall)):
        inside = lambda x: np.sort(x[(x > 1) & (x < 15)])  # away from the sweep's ends
        g, w = inside(got[name]), inside(want)
        assert len(g) == len(w) >= 13, name
        assert np.max(np.abs(g - w)) <= 1 / 20000, name


def test_eccentricity_moves_the_heads_in_opposite_ways_once_per_turn():
    printing = Printing(eccentricity=0.2, eccentricity_phase=0.3)
    L = 64
    theta = np.array([5.0, 20.0, 37.0])
    want = 0.2 * np.sin(2 * np.pi * theta / L + 0.3)
    assert np.allclose(printing.seen(theta, L, head=1) - theta, want)
    assert np.allclose(printing.seen(theta, L, head=2) - theta, -want)


def test_printing_parameters_out_of_range_are_refused():
    for kwargs in ({"duty_a": 0.2}, {"edge_error": 0.2}, {"phase_deg": 45}, {"eccentricity": 0.5}):
        with pytest.raises(ValueError, match=next(iter(kwargs))):
            Printing(**kwargs)


def test_speed_ripple_moves_the_speed_around_its_mean():
    clk = 1e6
    traj = Trajectory(clk_hz=clk, start=0.0).constant(1000.0, 0.02, ripple=0.02, ripple_hz=100.0)
    speed = np.diff(traj.theta) * clk
    assert abs(speed.max() / 1000.0 - 1.02) < 1e-3 and abs(speed.min() / 1000.0 - 0.98) < 1e-3
    # Whole ripple periods (two of 10 ms) travel exactly the mean speed's distance.
    assert abs(traj.theta[-1] - 20.0) < 1e-6
