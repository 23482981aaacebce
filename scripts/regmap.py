# SPDX-License-Identifier: Apache-2.0
"""The register map of prenc_wb, from its one description (rtl/bus/prenc_wb.rdl, SystemRDL)
through PeakRDL's exporters:

    sw/prenc_wb.h         C header (PeakRDL-cheader): offsets, field masks, a struct
    docs/registers.md     the register map's page: a summary table, then every register
                          and field (PeakRDL-markdown)
    <dir>/prenc_wb/       Python register access (PeakRDL-python, async), with --python

    scripts/regmap.py             write the committed files (after editing the RDL)
    scripts/regmap.py --check     exit 1 if a committed file differs from the RDL's output
    scripts/regmap.py --python D  write the Python register access into D (the tests do)

The committed files are generated sources, checked by tb/lint/test_regmap.py, so that a
user of the core needs neither the RDL tools nor this script.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
RDL = REPO / "rtl" / "bus" / "prenc_wb.rdl"
HEADER = REPO / "sw" / "prenc_wb.h"
DOCS = REPO / "docs" / "registers.md"
NOTICE = "Generated from rtl/bus/prenc_wb.rdl by scripts/regmap.py; do not edit."


def compile_rdl(path: Path = RDL):
    """The elaborated register map (systemrdl-compiler); stops on any RDL error."""
    from systemrdl import RDLCompileError, RDLCompiler

    compiler = RDLCompiler()
    try:
        compiler.compile_file(str(path))
        return compiler.elaborate()
    except RDLCompileError:
        sys.exit(f"regmap: {path.relative_to(REPO)} does not compile (messages above)")


def registers(root) -> list[dict]:
    """Each register: name, byte offset, and its fields (name, lsb, msb, sw access, reset)."""
    out = []
    for reg in root.top.registers():
        fields = [{"name": f.inst_name, "lsb": f.lsb, "msb": f.msb, "sw": access(f),
                   "reset": f.get_property("reset")} for f in reg.fields()]
        out.append({"name": reg.inst_name, "offset": reg.absolute_address, "fields": fields})
    return out


def access(field) -> str:
    """Software access in the usual short form: r, rw, w1c (write 1 to clear), w1p
    (write 1 for a one-clock pulse)."""
    onwrite = field.get_property("onwrite")
    if onwrite is not None and onwrite.name == "woclr":
        return "w1c"
    if field.get_property("singlepulse"):
        return "w1p"
    return field.get_property("sw").name


def c_header(root) -> str:
    from peakrdl_cheader.exporter import CHeaderExporter

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "prenc_wb.h"
        CHeaderExporter().export(root, str(path))
        body = path.read_text()
    return f"// SPDX-License-Identifier: Apache-2.0\n// {NOTICE}\n{body}"


def markdown(root) -> str:
    from peakrdl_markdown import MarkdownExporter

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "registers.md"
        MarkdownExporter().export(root, str(path))
        body = path.read_text()
    body = body.replace("Generated from: $root", f"{NOTICE}")
    head, detail = body.split("\n## ", 1)
    title = ("# Register map\n\n"
             "`prenc_wb`'s registers (Wishbone B4, 32-bit data, word addresses: `wb_adr_i` = byte\n"
             "offset / 4). Access: r read, rw read/write, w1c write 1 to clear, w1p write 1 for a\n"
             "one-clock pulse. The C header `sw/prenc_wb.h` and the tests' Python access are\n"
             "generated from the same RDL ([in your design](guide/in-your-design.md)).\n\n")
    return ("<!-- SPDX-License-Identifier: Apache-2.0 -->\n" + head.strip() + "\n\n"
            + title + summary_table(root) + "\n\n## " + detail)


def summary_table(root) -> str:
    """The summary table: offset, register, fields (bits), access."""
    rows = ["| offset | register | fields (bits) | access |", "|---|---|---|---|"]
    # access: r read only, rw read/write, w1c write 1 to clear, w1p write 1 for a pulse
    for reg in registers(root):
        fields = ", ".join(f"{f['name']} [{f['msb']}:{f['lsb']}]" if f["msb"] != f["lsb"]
                           else f"{f['name']} [{f['lsb']}]" for f in reg["fields"])
        kinds = "/".join(dict.fromkeys(f["sw"] for f in reg["fields"]))
        rows.append(f"| 0x{reg['offset']:02X} | `{reg['name']}` | {fields} | {kinds} |")
    return "\n".join(rows)


def python_access(root, folder: Path) -> Path:
    """PeakRDL-python's async register access, as package `prenc_wb` in folder."""
    from peakrdl_python import PythonExporter

    folder.mkdir(parents=True, exist_ok=True)
    PythonExporter().export(root.top, str(folder), asyncoutput=True, skip_test_case_generation=True)
    return folder / "prenc_wb"


def outputs(root) -> dict[Path, str]:
    return {HEADER: c_header(root), DOCS: markdown(root)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true", help="compare, do not write")
    parser.add_argument("--python", type=Path, metavar="DIR", help="write the Python register access")
    args = parser.parse_args(argv)
    root = compile_rdl()
    if args.python:
        print(python_access(root, args.python))
        return 0
    stale = []
    for path, text in outputs(root).items():
        if path.exists() and path.read_text() == text:
            continue
        if args.check:
            stale.append(str(path.relative_to(REPO)))
        else:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
            print(f"wrote {path.relative_to(REPO)}")
    if stale:
        print(f"regmap: out of date with {RDL.relative_to(REPO)}: {', '.join(stale)}; "
              "run .venv/bin/python scripts/regmap.py", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
