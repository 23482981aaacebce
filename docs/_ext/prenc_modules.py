# SPDX-License-Identifier: Apache-2.0
"""Sphinx extension: one reference page per RTL module, generated from its source.

For every rtl/<subsystem>/prenc_*.v it writes docs/reference/modules/<module>.md (not
kept in git) before Sphinx reads the sources: the module's summary line, its
parameters with their defaults and its ports with direction and width (both read from
the module's ANSI header), the header comment's "Latency" paragraph, and the whole
header comment. A module whose header says nothing of its latency is a build warning,
so `make docs` (warnings as errors) fails on it.
"""

from __future__ import annotations

import re
from pathlib import Path

from sphinx.application import Sphinx
from sphinx.util import logging

LOG = logging.getLogger(__name__)

MODULE = re.compile(r"^\s*module\s+(\w+)\s*", re.M)
PARAM = re.compile(r"parameter\s+(?:integer\s+|real\s+|\[[^\]]*\]\s*)?(\w+)\s*=\s*([^,]+?)\s*(?:,|$)", re.S)
PORT = re.compile(r"^\s*(input|output|inout)\s+(?:wire|reg)?\s*(?:signed\s+)?(\[[^\]]*\])?\s*(\w+)\s*,?",
                  re.M)


def header_comment(text: str) -> list[str]:
    """The comment block at the top of the file, without the SPDX line."""
    lines = []
    for line in text.splitlines():
        if not line.startswith("//"):
            break
        lines.append(line[2:].removeprefix(" ").rstrip())
    return [line for line in lines if not line.startswith("SPDX-License-Identifier")]


def latency(comment: list[str]) -> str | None:
    """The paragraph that starts with 'Latency' (a line of its own or inline)."""
    for k, line in enumerate(comment):
        if re.match(r"\s*Latency\b", line):
            para = [line.strip()]
            for more in comment[k + 1:]:
                if not more.strip():
                    break
                para.append(more.strip())
            return " ".join(para)
    return None


def balanced(text: str, start: int) -> tuple[str, int]:
    """The text inside the parentheses that open at text[start], and the index after them."""
    depth = 0
    for k in range(start, len(text)):
        depth += {"(": 1, ")": -1}.get(text[k], 0)
        if depth == 0:
            return text[start + 1:k], k + 1
    raise ValueError("unbalanced parentheses")


def declaration(text: str) -> tuple[str, str, str] | None:
    """(name, parameter list, port list) of the module's ANSI header."""
    text = re.sub(r"//[^\n]*", "", text)
    found = MODULE.search(text)
    if found is None:
        return None
    k, params, ports = found.end(), "", ""
    if text[k] == "#":
        k = text.index("(", k)
        params, k = balanced(text, k)
    k = len(text) - len(text[k:].lstrip())  # past the blanks
    if text[k] == "(":
        ports, k = balanced(text, k)
    return found.group(1), params, ports


def described(comment: list[str]) -> dict[str, str]:
    """Each name's description from the header's "Parameters" and "Ports" lists: lines
    "  name[, name ...]   what it is", continued on deeper-indented lines."""
    found: dict[str, str] = {}
    names: list[str] = []
    in_list = False
    for line in comment:
        head = line.strip()
        if re.match(r"(Parameters|Ports)\b", head):
            in_list, names = True, []
            continue
        if not head:  # a blank line ends a list that has begun
            in_list = in_list and not names
            continue
        if not in_list:
            continue
        item = re.match(r"^  (\w+(?:\s*(?:,|\.\.\.)\s*\w+)*)\s{2,}(.*)$", line)
        if item and not line.startswith("   "):
            names = [n for n in re.split(r"\s*(?:,|\.\.\.)\s*", item.group(1)) if n]
            for name in names:
                found[name] = item.group(2).strip()
        elif names and line.startswith("   "):
            for name in names:
                found[name] += " " + head
        elif names:  # the list has ended
            in_list = False
    return found


def width_of(rng: str | None) -> str:
    return "1" if not rng else rng.replace(" ", "")


def capital(text: str) -> str:
    return text[:1].upper() + text[1:]


def cell(text: str) -> str:
    """Text for a Markdown table cell."""
    return text.replace("|", "\\|")


def page(source: Path, repo: Path) -> tuple[str, str]:
    text = source.read_text()
    decl = declaration(text)
    if decl is None:
        raise ValueError(f"{source}: no module header found")
    name, param_list, port_list = decl
    params = PARAM.findall(param_list)
    ports = PORT.findall(port_list)
    comment = header_comment(text)
    summary = comment[0].split(":", 1)[-1].strip() if comment else ""
    rel = source.relative_to(repo).as_posix()
    lat = latency(comment)
    meaning = described(comment)
    if lat is None:
        LOG.warning("%s: the header comment has no 'Latency' paragraph", rel, type="prenc", subtype="latency")
        lat = "(not stated)"
    out = [f"# `{name}`", "", capital(summary), "", f"Source: `{rel}`", ""]
    out += ["## Parameters", ""]
    if params:
        out += ["| parameter | default | meaning |", "|---|---|---|"]
        out += [f"| `{p}` | `{d.strip()}` | {cell(meaning.get(p, ''))} |" for p, d in params]
    else:
        out += ["None."]
    out += ["", "## Ports", ""]
    if ports:
        out += ["| port | direction | width | meaning |", "|---|---|---|---|"]
        out += [f"| `{n}` | {d} | `{width_of(w)}` | {cell(meaning.get(n, ''))} |" for d, w, n in ports]
    else:
        out += ["None: the module checks its parameters and files while it is elaborated."]
    out += ["", "## Latency", "", capital(re.sub(r"^Latency:?\s*", "", lat)), "", "## From the source's header", "", "```text"]
    out += comment + ["```", ""]
    return name, "\n".join(out)


def generate(app: Sphinx) -> None:
    docs = Path(app.srcdir)
    repo = docs.parent
    folder = docs / "reference" / "modules"
    folder.mkdir(parents=True, exist_ok=True)
    written = set()
    for source in sorted(repo.glob("rtl/*/prenc_*.v")):
        name, text = page(source, repo)
        target = folder / f"{name}.md"
        written.add(target.name)
        if not target.exists() or target.read_text() != text:
            target.write_text(text)
    for stale in folder.glob("*.md"):
        if stale.name not in written:
            stale.unlink()


def setup(app: Sphinx) -> dict:
    app.connect("builder-inited", generate)
    return {"version": "1.0", "parallel_read_safe": True}
