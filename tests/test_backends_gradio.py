"""The Gradio backend against stand-in apps speaking Gradio's HTTP API on 127.0.0.1."""

from __future__ import annotations

import pytest
import trimesh

from gradio_server import GradioStandIn, trellis_app, triposr_app
from hunyuan_server import png
from scenewright.assets.normalise import check_glb, parse_glb
from scenewright.backends import MeshRequest, create_backend
from scenewright.backends.gradio import RECIPES, Gradio
from scenewright.errors import BackendError, InputError
from scenewright.scene import Vec3
from scenewright.settings import Settings


def box_glb() -> bytes:
    return trimesh.Scene(trimesh.creation.box(extents=(0.8, 1.2, 0.6))).export(file_type="glb")


def box_obj() -> bytes:
    return trimesh.creation.box(extents=(0.5, 0.5, 0.5)).export(file_type="obj").encode()


def requests(n: int) -> list[MeshRequest]:
    return [MeshRequest(id=f"chair_{i}", name="chair", category=None, description="", style="realistic",
                        size=Vec3(x=1, y=1, z=1), image=png((i * 30 % 256, 9, 9))) for i in range(1, n + 1)]


def test_trellis_recipe_runs_its_three_steps_in_one_session_and_fetches_the_glb():
    with trellis_app(box_glb()) as app:
        backend = Gradio([app.url], RECIPES["trellis"])
        reqs = requests(2)
        seen: list[str] = []
        results = backend.generate(reqs, progress=seen.append)
        assert set(results) == {"chair_1", "chair_2"}
        assert all(parse_glb(glb).extents == pytest.approx((0.8, 1.2, 0.6)) for glb in results.values())
        # paid calls: one upload and three endpoint calls per asset, nothing more
        assert app.counts["upload"] == 2
        assert [app.counts[a] for a in ("/preprocess_image", "/image_to_3d", "/extract_mesh")] == [2, 2, 2]
        sessions = {}
        for api, inputs, session in app.calls:
            sessions.setdefault(session, []).append(api)
        assert sorted(sessions.values()) == [["/preprocess_image", "/image_to_3d", "/extract_mesh"]] * 2
        seeds = {inputs[5] for api, inputs, _ in app.calls if api == "/image_to_3d"}
        assert seeds == {1234}
        assert any("step 3 of 3" in line for line in seen)


def test_a_gradio_4_app_without_prefix_and_an_obj_output_gives_a_glb():
    with triposr_app(box_obj()) as app:
        results = Gradio([app.url], RECIPES["triposr"]).generate(requests(1))
        assert check_glb(results["chair_1"]) is None
        assert parse_glb(results["chair_1"]).extents == pytest.approx((0.5, 0.5, 0.5))
        assert app.counts["/preprocess"] == 1 and app.counts["/generate"] == 1


def test_an_error_event_moves_the_job_to_another_app_and_provenance_says_so():
    with trellis_app(box_glb(), fail_api="/extract_mesh", fail_calls=1) as flaky, trellis_app(box_glb()) as good:
        backend = Gradio([flaky.url, good.url], RECIPES["trellis"])
        results = backend.generate(requests(3))
        assert len(results) == 3
        record = backend.provenance(["chair_1", "chair_2", "chair_3"])
        (failed,) = record["failed_attempts"]
        assert failed["server"] == flaky.url and "/extract_mesh ended in error" in failed["error"]
        assert record["built_by"][failed["object"]] == good.url
        # 3 assets + 1 failed attempt = 4 uploads and 4 image_to_3d calls in all
        assert flaky.counts["upload"] + good.counts["upload"] == 4


def test_a_recipe_that_does_not_fit_the_app_fails_with_the_apps_message():
    with trellis_app(box_glb()) as app:
        wrong = RECIPES["trellis2"]  # TRELLIS.2's endpoints on a TRELLIS app
        with pytest.raises(BackendError, match="not found|needed: 11"):
            Gradio([app.url], wrong, max_failures=1).generate(requests(1))


def test_output_urls_pointing_elsewhere_are_not_followed():
    with trellis_app(box_glb()) as app:
        original = app.store

        def store(data, name):
            filedata = original(data, name)
            return {**filedata, "url": "http://169.254.169.254/latest/meta-data"}

        app.store = store
        results = Gradio([app.url], RECIPES["trellis"]).generate(requests(1))
        assert check_glb(results["chair_1"]) is None  # fetched from the app's own /file= route


