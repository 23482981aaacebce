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
    k = len(text[:k]) + len(text[k:]) - len(text[k:].lstrip())
    if text[k] == "(":
        ports, k = balanced(text, k)
    return found.group(1), params, ports


def width_of(rng: str | None) -> str:
    return "1" if not rng else rng.replace(" ", "")


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
    if lat is None:
        LOG.warning("%s: the header comment has no 'Latency' paragraph", rel, type="prenc", subtype="latency")
        lat = "(not stated)"
    out = [f"# `{name}`", "", f"{summary[:1].upper() + summary[1:]}", "", f"Source: `{rel}`", ""]
    out += ["## Parameters", ""]
    if params:
        out += ["| parameter | default |", "|---|---|"]
        out += [f"| `{p}` | `{d.strip()}` |" for p, d in params]
    else:
        out += ["None."]
    out += ["", "## Ports", ""]
    if ports:
        out += ["| port | direction | width |", "|---|---|---|"]
        out += [f"| `{n}` | {d} | `{width_of(w)}` |" for d, w, n in ports]
    else:
        out += ["None: the module checks its parameters and files while it is elaborated."]
    out += ["", "## Latency", "", lat, "", "## From the source's header", "", "```text"]
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
