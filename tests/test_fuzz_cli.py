"""Issue 11's fuzz test: hostile documents, folders and flags through the CLI.

Hypothesis tampers with a built scene folder (paths to files outside it, links, broken
history and render records, wrong types, huge or hostile strings, corrupt assets) and runs a
command on it; separately it feeds hostile flags to every command. Each run must end in an
exit code (no exception escapes ``main``), nothing outside the folder may change, and no file
outside it may be opened: a trap folder beside the scene holds a real image, a real GLB and a
text file, every hostile path points into it, and an audit hook sees every ``open``.

Blender is replaced by a stand-in that checks the job it would get (every path inside the
folder), so the test stays fast; the counts of examples and findings go to the closing note.
"""

from __future__ import annotations

import json
import os
import shutil
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from editing_scenes import build_folder, snapshot
from hunyuan_server import box_glb, png
from scenewright.cli import main

pytestmark = pytest.mark.filterwarnings("ignore")

EXIT_CODES = {0, 1, 2, 3}

# --- what was opened: one audit hook for the whole session, switched on around each run ------

_opened: list[str] | None = None


def _audit(event: str, args: tuple) -> None:
    if _opened is not None and event == "open" and args and isinstance(args[0], (str, bytes, os.PathLike)):
        _opened.append(os.fsdecode(args[0]))


sys.addaudithook(_audit)


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    root = tmp_path_factory.mktemp("fuzz")
    trap = root / "trap"
    trap.mkdir()
    (trap / "secret.png").write_bytes(png())
    (trap / "secret.glb").write_bytes(box_glb())
    (trap / "passwd").write_text("root:x:0:0:SECRET:/root:/bin/bash\n")
    (trap / "subdir").mkdir()
    template = build_folder(root / "template").root
    main(["edit", str(template), "move the armchair a bit to the left"])
    return root


def run_confined(base: Path, argv: list[str], monkeypatch) -> int:
    """Run ``argv``; fail on an escaping exception, a change outside, or an open of the trap
    that the command line did not ask for (a user may name any file as ``--config``)."""
    global _opened
    trap = base / "trap"
    before = snapshot(trap)
    siblings = {p.name for p in base.iterdir()}
    _opened = []
    try:
        code = main(argv)
    except SystemExit as exc:  # typer's own exits are fine as long as they carry a code
        code = exc.code if isinstance(exc.code, int) else 2
    finally:
        opened, _opened = _opened, None
    assert code in EXIT_CODES, (argv, code)
    assert snapshot(trap) == before, f"{argv} changed the trap folder"
    assert {p.name for p in base.iterdir()} <= siblings | {"scene", "report"}, f"{argv} wrote beside the folder"
    asked = any(str(trap) in a for a in argv)
    inside_trap = [p for p in opened if _resolves_into(p, trap)] if not asked else []
    assert not inside_trap, f"{argv} opened {inside_trap}"
    return code


def _resolves_into(path: str, folder: Path) -> bool:
    try:
        return Path(path).resolve().is_relative_to(folder.resolve())
    except (OSError, RuntimeError, ValueError):
        return False


@pytest.fixture(autouse=True)
def no_blender(monkeypatch, tmp_path):
    """Blender's stand-in: it checks that everything the job names is inside the scene folder."""
    import scenewright.render as render_module

    def fake_worker(job_path, result_path, timeout):
        job = json.loads(Path(job_path).read_text())
        out = Path(job["out_dir"])
        for key in ("glb", "ground_texture"):
            if job[key] is not None:
                assert not _resolves_into(job[key], out.parent.parent / "trap"), f"Blender would read {job[key]}"
        return {"images": {}, "best": job["views"][0], "total_seconds": 0.0, "visible": {}, "missing": []}

    monkeypatch.setattr(render_module, "_run_worker", fake_worker)
    monkeypatch.setattr("importlib.util.find_spec", lambda name, *a: object() if name == "bpy" else _find(name, *a))
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("OPENAI_API_KEY", raising=False)


def _find(name, *args):
    import importlib.machinery

    return importlib.machinery.PathFinder.find_spec(name, *args) if "." not in name else None


# --- tampering strategies --------------------------------------------------------------------