def test_a_server_that_is_not_a_gradio_app_leaves_the_rotation():
    with trellis_app(box_glb()) as good:
        backend = Gradio(["http://127.0.0.1:9", good.url], RECIPES["trellis"])
        assert len(backend.generate(requests(2))) == 2
        assert "health check failed" in backend.servers[0].retired


def test_spec_recipes_and_settings():
    settings = Settings(mesh_concurrency=2)
    backend = create_backend("meshes", "gradio:http://a:7860,http://b:7860#sf3d", settings)
    assert [s.url for s in backend.servers] == ["http://a:7860", "http://b:7860"]
    assert backend.recipe.name == "sf3d" and backend.slots == 4
    with pytest.raises(InputError, match="unknown gradio recipe 'nope'.*trellis"):
        create_backend("meshes", "gradio:http://a:7860#nope", settings)
    with pytest.raises(InputError, match="an app recipe"):
        create_backend("meshes", "gradio:http://a:7860", settings)
    settings.extra = {"gradio": {"recipes": {"mine": {"steps": [{"api": "/run", "inputs": ["$image", 3]}],
                                                      "output": 0}}, "seed": 7}}
    custom = create_backend("meshes", "gradio:http://a:7860#mine", settings)
    assert custom.recipe.steps[0].api == "/run" and custom.seed == 7
    settings.extra = {"gradio": {"recipes": {"bad": {"steps": [{"api": "run"}]}}}}
    with pytest.raises(InputError, match="gradio recipe 'bad'"):
        create_backend("meshes", "gradio:http://a:7860#bad", settings)


def test_a_custom_recipe_runs_against_its_app():
    def run(inputs, state, app):
        assert inputs[1] == 3
        return ["log text", app.store(box_glb(), "out.glb")]

    with GradioStandIn({"/run": (2, run)}) as app:
        settings = Settings()
        settings.extra = {"gradio": {"recipes": {"mine": {"steps": [{"api": "/run", "inputs": ["$image", 3]}],
                                                          "output": 1}}}}
        backend = create_backend("meshes", f"gradio:{app.url}#mine", settings)
        assert check_glb(backend.generate(requests(1))["chair_1"]) is None


def test_generate_builds_every_asset_on_a_gradio_app(openai_server, tmp_path, monkeypatch):
    from scenewright.testing.fake_openai import CHAT, GENERATE, chat_reply, image_reply
    from scenewright.cli import main
    from scenewright.folder import SceneFolder
    from test_remote_generate import ANSWERS, REFERENCE, TEXT

    (tmp_path / "scenewright.toml").write_text(f'cache_dir = "{(tmp_path / "cache").as_posix()}"\nmax_retries = 1\n')
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("OPENAI_API_KEY", raising=False)
    openai_server.responders[CHAT] = lambda request: chat_reply(ANSWERS[request.schema_name])
    openai_server.responders[GENERATE] = lambda request: image_reply(REFERENCE)
    with trellis_app(box_glb()) as app:
        flags = ["--vlm", "openai:test-model", "--images", "openai:test-image", "--base-url", openai_server.url,
                 "--meshes", f"gradio:{app.url}#trellis", "--no-render"]
        assert main(["generate", TEXT, "--out", "scene", *flags]) == 0
        scene = SceneFolder(tmp_path / "scene").load()
        assert all(o.asset and (tmp_path / "scene" / o.asset).is_file() for o in scene.objects)
        assert app.counts["/extract_mesh"] == len(scene.objects) == 4  # one paid build per object
        event = [e for e in scene.provenance if e.stage == "assets"][-1]
        assert set(event.data["built_by"].values()) == {app.url}
        # a resumed run after losing two assets builds only those two again
        for obj in scene.objects[:2]:
            (tmp_path / "scene" / obj.asset).unlink()
        rest = [f for f in flags if f != "--no-render"]
        assert main(["generate", "--resume", "scene", *rest, "--no-render"]) == 0
        assert app.counts["/extract_mesh"] == 4  # both came from the mesh cache: nothing paid twice
