# SPDX-License-Identifier: Apache-2.0
"""The layout shows the architecture (issue 17): the model's subpackages import one way,
no module imports itself back through another, and every testbench folder sits beside
the RTL subsystem of the module it tests (rtl/<subsystem>/<top>.v, tb/<subsystem>/<top>/)."""

from __future__ import annotations

import ast
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
PACKAGE = REPO / "sim" / "prenc"

# A subpackage imports only from lower layers (and from itself); the top package gives
# __version__ to all.
LAYERS = {"codes": 0, "core": 1, "cal": 1, "bus": 1, "health": 1, "fine": 2, "virtual": 3, "board": 3, "nd": 4, "matrix": 4, "cli": 5}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def runtime_imports(path: Path, modules: set[str]) -> set[str]:
    """prenc modules imported by a file, not counting `if TYPE_CHECKING:` blocks."""
    name = module_name(path)
    package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
    tree = ast.parse(path.read_text())
    skip = {id(n) for node in ast.walk(tree) if isinstance(node, ast.If)
            and getattr(node.test, "id", None) == "TYPE_CHECKING" for n in ast.walk(node)}
    found = set()
    for node in ast.walk(tree):
        if id(node) in skip:
            continue
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            candidates = [target] + [f"{target}.{alias.name}" for alias in node.names]
        elif isinstance(node, ast.Import):
            candidates = [alias.name for alias in node.names]
        else:
            continue
        found |= {c for c in candidates if c in modules and c != name}
    return found


def import_graph() -> dict[str, set[str]]:
    files = {module_name(p): p for p in PACKAGE.rglob("*.py")}
    return {name: runtime_imports(path, set(files)) for name, path in files.items()}


def test_every_subpackage_has_a_layer():
    found = {p.parent.name for p in PACKAGE.glob("*/__init__.py")}
    assert found == set(LAYERS)


def test_subpackages_import_only_from_lower_layers():
    wrong = []
    for name, imports in import_graph().items():
        mine = name.split(".")[1] if name.count(".") else None
        if mine not in LAYERS:  # prenc itself, prenc.__main__
            continue
        for target in imports:
            theirs = target.split(".")[1] if target.count(".") else None
            if theirs in LAYERS and theirs != mine and LAYERS[theirs] >= LAYERS[mine]:
                wrong.append(f"{name} imports {target}")
    assert not wrong, "\n".join(wrong)


def test_no_import_cycle():
    graph = import_graph()
    state: dict[str, int] = {}

    def visit(node: str, path: list[str]) -> None:
        state[node] = 1
        for nxt in sorted(graph[node]):
            if state.get(nxt) == 1:
                raise AssertionError(" -> ".join(path[path.index(nxt):] + [node, nxt]))
            if nxt not in state:
                visit(nxt, path + [node])
        state[node] = 2

    for node in sorted(graph):
        if node not in state:
            visit(node, [])


def test_every_testbench_sits_beside_its_rtl_subsystem():
    for folder in sorted((REPO / "tb").glob("*/prenc_*")):
        subsystem, top = folder.parent.name, folder.name
        assert (REPO / "rtl" / subsystem / f"{top}.v").is_file(), f"tb/{subsystem}/{top}: no rtl/{subsystem}/{top}.v"


def test_every_rtl_module_of_the_core_has_its_model():
    models = {p.stem for p in (PACKAGE / "core").glob("*.py")}
    for source in sorted((REPO / "rtl" / "core").glob("prenc_*.v")):
        stem = source.stem.removeprefix("prenc_")
        # the law is inside track_word; core is reader.py; core_harness only
        # places the core on a small package (synthesis), it reads nothing
        if stem in ("disc_law", "core", "core_harness"):
            continue
        assert stem in models, f"rtl/core/{source.name}: no sim/prenc/core/{stem}.py"
