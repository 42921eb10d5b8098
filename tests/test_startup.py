"""Start-up: importing the package or the command line pulls no heavy dependency.

Every command pays for what ``scenewright.cli`` imports before it runs, ``--help`` included;
the solver, mesh and render stacks are imported inside the commands that use them.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

HEAVY = ("trimesh", "scipy", "fcl", "bpy", "networkx", "shapely", "mujoco", "pxr", "torch")


@pytest.mark.parametrize("module", ["scenewright", "scenewright.cli"])
def test_import_pulls_no_heavy_module(module):
    code = (
        f"import json, sys, {module}\n"
        f"print(json.dumps(sorted(m for m in sys.modules if m.split('.')[0] in {HEAVY!r})))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert json.loads(out.stdout) == []


def test_help_runs_without_heavy_modules():
    code = (
        "import json, sys\n"
        "from scenewright.cli import main\n"
        "main(['--help'])\n"
        f"print(json.dumps(sorted(m for m in sys.modules if m.split('.')[0] in {HEAVY!r})))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "generate" in out.stdout
    assert json.loads(out.stdout.strip().splitlines()[-1]) == []


def test_help_does_not_build_the_document_model():
    """Building the document's pydantic models was a third of ``--help``; the help lists the styles
    and the seed range from plain constants instead. (Typer itself imports pydantic to coerce a
    command's parameters, so only the document model is checked for ``generate --help``.)"""
    code = (
        "import json, sys\n"
        "from scenewright.cli import main\n"
        "main(['--help'])\n"
        "top = sorted(m for m in sys.modules if m.split('.')[0] == 'pydantic' or m == 'scenewright.scene')\n"
        "main(['generate', '--help'])\n"
        "print(json.dumps([top, 'scenewright.scene' in sys.modules]))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "cartoon" in out.stdout  # the --style help names the styles
    assert json.loads(out.stdout.strip().splitlines()[-1]) == [[], False]
