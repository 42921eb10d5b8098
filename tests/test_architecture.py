"""The layers of docs/architecture.md hold: no module imports a package above its own.

The import graph is read with ``ast`` from the source, so imports inside functions and under
``TYPE_CHECKING`` count as much as those at the top of a module: a lazy import is still a
dependency, it only moves the moment it is paid.
"""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
PACKAGE = SRC / "scenewright"

#: Bottom to top. A package (or top-level module) may import only those in lower rows; the
#: packages of one row are independent of each other. The root ``scenewright`` module is the
#: public face: it sits above everything (it re-exports the stages) and nothing imports it.
LAYERS: list[set[str]] = [
    {"errors", "version", "examples"},
    {"files", "lock", "settings"},
    {"scene", "cache"},
    {"geometry", "folder", "gltf"},
    {"core"},
    {"layout"},
    {"analysis"},
    {"assets", "procedural"},
    {"export", "render"},
    {"integrity"},
    {"editing"},
    {"evaluation"},
    {"backends"},
    {"dataset", "pipeline"},
    {"batch", "studio"},
    {"testing"},
    {"bench"},
    {"cli"},
    {"__main__", "<root>"},
]
RANK = {name: rank for rank, row in enumerate(LAYERS) for name in row}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(SRC).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def imports(path: Path) -> list[tuple[str, int]]:
    """Every ``scenewright`` module the file imports, anywhere in it, with the line."""
    name = module_name(path)
    base = name.split(".") if path.name == "__init__.py" else name.split(".")[:-1]
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                anchor = base[: len(base) - (node.level - 1)]
                targets = [".".join(anchor + ([node.module] if node.module else []))]
            else:
                targets = [node.module or ""]
        elif isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        else:
            continue
        found += [(t, node.lineno) for t in targets if t == "scenewright" or t.startswith("scenewright.")]
    return found


def package_of(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "<root>"


def graph() -> dict[str, list[tuple[str, int]]]:
    return {module_name(p): imports(p) for p in sorted(PACKAGE.rglob("*.py"))}


def test_every_package_has_a_layer():
    packages = {package_of(m) for m in graph()}
    assert packages - RANK.keys() == set(), "give each new package a row in LAYERS (and docs/architecture.md)"


def test_no_module_imports_a_higher_or_sibling_package():
    wrong = []
    for module, targets in graph().items():
        own = package_of(module)
        for target, line in targets:
            other = package_of(target)
            if other != own and RANK[other] >= RANK[own]:
                wrong.append(f"{module}:{line} imports {target} ({other} is not below {own})")
    assert wrong == []


def test_the_package_graph_has_no_cycle():
    edges: dict[str, set[str]] = {}
    for module, targets in graph().items():
        for target, _ in targets:
            if package_of(target) != package_of(module):
                edges.setdefault(package_of(module), set()).add(package_of(target))
    state: dict[str, int] = {}

    def visit(node: str, path: list[str]) -> None:
        if state.get(node) == 1:
            pytest.fail("package cycle: " + " -> ".join(path[path.index(node):] + [node]))
        if state.get(node) == 2:
            return
        state[node] = 1
        for nxt in sorted(edges.get(node, ())):
            visit(nxt, path + [node])
        state[node] = 2

    for node in sorted(edges):
        visit(node, [])


def test_the_check_sees_imports_inside_functions(tmp_path):
    """The walker is not fooled by a lazy import (else the layer test could pass vacuously)."""
    source = tmp_path / "scenewright" / "core" / "x.py"
    source.parent.mkdir(parents=True)
    source.write_text("def f():\n    from scenewright.layout import solve\n    from ..cli import app\n")
    global SRC
    saved, SRC = SRC, tmp_path
    try:
        assert imports(source) == [("scenewright.layout", 2), ("scenewright.cli", 3)]
    finally:
        SRC = saved


def _loaded_after(statement: str) -> set[str]:
    code = f"import sys; {statement}; print('\\n'.join(m for m in sys.modules if m.startswith('scenewright')))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         env={"PYTHONPATH": str(SRC), "PATH": ""})
    return set(out.stdout.split())


def test_importing_the_edit_plan_loads_neither_the_solver_nor_a_stage():
    loaded = _loaded_after("import scenewright.core.plan")
    assert "scenewright.core.plan" in loaded
    assert {package_of(m) for m in loaded} <= {"<root>", "core", "scene", "settings", "errors", "files", "version"}
