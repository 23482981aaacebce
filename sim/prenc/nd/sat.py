# SPDX-License-Identifier: Apache-2.0
"""SAT back end: is there an (n,d)-sequence of length K, or of length at least K?

The encoding follows the de Bruijn graph (`prenc.nd.graph`) rather than the bits of
one fixed-length string, so that "at least K" is a single instance: one UNSAT answer
proves that no sequence of any length >= K exists, which is what an upper bound
needs (existence is not monotone in K, so a bound from fixed-length instances would
need one per length).

The graph: for d >= 2, two windows that differ only in their last bit would be at
distance 1, so the (n-1)-windows of an (n,d)-sequence are all distinct and the sequence
is a simple cycle of B(n-1), the de Bruijn graph of (n-1)-bit words, whose edges are
its n-windows. For d = 1 (n-windows distinct, (n-1)-windows may repeat) it is a simple
cycle of B(n), whose vertices are the windows. Variables, for B(m):

- `edge[x]` for each (m+1)-bit word x: the cycle goes from vertex x >> 1 to vertex
  x mod 2^m;
- `used[v]`: v is on the cycle; a used vertex has exactly one edge in and one out, so
  the used vertices form disjoint cycles;
- `first[v]`: v is the smallest used vertex (where the sequence starts: this fixes the
  rotation);
- `idx[v]`: B bits, v's place along the cycle: 0 at the first, +1 across every edge
  that does not return to the first. A cycle that does not pass the first vertex would
  need indices that increase all the way round, so all used vertices are on one cycle;
- the edge back into the first vertex leaves the vertex of index K-1 (exactly K) or of
  index >= K-1 (at least K).

Distance: two windows closer than d are never both chosen (one binary clause per pair).

Count (on by default): a totalizer (PySAT's `CardEnc`) says that at least K vertices
are used (and at most K for an exact length). The index already implies it, but only
once the cycle closes; the count lets the solver prune a branch as soon as too few
vertices are left (5 times faster on "(8,2), at least 64"; a cardinality network
instead when the totalizer would pass 4 M clauses).

Symmetry breaking (on by default): the complement, the reversal and both of an
(n,d)-sequence are (n,d)-sequences of the same length. Of the four, the one whose
smallest window is smallest is kept: the smallest window of each variant is selected
like `first` (for the complement, the largest window complemented; for the reversal,
the smallest bit-reversed window) and compared lexicographically with the first
window. With the rotation fixed by `first`, each class of up to 4K equal sequences is
met once or a few times (ties).

The answer is checked independently of the solver: a sequence by
`prenc.nd.sequence.check`; an UNSAT answer, on request, by a DRAT proof that the
solver logs and `dratify` (a checker that shares no code with the solver) replays
against the same clauses. What the proof proves is that the clauses have no
solution; that the clauses say what they should is the tests' job: every answer for
small n and d equals the exhaustive search's.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from itertools import combinations

from .bounds import upper_bound
from .graph import sequence_of_cycle
from .sequence import check

SOLVERS = ("cadical195", "cadical153", "cadical300", "kissat404", "glucose4", "maplechrono")
NO_PROOF = ("kissat404",)  # PySAT keeps no DRAT proof for these


@dataclass(frozen=True)
class Instance:
    """One question: a sequence of exactly `length` windows, or `at_least` that many."""

    n: int
    d: int
    length: int
    at_least: bool = False
    symmetry: bool = True
    count: bool = True

    def __post_init__(self) -> None:
        if not 2 <= self.n <= 14:
            raise ValueError(f"window length n = {self.n} is out of range 2..14 for the SAT search")
        if not 1 <= self.d <= self.n:
            raise ValueError(f"distance d = {self.d} is out of range 1..n")
        bound, reason = upper_bound(self.n, self.d)
        if not 1 <= self.length <= bound:
            raise ValueError(f"length {self.length} is out of range 1..{bound} for ({self.n},{self.d}) "
                             f"({reason}): none longer exists")

    @property
    def question(self) -> str:
        return f"({self.n},{self.d}), length {'>= ' if self.at_least else ''}{self.length}"


@dataclass(frozen=True)
class SatResult:
    instance: Instance
    status: str  # "sat", "unsat" or "unknown" (time limit)
    sequence: str | None
    seconds: float
    solver: str
    variables: int
    clauses: int
    proof_checked: bool | None  # None: no proof asked (or not UNSAT)
    proof_lines: int | None

    def as_dict(self) -> dict:
        inst = self.instance
        return {"n": inst.n, "d": inst.d, "length": inst.length, "at_least": inst.at_least,
                "symmetry": inst.symmetry, "count": inst.count, "status": self.status,
                "sequence": self.sequence,
                "found_length": len(self.sequence) if self.sequence else None,
                "seconds": round(self.seconds, 3), "solver": self.solver,
                "variables": self.variables, "clauses": self.clauses,
                "proof_checked": self.proof_checked, "proof_lines": self.proof_lines}


class _Builder:
    def __init__(self) -> None:
        self.top = 0
        self.clauses: list[list[int]] = []

    def var(self) -> int:
        self.top += 1
        return self.top

    def vars(self, count: int) -> list[int]:
        return [self.var() for _ in range(count)]

    def add(self, clause: list[int]) -> None:
        self.clauses.append(clause)


def _bits_of(value: int, width: int) -> list[int]:
    """Bits of value, MSB first."""
    return [value >> (width - 1 - j) & 1 for j in range(width)]


def _select_min(f: _Builder, chosen: list[int], order: list[int]) -> list[int]:
    """One-hot `sel` over windows: sel[w] <-> chosen[w] and no window before w in `order`.

    Returns sel indexed by window (needs at least one window chosen to be one-hot).
    """
    sel = [0] * len(chosen)
    before = None  # "some window earlier in the order is chosen"
    for w in order:
        s, c = f.var(), chosen[w]
        sel[w] = s
        f.add([-s, c])
        if before is None:
            f.add([s, -c])
        else:
            f.add([-s, -before])
            f.add([s, -c, before])
        nxt = f.var()
        f.add([-nxt, c] + ([before] if before else []))
        f.add([nxt, -c])
        if before:
            f.add([nxt, -before])
        before = nxt
    return sel


def _value_bits(f: _Builder, sel: list[int], width: int, value_of) -> list[int]:
    """Bits (MSB first) of value_of(w) for the window w that `sel` (one-hot) selects."""
    bits = f.vars(width)
    for w, s in enumerate(sel):
        for j, bit in enumerate(_bits_of(value_of(w), width)):
            f.add([-s, bits[j] if bit else -bits[j]])
    return bits


def _lex_leq(f: _Builder, a: list[int], b: list[int]) -> None:
    """a <= b as unsigned numbers, MSB first."""
    equal = None  # a and b equal on the bits so far
    for j in range(len(a)):
        guard = [] if equal is None else [-equal]
        f.add(guard + [-a[j], b[j]])
        if j < len(a) - 1:
            e = f.var()
            f.add(guard + [-a[j], -b[j], e])
            f.add(guard + [a[j], b[j], e])
            equal = e


def encode(inst: Instance) -> tuple[list[list[int]], int, list[int], list[int]]:
    """(clauses, number of variables, window variables c[w], edge variables e[x])."""
    n, d = inst.n, inst.d
    m = n - 1 if d >= 2 else n  # the sequences are the simple cycles of B(m)
    vertices, vmask = 1 << m, (1 << m) - 1
    f = _Builder()
    edge = f.vars(2 * vertices)  # edge x: from vertex x >> 1 to vertex x & vmask
    used = f.vars(vertices)
    for v in range(vertices):
        outs = [edge[v << 1], edge[v << 1 | 1]]
        ins = [edge[v], edge[vertices | v]]
        for group in (outs, ins):
            f.add([-used[v]] + group)
            for e in group:
                f.add([-e, used[v]])
            f.add([-group[0], -group[1]])
    window = edge if d >= 2 else used  # c[w]: window w is one of the sequence's

    errors = [sum(1 << i for i in bits) for r in range(1, d) for bits in combinations(range(n), r)]
    for w in range(1 << n):
        for e in errors:
            if w ^ e > w:
                f.add([-window[w], -window[w ^ e]])
    f.add(list(used))

    first = _select_min(f, used, list(range(vertices)))
    # Index width: the longest sequence the question allows (an upper bound is proven).
    longest = upper_bound(n, d)[0] if inst.at_least else inst.length
    width = max(1, (longest - 1).bit_length())
    last = _bits_of(inst.length - 1, width)
    idx = [f.vars(width) for _ in range(vertices)]
    for v in range(vertices):
        for x in idx[v]:
            f.add([-first[v], -x])
    for e in range(2 * vertices):
        u, v = e >> 1, e & vmask
        a, x, y = edge[e], idx[u], idx[v]
        # Into the first vertex: the cycle closes, u is the last vertex.
        closing = [-a, -first[v]]
        if inst.at_least:
            # x >= length-1: for each bit set in length-1, that bit of x or a higher bit
            # of x that is clear in length-1
            for i in range(width):
                if last[i]:
                    f.add(closing + [x[i]] + [x[j] for j in range(i) if not last[j]])
        else:
            for i in range(width):
                f.add(closing + [x[i] if last[i] else -x[i]])
        # Elsewhere: y = x + 1 without overflow (bits MSB first: the +1 enters at the end).
        step = [-a, first[v]]
        carry = None
        for i in reversed(range(width)):
            if carry is None:
                f.add(step + [y[i], x[i]])
                f.add(step + [-y[i], -x[i]])
                nxt = x[i]
            else:
                f.add(step + [-y[i], x[i], carry])
                f.add(step + [-y[i], -x[i], -carry])
                f.add(step + [y[i], -x[i], carry])
                f.add(step + [y[i], x[i], -carry])
                nxt = f.var()
                f.add([-nxt, x[i]])
                f.add([-nxt, carry])
                f.add([nxt, -x[i], -carry])
            carry = nxt
        f.add(step + [-carry])  # the carry out of the top bit: overflow

    if inst.count:
        from pysat.card import CardEnc, EncType
        from pysat.formula import IDPool

        # The totalizer grows as vertices x K; past 4 M clauses a cardinality network
        # (vertices x log^2) is used instead.
        kind = EncType.totalizer if vertices * inst.length <= 1 << 22 else EncType.cardnetwrk
        pool = IDPool(start_from=f.top + 1)
        card = CardEnc.atleast(lits=list(used), bound=inst.length, vpool=pool, encoding=kind)
        f.clauses.extend(card.clauses)
        f.top = max(f.top, pool.top)
        if not inst.at_least:
            card = CardEnc.atmost(lits=list(used), bound=inst.length, vpool=pool, encoding=kind)
            f.clauses.extend(card.clauses)
            f.top = max(f.top, pool.top)

    if inst.symmetry:
        wmask = (1 << n) - 1
        start = _value_bits(f, _select_min(f, window, list(range(1 << n))), n, lambda w: w)

        def reverse(w: int) -> int:
            return int(format(w, f"0{n}b")[::-1], 2)

        for variant in (lambda w: ~w & wmask, reverse, lambda w: ~reverse(w) & wmask):
            order = sorted(range(1 << n), key=variant)  # windows by their image
            smallest = _value_bits(f, _select_min(f, window, order), n, variant)
            _lex_leq(f, start, smallest)
    return f.clauses, f.top, window, edge


def _decode(model: list[int], edge: list[int], m: int) -> str:
    """The sequence of the cycle of chosen edges in B(m), from its smallest vertex."""
    def true(v: int) -> bool:
        return model[v - 1] > 0

    chosen = [x for x, v in enumerate(edge) if true(v)]
    succ = {}
    for x in chosen:
        if x >> 1 in succ:
            raise AssertionError("the model's chosen edges are not one cycle")
        succ[x >> 1] = x & ((1 << m) - 1)
    start = min(succ)
    cycle, v = [start], succ[start]
    while v != start:
        cycle.append(v)
        v = succ[v]
        if len(cycle) > len(chosen):
            break
    if len(cycle) != len(chosen):
        raise AssertionError("the model's chosen edges are not one cycle")
    return sequence_of_cycle(cycle, m)


def dimacs(clauses: list[list[int]], variables: int, comment: str = "") -> str:
    """The clauses as DIMACS CNF text, comment lines first."""
    head = "".join(f"c {line}\n" for line in comment.splitlines())
    body = "".join(" ".join(map(str, cl)) + " 0\n" for cl in clauses)
    return f"{head}p cnf {variables} {len(clauses)}\n{body}"


def write_dimacs(path: str, clauses: list[list[int]], variables: int, comment: str = "") -> None:
    with open(path, "w") as fh:
        fh.write(dimacs(clauses, variables, comment))


def check_drat(clauses: list[list[int]], variables: int, proof: list[str]) -> bool:
    """True when the DRAT proof derives the empty clause from these clauses (dratify)."""
    from dratify import check_proof, parse_dimacs

    result = check_proof(parse_dimacs(dimacs(clauses, variables)), "\n".join(proof) + "\n")
    return bool(result.ok and result.reached_empty)


def _solve_in_child(conn, clauses: list[list[int]], solver: str, proof_file: str | None) -> None:
    """Child process: run the solver, send back the model (or None / False), write the proof."""
    from pysat.solvers import Solver

    with Solver(name=solver, bootstrap_with=clauses, with_proof=proof_file is not None) as sat:
        answer = sat.solve()
        lines = None
        if not answer and proof_file is not None:
            proof = sat.get_proof()
            lines = len(proof)
            with open(proof_file, "w") as fh:
                fh.write("\n".join(proof) + "\n")
        conn.send((sat.get_model() if answer else False, lines))
    conn.close()


def solve(inst: Instance, *, time_limit: float | None = None, solver: str = "cadical195",
          proof_path: str | None = None, check_proof: bool = False,
          cnf_path: str | None = None) -> SatResult:
    """Answer one instance. A found sequence is checked; UNSAT optionally with DRAT.

    The solver runs in a child process, stopped when `time_limit` (seconds) runs out:
    PySAT's CaDiCaL and Kissat keep Python's lock while they solve, so a timer in this
    process could not interrupt them.
    """
    import multiprocessing
    import os
    import tempfile

    if solver not in SOLVERS:
        raise ValueError(f"solver {solver!r} is not one of {', '.join(SOLVERS)}")
    if (proof_path or check_proof) and solver in NO_PROOF:
        raise ValueError(f"solver {solver} keeps no DRAT proof in PySAT; use cadical195 for --proof "
                         "and --check-proof")
    if time_limit is not None and time_limit <= 0:
        raise ValueError(f"time limit {time_limit} s must be positive")
    start = time.perf_counter()
    clauses, variables, _, edge = encode(inst)
    if cnf_path:
        write_dimacs(cnf_path, clauses, variables, f"prenc nd: {inst.question}")
    want_proof = bool(proof_path or check_proof)
    with tempfile.TemporaryDirectory(prefix="prenc-nd-") as tmp:
        proof_file = (proof_path or os.path.join(tmp, "proof.drat")) if want_proof else None
        ctx = multiprocessing.get_context("fork")
        receive, send = ctx.Pipe(duplex=False)
        child = ctx.Process(target=_solve_in_child, args=(send, clauses, solver, proof_file),
                            daemon=True)
        child.start()
        send.close()
        answer = lines = None
        if receive.poll(time_limit):
            try:
                answer, lines = receive.recv()
            except EOFError:
                child.join()
                raise RuntimeError(f"the solver {solver} stopped without an answer "
                                   f"(exit code {child.exitcode}) on {inst.question}") from None
        child.kill()
        child.join()
        sequence = proof_ok = None
        if answer:
            sequence = _decode(answer, edge, inst.n - 1 if inst.d >= 2 else inst.n)
            check(sequence, inst.n, inst.d)
            if len(sequence) < inst.length or (not inst.at_least and len(sequence) != inst.length):
                raise AssertionError(f"the solver's sequence has length {len(sequence)} for "
                                     f"{inst.question}")
        elif answer is False and check_proof:
            with open(proof_file) as fh:
                proof_ok = check_drat(clauses, variables, fh.read().splitlines())
    status = "sat" if answer else "unsat" if answer is False else "unknown"
    return SatResult(inst, status, sequence, time.perf_counter() - start, solver, variables,
                     len(clauses), proof_ok, lines)


@dataclass(frozen=True)
class Settlement:
    """What a run of questions settled: the longest found, the best proven bound."""

    n: int
    d: int
    lower: int
    sequence: str | None
    upper: int
    upper_reason: str
    tried: tuple[SatResult, ...]

    @property
    def exact(self) -> bool:
        return self.lower == self.upper

    def as_dict(self) -> dict:
        return {"n": self.n, "d": self.d, "length": self.lower, "sequence": self.sequence,
                "upper_bound": self.upper, "upper_bound_reason": self.upper_reason,
                "exact": self.exact,
                "tried": [{"question": r.instance.question, "status": r.status,
                           "found_length": len(r.sequence) if r.sequence else None,
                           "seconds": round(r.seconds, 3)} for r in self.tried]}


def settle(n: int, d: int, *, lower: int = 0, sequence: str | None = None,
           time_limit: float | None = None, solver: str = "cadical195", symmetry: bool = True,
           progress=None) -> Settlement:
    """Raise the longest known (n,d)-sequence and lower the proven bound, by "at least K?".

    First upward: a sequence longer than `lower`? Each one found raises `lower`; an UNSAT
    answer proves `lower` maximal. When a question runs out of `time_limit`, the bound is
    bisected downward between it and the proven upper bound: UNSAT at K proves K - 1,
    a question out of time raises the floor of the next ones.
    """
    upper, reason = upper_bound(n, d)
    if sequence is not None:
        check(sequence, n, d)
        lower = max(lower, len(sequence))
    tried: list[SatResult] = []
    hard = None  # the largest K whose question ran out of time
    while lower < upper:
        if hard is None:
            k = lower + 1
        else:
            low = max(hard, lower) + 1
            if low > upper:
                break
            k = (low + upper + 1) // 2
        result = solve(Instance(n, d, k, at_least=True, symmetry=symmetry), time_limit=time_limit,
                       solver=solver)
        tried.append(result)
        if progress:
            progress(result)
        if result.status == "sat":
            lower, sequence = len(result.sequence), result.sequence
        elif result.status == "unsat":
            upper, reason = k - 1, f"SAT: no sequence of length >= {k} ({solver})"
        else:
            hard = k
    return Settlement(n, d, lower, sequence, upper, reason, tuple(tried))