HOSTILE_PATHS = [
    "{trap}/secret.png", "{trap}/secret.glb", "{trap}/passwd", "../trap/secret.png", "../trap/secret.glb",
    "assets/../../trap/secret.glb", "images/../../trap/passwd", "link.png", "link.glb", "~/secret.png",
    "/etc/passwd", "", "assets", "images", ".", "..", "a\x00b.png", "x" * 5000 + ".png", "C:\\secret.png",
    "assets/sofa_1.glb", "images/objects/none.png", "{trap}/subdir",
]
HOSTILE_STRINGS = st.one_of(
    st.sampled_from(["[red]x[/red]", "\x1b[2J\x1b[H", "a" * 65, "x" * 30_000, "", " ", "../../x", "\x00", "[/]"]),
    st.text(max_size=40),
)
NUMBERS = st.one_of(
    st.sampled_from([0, -1, -5, 1, 2**32, 2**64, 0.0, -0.0, 1e-12, 1e6, 1e308, -1e308]),
    st.integers(-10, 10),
)
ANY_JSON = st.recursive(
    st.none() | st.booleans() | NUMBERS | HOSTILE_STRINGS,
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=8), inner, max_size=3),
    max_leaves=6,
)


def _path(value: str, base: Path) -> str:
    return value.replace("{trap}", str(base / "trap"))


@st.composite
def tamperings(draw):
    kind = draw(st.sampled_from([
        "asset", "image", "texture", "string", "number", "wrong_type", "renders_json", "history",
        "linked_subfolder", "linked_file", "corrupt_asset", "document_bytes", "done",
    ]))
    return kind, draw(st.data())


def tamper(folder: Path, base: Path, kind: str, data) -> None:
    document = folder / "scene.json"
    scene = json.loads(document.read_text())
    index = data.draw(st.integers(0, len(scene["objects"]) - 1))
    obj = scene["objects"][index]
    hostile = _path(data.draw(st.sampled_from(HOSTILE_PATHS)), base)
    (folder / "link.png").symlink_to(base / "trap" / "secret.png")
    (folder / "link.glb").symlink_to(base / "trap" / "secret.glb")
    if kind == "asset":
        obj["asset"] = hostile
    elif kind == "image":
        obj["image"] = hostile
        scene["done"] = data.draw(st.sampled_from([["analyze"], scene["done"]]))
        if data.draw(st.booleans()):
            obj["asset"] = None
    elif kind == "texture":
        scene["ground"]["texture"] = hostile
    elif kind == "string":
        field = data.draw(st.sampled_from(["id", "name", "visual_description", "category", "text", "style"]))
        target = scene if field in ("text", "style") else obj
        target[field] = data.draw(HOSTILE_STRINGS)
    elif kind == "number":
        field = data.draw(st.sampled_from(["seed", "schema_version", "size", "position"]))
        value = data.draw(NUMBERS)
        if field in ("seed", "schema_version"):
            scene[field] = value
        else:
            obj[field][data.draw(st.sampled_from("xyz"))] = value
    elif kind == "wrong_type":
        where = data.draw(st.sampled_from(["objects", "constraints", "ground", "object", "done", "initial", "bounds"]))
        value = data.draw(ANY_JSON)
        if where == "object":
            scene["objects"][index] = value
        else:
            scene[where] = value
    elif kind == "renders_json":
        (folder / "renders").mkdir(exist_ok=True)
        content = data.draw(st.one_of(
            st.builds(lambda v, p: json.dumps({"images": {v: p}, "best": v}),
                      st.sampled_from(["front", "iso_left", "x"]), st.just(hostile)),
            ANY_JSON.map(json.dumps), st.just("{"),
        ))
        (folder / "renders" / "renders.json").write_text(content)
    elif kind == "history":
        name = data.draw(st.sampled_from(["log.jsonl", "state.json", "0001.json", "0001.after.json"]))
        content = data.draw(st.one_of(ANY_JSON.map(json.dumps), st.just("{"), st.just("")))
        (folder / "history" / name).write_text(content)
    elif kind == "linked_subfolder":
        name = data.draw(st.sampled_from(["history", "renders", "assets", "images", "images/objects"]))
        target = folder / name
        if target.exists():
            shutil.rmtree(target)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.symlink_to(base / "trap", target_is_directory=True)
    elif kind == "linked_file":
        name = data.draw(st.sampled_from(["scene.glb", "images/reference.png", "images/ground.png",
                                          f"assets/{obj['id']}.glb", "history/state.json", "renders/renders.json"]))
        target = folder / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.unlink(missing_ok=True)
        target.symlink_to(base / "trap" / data.draw(st.sampled_from(["secret.png", "secret.glb", "passwd"])))
    elif kind == "corrupt_asset":
        content = data.draw(st.sampled_from([b"", b"glTF", b"glTF\x02\x00\x00\x00\x0c\x00\x00\x00", b"\x00" * 100]))
        (folder / "assets" / f"{obj['id']}.glb").write_bytes(content)
    elif kind == "done":
        scene["done"] = data.draw(st.lists(st.sampled_from(["analyze", "assets", "layout", "export", "render"]),
                                           max_size=5))
    if kind == "document_bytes":
        document.write_bytes(data.draw(st.sampled_from([b"", b"\xff\xfe", b"[]", b"null", b"{", b"1e999"])))
    else:
        text = json.dumps(scene, allow_nan=True)
        document.write_text(text)


