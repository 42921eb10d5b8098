"""Issue 11 end to end through the CLI: a scene folder confines every path, tampered files and
bad flags give exit 2 with a message (never a traceback), and nothing outside is read or written."""

from __future__ import annotations

import json
import tempfile

import pytest

from editing_scenes import snapshot
from hunyuan_server import png, servers
from scenewright.testing.fake_openai import CHAT, chat_reply
from scenewright.cli import main
from scenewright.folder import SceneFolder

MOVE = "move the armchair a bit to the left"


@pytest.fixture(autouse=True)
def workdir(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("OPENAI_API_KEY", raising=False)


def tamper(folder: SceneFolder, change) -> None:
    data = json.loads(folder.document.read_text())
    change(data)
    folder.document.write_text(json.dumps(data))


def run(capsys, *argv) -> tuple[int, str]:
    code = main([str(a) for a in argv])
    err = capsys.readouterr().err
    assert "Traceback" not in err
    return code, err


# --- 1. local files are never read through a document's paths ----------------------------------


def test_an_outside_glb_named_as_asset_is_not_copied_into_scene_glb(folder, tmp_path, capsys):
    outside = tmp_path / "private.glb"
    outside.write_bytes(folder.asset("sofa_1").read_bytes())
    tamper(folder, lambda d: d["objects"][0].update(asset=str(outside)))
    before = snapshot(folder.root)
    code, err = run(capsys, "edit", folder.root, MOVE)
    assert code == 2
    assert "objects[sofa_1].asset" in err and "is an absolute path" in err
    assert snapshot(folder.root) == before


def test_a_non_glb_asset_is_refused_without_printing_its_bytes(folder, tmp_path, capsys):
    secret = tmp_path / "passwd"
    secret.write_text("root:x:0:0:SECRET-LINE\n")
    (folder.assets / "stolen.glb").symlink_to(secret)
    tamper(folder, lambda d: d["objects"][0].update(asset="assets/stolen.glb"))
    code, err = run(capsys, "edit", folder.root, MOVE)
    assert code == 2 and "leads outside the scene folder" in err and "SECRET" not in err


def test_resume_never_uploads_a_file_outside_the_folder_as_an_object_image(folder, tmp_path, capsys):
    secret = tmp_path / "id_rsa.png"
    secret.write_bytes(png())  # even a real image: outside is outside
    def change(d):
        d["objects"][0].update(image=str(secret), asset=None)
        d["done"] = ["analyze"]
    tamper(folder, change)
    with servers({}) as started:
        code, err = run(capsys, "generate", "--resume", folder.root, "--meshes", f"hunyuan3d:{started[0].url}",
                        "--no-render")
        assert started[0].submitted == []
    assert code == 2 and "objects[sofa_1].image" in err


def test_resume_never_uploads_a_file_that_is_not_an_image(folder, capsys):
    (folder.object_images).mkdir(parents=True, exist_ok=True)
    (folder.object_images / "sofa_1.png").write_text("root:x:0:0:root:/root:/bin/bash\n")
    def change(d):
        d["objects"][0].update(image="images/objects/sofa_1.png", asset=None)
        d["done"] = ["analyze"]
    tamper(folder, change)
    with servers({}) as started:
        code, err = run(capsys, "generate", "--resume", folder.root, "--meshes", f"hunyuan3d:{started[0].url}",
                        "--no-render")
        assert started[0].submitted == []
    assert code == 2 and "is not a readable image" in err


def test_evaluate_judge_never_uploads_a_render_named_outside(folder, tmp_path, openai_server, capsys):
    secret = tmp_path / "holiday.png"
    secret.write_bytes(png())
    folder.renders.mkdir()
    (folder.renders / "renders.json").write_text(json.dumps({"images": {"iso_left": str(secret)}, "best": "iso_left"}))
    openai_server.responders[CHAT] = lambda r: chat_reply("Score: 50")
    code, err = run(capsys, "evaluate", folder.root, "--out", tmp_path / "report", "--judge",
                    "--vlm", "openai:test-model", "--base-url", openai_server.url)
    assert code == 2 and "renders.json images.iso_left" in err
    assert openai_server.requests == []


# --- 2. no write outside through linked sub-folders ---------------------------------------------


@pytest.mark.parametrize(("name", "argv"), [("history", ["edit", MOVE]), ("renders", ["render"]),
                                             ("assets", ["edit", "add a lamp next to the sofa"])])
def test_a_linked_sub_folder_is_refused_and_nothing_lands_elsewhere(folder, tmp_path, capsys, name, argv):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    target = folder.root / name
    if target.exists():
        for child in target.iterdir():
            (elsewhere / child.name).write_bytes(child.read_bytes())
        for child in target.iterdir():
            child.unlink()
        target.rmdir()
    target.symlink_to(elsewhere, target_is_directory=True)
    before = snapshot(elsewhere)
    code, err = run(capsys, argv[0], folder.root, *argv[1:])
    assert code == 2 and f"{name} is a symbolic link" in err
    assert snapshot(elsewhere) == before


# --- 10. tracebacks become exit 2 with a message --------------------------------------------------


def test_a_negative_seed_is_refused_before_any_folder_is_made(tmp_path, capsys):
    code, err = run(capsys, "generate", "a chair", "--out", tmp_path / "new", "--seed", "-5", "--no-render")
    assert code == 2 and "--seed must be an integer from 0" in err
    assert not (tmp_path / "new").exists()


def test_a_path_style_is_refused_before_any_folder_is_made(tmp_path, capsys):
    code, err = run(capsys, "generate", "a chair", "--out", tmp_path / "new", "--style", "../../x", "--no-render")
    assert code == 2 and "style '../../x' must be a name" in err
    assert not (tmp_path / "new").exists()


def test_a_model_name_of_300_characters_is_refused(tmp_path, capsys):
    code, err = run(capsys, "generate", "a chair", "--out", tmp_path / "new", "--vlm", "openai:" + "m" * 300,
                    "--base-url", "http://127.0.0.1:9", "--no-render")
    assert code == 2 and "is not a model name" in err


def test_a_non_json_200_from_the_model_server_is_a_backend_error(tmp_path, openai_server, capsys):
    from scenewright.testing.fake_openai import Reply

    openai_server.responders[CHAT] = lambda r: Reply("<html>502</html>")
    code, err = run(capsys, "generate", "a chair", "--out", tmp_path / "new", "--vlm", "openai:m",
                    "--base-url", openai_server.url, "--no-render")
    assert code == 1 and "body that is not JSON" in err


@pytest.mark.parametrize(
    ("bounds", "seed", "time_limit"), [("nan,5", "0", "1"), ("inf,5", "0", "1"), ("4,5", "-5", "1"), ("4,5", "0", "nan")]
)
def test_solve_refuses_non_finite_bounds_negative_seeds_and_nan_time(tmp_path, capsys, bounds, seed, time_limit):
    (tmp_path / "objects.json").write_text(json.dumps({"items": [{"id": "a", "name": "a", "size": {"x": 1, "y": 1, "z": 1}}]}))
    (tmp_path / "constraints.json").write_text("[]")
    code, err = run(capsys, "solve", tmp_path / "objects.json", tmp_path / "constraints.json", "-o", tmp_path / "out.json",
                    "--bounds", bounds, "--seed", seed, "--time-limit", time_limit)
    assert code == 2
    assert not (tmp_path / "out.json").exists()


def test_solve_to_a_folder_and_evaluate_to_a_file_are_refused(folder, tmp_path, capsys):
    (tmp_path / "objects.json").write_text(json.dumps({"items": []}))
    (tmp_path / "constraints.json").write_text("[]")
    code, err = run(capsys, "solve", tmp_path / "objects.json", tmp_path / "constraints.json", "-o", tmp_path)
    assert code == 2 and "is a folder" in err
    (tmp_path / "existing").write_text("keep me")
    code, err = run(capsys, "evaluate", folder.root, "--out", tmp_path / "existing")
    assert code == 2 and "is a file" in err
    assert (tmp_path / "existing").read_text() == "keep me"


@pytest.mark.parametrize(
    ("name", "content", "message"),
    [
        ("log.jsonl", "garbage\n", "log.jsonl is broken"),
        ("log.jsonl", '{"number": 1}\n', "log.jsonl is broken"),
        ("state.json", '{"current": "x"}', "state.json is broken"),
        ("state.json", '{"current": 7}', "state.json is broken"),
        ("0001.json", "{", "0001.json is broken"),
    ],
)
def test_a_broken_history_is_exit_2_for_every_history_command(folder, capsys, name, content, message):
    assert main(["edit", str(folder.root), MOVE]) == 0
    (folder.history / name).write_text(content)
    before = snapshot(folder.root)
    # A stored version is only needed to go back to it; the log and state are needed by all.
    commands = [["undo"]] if name == "0001.json" else [["undo"], ["redo"], ["history"], ["edit", MOVE]]
    for command in commands:
        code, err = run(capsys, command[0], folder.root, *command[1:])
        assert code == 2 and message in err, (command, err)
    assert snapshot(folder.root) == before


def test_a_broken_renders_json_stops_edit_before_it_saves(folder, capsys):
    folder.renders.mkdir()
    (folder.renders / "renders.json").write_text("{")
    before = snapshot(folder.root)
    code, err = run(capsys, "edit", folder.root, MOVE)
    assert code == 2 and "renders.json is broken" in err
    assert snapshot(folder.root) == before


def test_a_read_only_folder_is_exit_2_naming_the_file(folder, capsys, monkeypatch):
    # Tests run as root here, where chmod cannot make a folder read-only; the OS error is what
    # a read-only folder raises.
    def refuse(*args, **kwargs):
        raise PermissionError(13, "Permission denied", kwargs.get("dir") or args[0] if args else None)

    monkeypatch.setattr(tempfile, "mkstemp", refuse)
    before = snapshot(folder.root)
    code, err = run(capsys, "edit", folder.root, MOVE)
    assert code == 2 and "Permission denied" in err
    assert snapshot(folder.root) == before


@pytest.mark.parametrize("version", [-1, 0, 99])
def test_a_schema_version_that_was_never_written_is_refused(folder, capsys, version):
    tamper(folder, lambda d: d.update(schema_version=version))
    code, err = run(capsys, "edit", folder.root, MOVE)
    assert code == 2 and "schema_version" in err


# --- 11. corrupt, empty or zero-triangle assets ---------------------------------------------------


def _zero_triangle_glb() -> bytes:
    import trimesh

    return trimesh.Scene(trimesh.PointCloud([[0, 0, 0], [1, 1, 1]])).export(file_type="glb")


@pytest.mark.parametrize("content", [b"", b"glTF garbage", "zero-triangles"])
def test_resume_rebuilds_a_corrupt_empty_or_empty_mesh_asset(folder, capsys, content):
    data = _zero_triangle_glb() if content == "zero-triangles" else content
    folder.asset("sofa_1").write_bytes(data)
    code, err = run(capsys, "generate", "--resume", folder.root, "--no-render")
    assert code in (0, 3), err
    from scenewright.assets.load import asset_mesh

    scene = folder.load()
    assert len(asset_mesh(folder.asset_of(scene.get("sofa_1")).read_bytes()).faces) > 0


@pytest.mark.parametrize("content", [b"", b"glTF garbage", "zero-triangles"])
def test_render_refuses_a_corrupt_asset(folder, capsys, content):
    folder.asset("sofa_1").write_bytes(_zero_triangle_glb() if content == "zero-triangles" else content)
    code, err = run(capsys, "render", folder.root, "--draft")
    assert code == 2 and "sofa_1" in err and "--resume" in err