COMMANDS = [
    ["edit", "{folder}", "move the armchair a bit to the left"],
    ["edit", "{folder}", "add a lamp next to the sofa"],
    ["edit", "{folder}", "delete the vase"],
    ["undo", "{folder}"],
    ["redo", "{folder}"],
    ["history", "{folder}"],
    ["render", "{folder}", "--draft"],
    ["evaluate", "{folder}", "--out", "{base}/report"],
    ["generate", "--resume", "{folder}", "--no-render"],
]

#: Examples each fuzz test runs; together they stay well under two minutes on two busy cores.
DOCUMENT_EXAMPLES = 120
FLAG_EXAMPLES = 120


@settings(max_examples=DOCUMENT_EXAMPLES, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(tampering=tamperings(), command=st.sampled_from(COMMANDS))
def test_tampered_folders_never_crash_escape_or_leak(base, monkeypatch, tampering, command):
    folder = base / "scene"
    shutil.rmtree(folder, ignore_errors=True)
    shutil.rmtree(base / "report", ignore_errors=True)
    shutil.copytree(base / "template", folder, symlinks=True)
    kind, data = tampering
    tamper(folder, base, kind, data)
    argv = [a.replace("{folder}", str(folder)).replace("{base}", str(base)) for a in command]
    run_confined(base, argv, monkeypatch)


FLAG_VALUES = st.one_of(
    st.sampled_from(["-5", "0", "nan", "inf", "-inf", "1e308", "100000x100000", "0x0", "16x16", "1x2x3", "nan,5",
                     "4,5", "-1,3", "../../x", "[red]x", "\x1b[2J", "", "x" * 300, "{trap}/passwd", "{trap}",
                     "{base}/scene", "openai:" + "m" * 300, "hunyuan3d:ftp://x", "library:{trap}", "999999999999"]),
    st.text(max_size=12),
)
OPTIONS = {
    "generate": ["--out", "--style", "--seed", "--resume", "--vlm", "--images", "--meshes", "--timeout",
                 "--feedback-rounds", "--max-faces", "--image-concurrency", "--config"],
    "render": ["--views", "--resolution", "--samples", "--config"],
    "solve": ["-o", "--bounds", "--time-limit", "--seed"],
    "edit": ["--vlm", "--meshes", "--timeout", "--config"],
    "evaluate": ["--out", "--group", "--clip-weights", "--config"],
}


@st.composite
def command_lines(draw, base: Path):
    command = draw(st.sampled_from(sorted(OPTIONS)))
    value = lambda: _path(draw(FLAG_VALUES), base).replace("{base}", str(base))  # noqa: E731
    argv = [command]
    if command == "generate":
        argv.append(draw(st.sampled_from(["a chair next to a table", "", "   ", "[red]", "x" * 30_000])))
    elif command == "solve":
        argv += [str(base / "objects.json"), str(base / "constraints.json")]
    else:
        argv.append(draw(st.sampled_from([str(base / "template"), str(base / "trap"), "{trap}/passwd", ""]))
                    .replace("{trap}", str(base / "trap")))
    for option in draw(st.lists(st.sampled_from(OPTIONS[command]), max_size=4, unique=True)):
        argv += [option, value()]
    if command in ("generate", "edit"):
        argv += ["--no-render"] if command == "generate" else ["move the sofa left"]
    return argv


@settings(max_examples=FLAG_EXAMPLES, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(data=st.data())
def test_hostile_flags_never_crash_escape_or_leak(base, monkeypatch, data):
    template = base / "template"
    pristine = snapshot(template)
    (base / "objects.json").write_text(json.dumps({"items": [{"id": "a", "name": "a", "size": {"x": 1, "y": 1, "z": 1}}]}))
    (base / "constraints.json").write_text("[]")
    argv = data.draw(command_lines(base))
    shutil.rmtree(base / "scene", ignore_errors=True)
    try:
        run_confined(base, argv, monkeypatch)
    finally:
        if snapshot(template) != pristine:  # an edit of the template is fine; keep it pristine for the next
            shutil.rmtree(template)
            build_folder(template)
