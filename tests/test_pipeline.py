"""The pipeline and its stages: resumable, recorded, with the feedback loop and quality control."""

from __future__ import annotations

import dataclasses
import io
import json
from collections import Counter

import pytest
from PIL import Image

from scenewright.analysis.stage import analyze
from scenewright.backends import Backends, backends_from_settings
from scenewright.core.protocols import Answer
from scenewright.errors import BackendError, InputError, MissingExtra
from scenewright.folder import DocumentSaver, SceneFolder
from scenewright.layout.stage import arrange
from scenewright.pipeline import generate, resume
from scenewright.scene import DEFAULT_STYLE, Constraint, Scene, SceneObject, Vec3
from scenewright.settings import Settings

TEXT = (
    "A small study: a wooden desk with a laptop on it, an office chair in front of the desk "
    "facing it, and a tall bookshelf to the left of the desk."
)


class Counting:
    """Wraps a backend and counts the calls (and mesh requests) it receives."""

    def __init__(self, inner, fail_after: int | None = None):
        self.inner = inner
        self.name = inner.name
        self.calls: Counter[str] = Counter()
        self.fail_after = fail_after

    def __getattr__(self, attr):
        target = getattr(self.inner, attr)
        if not callable(target):
            return target

        def call(*args, **kwargs):
            self.calls[attr] += 1
            if attr == "generate":
                self.calls["requests"] += len(args[0])
                if self.fail_after is not None and self.calls["requests"] > self.fail_after:
                    raise BackendError("mesh server went away (simulated)")
            return target(*args, **kwargs)

        return call


def _settings() -> Settings:
    return Settings(cache_dir=None)


def _counting(settings: Settings, fail_after: int | None = None) -> Backends:
    real = backends_from_settings(settings)
    return Backends(vlm=Counting(real.vlm), images=Counting(real.images), meshes=Counting(real.meshes, fail_after))


def _png(colour=(200, 100, 50, 255)) -> bytes:
    buf = io.BytesIO()
    Image.new("RGBA", (16, 16), colour).save(buf, "PNG")
    return buf.getvalue()


def test_generate_writes_a_complete_scene_folder(tmp_path):
    folder = SceneFolder(tmp_path / "study")
    scene = generate(TEXT, folder, backends=backends_from_settings(_settings()), settings=_settings(), render=False)
    assert scene.done == ["analyze", "assets", "layout", "export"]
    assert folder.glb.is_file() and folder.ground_image.is_file()
    assert {o.category for o in scene.objects} >= {"desk", "laptop", "office_chair", "bookshelf"}
    stored = json.loads(folder.document.read_text())
    for obj in stored["objects"]:
        assert {"id", "name", "category", "position", "rotation", "size", "visual_description", "asset"} <= set(obj)
        assert (folder.root / obj["asset"]).is_file()
    assert stored["constraints"] and stored["layout"]["placed"]
    assert {e["stage"] for e in stored["provenance"]} >= {"generate", "analyze", "layout", "export"}
    assert scene.backends == {"vlm": "offline", "images": "offline", "meshes": "procedural"}


def test_rerun_of_a_finished_scene_calls_no_backend(tmp_path):
    settings = _settings()
    generate(TEXT, tmp_path / "s", backends=backends_from_settings(settings), settings=settings, render=False)
    backends = _counting(settings)
    generate(TEXT, tmp_path / "s", backends=backends, settings=settings, render=False)
    assert not (backends.vlm.calls + backends.images.calls + backends.meshes.calls)


def test_deleted_glb_is_rebuilt_by_export_alone(tmp_path):
    settings = _settings()
    folder = SceneFolder(tmp_path / "s")
    first = generate(TEXT, folder, backends=backends_from_settings(settings), settings=settings, render=False)
    folder.glb.unlink()
    backends = _counting(settings)
    scene = resume(folder, backends=backends, settings=settings, render=False)
    assert folder.glb.is_file()
    assert not (backends.vlm.calls + backends.images.calls + backends.meshes.calls)
    assert [o.position for o in scene.objects] == [o.position for o in first.objects]


def test_interrupted_asset_stage_resumes_with_only_the_missing_assets(tmp_path):
    settings = _settings()
    folder = SceneFolder(tmp_path / "s")
    with pytest.raises(BackendError, match="simulated"):
        generate(TEXT, folder, backends=_counting(settings, fail_after=2), settings=settings, render=False)
    interrupted = folder.load()
    assert interrupted.done == ["analyze"]
    built = [o.id for o in interrupted.objects if o.asset and folder.resolve(o.asset).is_file()]
    assert 0 < len(built) < len(interrupted.objects)

    backends = _counting(settings)
    scene = resume(folder, backends=backends, settings=settings, render=False)
    assert scene.done == ["analyze", "assets", "layout", "export"]
    assert backends.vlm.calls["describe_objects"] == 0
    assert backends.images.calls["ground_texture"] == 0
    assert backends.meshes.calls["requests"] == len(scene.objects) - len(built)


def test_cache_spares_the_mesh_backend_on_a_fresh_run_of_the_same_text(tmp_path):
    settings = Settings(cache_dir=tmp_path / "cache")
    generate(TEXT, tmp_path / "a", backends=backends_from_settings(settings), settings=settings, render=False)
    backends = _counting(settings)
    generate(TEXT, tmp_path / "b", backends=backends, settings=settings, render=False)
    assert backends.meshes.calls["requests"] == 0


def test_style_from_flag_then_text_then_default(tmp_path):
    backends, settings = backends_from_settings(_settings()), _settings()

    def style_of(text, folder, style=None):
        return generate(text, tmp_path / folder, backends=backends, settings=settings, style=style, render=False).style

    cartoon = "A cartoon-style playground: a red slide next to a blue swing."
    assert style_of(cartoon, "a", style="Steampunk") == "steampunk"
    assert style_of(cartoon, "b") == "cartoon"
    assert style_of("A playground: a red slide next to a blue swing.", "c") == DEFAULT_STYLE


def test_ground_kind_follows_the_text(tmp_path):
    backends, settings = backends_from_settings(_settings()), _settings()
    scene = generate(
        "A park on green grass: an oak tree with a bench in front of it.",
        tmp_path / "p", backends=backends, settings=settings, render=False,
    )
    assert scene.ground.kind == "grass"
    assert scene.ground.texture == "images/ground.png"


def test_folder_holding_another_scene_is_refused_untouched(tmp_path):
    settings = _settings()
    folder = SceneFolder(tmp_path / "s")
    generate(TEXT, folder, backends=backends_from_settings(settings), settings=settings, render=False)
    before = folder.document.read_bytes()
    with pytest.raises(InputError, match="already holds another scene"):
        generate("A kitchen with a fridge.", folder, backends=backends_from_settings(settings), settings=settings)
    assert folder.document.read_bytes() == before


def test_missing_render_extra_is_a_warning(tmp_path, monkeypatch, caplog):
    import scenewright.render

    def no_blender(scene, folder, **kwargs):
        raise MissingExtra("rendering", "render", "bpy")

    monkeypatch.setattr(scenewright.render, "render", no_blender)
    settings = _settings()
    scene = generate(TEXT, tmp_path / "s", backends=backends_from_settings(settings), settings=settings, render=True)
    assert scene.done == ["analyze", "assets", "layout", "export"]
    assert "no preview renders" in caplog.text

    def fake_render(scene, folder, **kwargs):
        folder.renders.mkdir(exist_ok=True)
        (folder.renders / "front.png").write_bytes(_png())
        return [folder.renders / "front.png"]

    monkeypatch.setattr(scenewright.render, "render", fake_render)
    scene = resume(tmp_path / "s", backends=_counting(settings), settings=settings, render=True)
    assert scene.done[-1] == "render"
    assert scene.provenance[-1].data["files"] == ["front.png"]


# --- analysis stage, with a stand-in image backend that draws object images ---------------------


class DrawingImages:
    """An image backend that draws a reference and one image per object (as remote ones do)."""

    name = "drawing"

    def reference_image(self, text, style):
        return _png((1, 2, 3, 255))

    def object_images(self, objects, style, reference, progress=None):
        return {o.id: _png() for o in objects}

    def ground_texture(self, text, style, kind, reference):
        return _png((90, 140, 60, 255))


class RedundantVLM:
    """Says the faucet is already part of the bathtub's image, as in the paper's example."""

    name = "stand-in"

    def __init__(self):
        self.seen_images: dict[str, bytes] = {}

    def describe_objects(self, text, style, reference):
        assert reference is not None
        return Answer([
            SceneObject(id="bathtub_1", name="bathtub", size=Vec3(x=1.7, y=0.8, z=0.6)),
            SceneObject(id="faucet_1", name="faucet", size=Vec3(x=0.1, y=0.2, z=0.3)),
        ])

    def find_redundant(self, objects, images):
        self.seen_images = dict(images)
        return Answer({"faucet_1": "already part of the bathtub's image"})


def test_analyze_saves_images_and_records_removed_objects(tmp_path):
    folder = SceneFolder(tmp_path / "bath")
    folder.create()
    scene = Scene(text="A bathtub with a faucet.")
    vlm = RedundantVLM()
    saver = DocumentSaver(folder, scene, interval=0.0)
    analyze(scene, folder, vlm, DrawingImages(), checkpoint=saver.checkpoint)
    assert folder.reference_image.is_file() and folder.ground_image.is_file()
    assert set(vlm.seen_images) == {"bathtub_1", "faucet_1"}
    assert [o.id for o in scene.objects] == ["bathtub_1"]
    assert scene.objects[0].image == "images/objects/bathtub_1.png"
    assert folder.object_image("faucet_1").is_file()
    assert [(r.id, r.reason) for r in scene.removed] == [("faucet_1", "already part of the bathtub's image")]
    # Checkpoints offered after the objects, their images and quality control, each saved.
    assert saver.saves == 3 and Scene.load(folder.document).removed == scene.removed

    # A second pass finds every output in place and asks nothing again.
    vlm.find_redundant = lambda *a: pytest.fail("quality control ran twice")
    again = analyze(scene, folder, vlm, DrawingImages())
    assert len(again.removed) == 1


def test_analyze_refuses_a_text_without_objects(tmp_path):
    class Nothing(RedundantVLM):
        def describe_objects(self, text, style, reference):
            return Answer([])

    folder = SceneFolder(tmp_path / "x")
    folder.create()
    with pytest.raises(InputError, match="no object"):
        analyze(Scene(text="blue sky"), folder, Nothing(), DrawingImages())


# --- layout stage: the feedback loop -------------------------------------------------------------


class FeedbackVLM:
    """First asks for the impossible (a sofa far from a table inside a 6 m room), then relents."""

    name = "stand-in"

    def __init__(self, give_up: bool):
        self.give_up = give_up
        self.reports = []

    def write_constraints(self, text, objects, reference, room=None):
        return Answer([Constraint(relation="far", source="sofa_1", target="table_1")])

    def revise_constraints(self, text, objects, constraints, report, reference, room=None):
        self.reports.append(report)
        if self.give_up:
            return Answer(list(constraints))
        return Answer([Constraint(relation="near", source="sofa_1", target="table_1")])


def _room(tmp_path) -> tuple[Scene, SceneFolder]:
    folder = SceneFolder(tmp_path / "room")
    folder.create()
    scene = Scene(
        text="a sofa far from a table",
        bounds=(6.0, 6.0),
        objects=[
            SceneObject(id="table_1", name="table", size=Vec3(x=1.2, y=0.8, z=0.75), position=Vec3(z=0.375)),
            SceneObject(id="sofa_1", name="sofa", size=Vec3(x=2.0, y=0.9, z=0.8), position=Vec3(x=2.0, z=0.4)),
        ],
    )
    return scene, folder


def test_feedback_loop_revises_until_the_layout_is_complete(tmp_path):
    from scenewright.layout import check

    scene, folder = _room(tmp_path)
    vlm = FeedbackVLM(give_up=False)
    arrange(scene, folder, vlm, {}, rounds=3, time_limit=2.0)
    assert len(vlm.reports) == 1 and [u.id for u in vlm.reports[0].unplaced] == ["sofa_1"]
    assert scene.layout.complete
    assert [str(c) for c in scene.constraints] == ["sofa_1 near table_1"]
    assert check("near", scene.get("sofa_1"), scene.get("table_1"))
    rounds = [e.data["round"] for e in scene.provenance if e.stage == "layout" and "round" in e.data]
    assert rounds == [0, 1]


def test_feedback_loop_is_bounded_and_keeps_the_best_round(tmp_path):
    scene, folder = _room(tmp_path)
    vlm = FeedbackVLM(give_up=True)
    arrange(scene, folder, vlm, {}, rounds=2, time_limit=1.0)
    assert len(vlm.reports) == 2
    assert not scene.layout.complete and scene.layout.unplaced[0].id == "sofa_1"


class FixedVLM:
    """Writes the constraints it was given and revises nothing."""

    name = "stand-in"

    def __init__(self, constraints):
        self.constraints = constraints

    def write_constraints(self, text, objects, reference, room=None):
        return Answer(list(self.constraints))

    def revise_constraints(self, text, objects, constraints, report, reference, room=None):
        return Answer(list(constraints))


def _crates(tmp_path, room, n: int) -> tuple[Scene, SceneFolder]:
    folder = SceneFolder(tmp_path / "crates")
    folder.create()
    crates = [SceneObject(id=f"crate_{i}", name="crate", size=Vec3(x=0.9, y=0.9, z=0.9), position=Vec3(z=0.45))
              for i in range(n)]
    return Scene(text="crates", objects=crates, room=room), folder


def test_a_room_nobody_sized_grows_until_everything_is_placed_and_reached(tmp_path):
    from scenewright.layout.room import problems
    from scenewright.scene import Opening, Room

    room = Room.model_validate({**Room.rectangle(2.4, 2.4).model_dump(),
                                "openings": [Opening(kind="door", wall=3, offset=1.2, width=0.8, height=2.0)]})
    scene, folder = _crates(tmp_path, room, 5)
    arrange(scene, folder, FixedVLM([]), {}, rounds=0, time_limit=2.0, grow=True)
    grew = [e for e in scene.provenance if e.data.get("step") == "grow room"]
    assert grew and scene.room.wall_length(0) > 2.4
    assert scene.layout.complete and problems(scene.room, scene.objects) == []


def test_a_ceiling_nobody_gave_a_height_is_raised_for_what_hangs_above_another(tmp_path):
    from scenewright.layout import check
    from scenewright.scene import Room

    scene, folder = _crates(tmp_path, Room.rectangle(4.0, 4.0, 2.5), 1)
    scene.objects.append(SceneObject(id="sign_1", name="sign", size=Vec3(x=0.6, y=0.05, z=0.4), position=Vec3(z=1.5)))
    said = [Constraint(relation="above", source="sign_1", target="crate_0"),
            Constraint(relation="on wall", source="sign_1", target="room"),
            Constraint(relation="against wall", source="crate_0", target="room")]

    def lift(objects, constraints, height):
        return 3.0

    arrange(scene, folder, FixedVLM(said), {}, rounds=0, time_limit=2.0, lift=lift)
    assert scene.room.height == 3.0 and any(e.data.get("step") == "raise ceiling" for e in scene.provenance)
    assert check("above", scene.get("sign_1"), scene.get("crate_0"))


def test_arrange_records_the_proposed_poses_once_before_solving(tmp_path):
    scene, folder = _room(tmp_path)
    scene.get("sofa_1").position = Vec3(x=0.3, z=0.4)  # inside the table: the solver has to move it
    proposed = {o.id: (o.position.tuple(), o.rotation.tuple()) for o in scene.objects}
    arrange(scene, folder, FeedbackVLM(give_up=False), {}, rounds=3, time_limit=2.0)
    recorded = {oid: (p.position.tuple(), p.rotation.tuple()) for oid, p in scene.initial.items()}
    assert recorded == proposed
    assert scene.get("sofa_1").position.tuple() != proposed["sofa_1"][0]
    first = {oid: pose.model_copy(deep=True) for oid, pose in scene.initial.items()}
    scene.constraints = []  # arranging again (a resume, a new round of constraints) starts from solved poses
    arrange(scene, folder, FeedbackVLM(give_up=False), {}, rounds=3, time_limit=2.0)
    assert scene.initial == first


# --- the stage table: one save per stage, each asset parsed once, no offline parse for a remote model ---


def test_a_run_saves_the_document_once_per_stage_and_parses_each_asset_once(tmp_path, monkeypatch):
    import importlib

    load = importlib.import_module("scenewright.assets.load")
    normalise = importlib.import_module("scenewright.assets.normalise")  # the package exports a function of that name
    saves, parses, checks, reads = [], [], [], []
    real_save, real_parse, real_read = SceneFolder.save, normalise.parse_glb, load.glb_triangles
    real_check = normalise.glb_triangles
    monkeypatch.setattr(SceneFolder, "save", lambda self, scene: saves.append(list(scene.done)) or real_save(self, scene))

    def counted(data):
        parses.append(len(data))
        return real_parse(data)

    def counted_check(glb):
        checks.append(glb)
        return real_check(glb)

    def counted_read(glb):
        reads.append(glb)
        return real_read(glb)

    monkeypatch.setattr(normalise, "parse_glb", counted)
    monkeypatch.setattr(normalise, "glb_triangles", counted_check)
    monkeypatch.setattr(load, "glb_triangles", counted_read)
    settings = _settings()
    scene = generate(TEXT, tmp_path / "s", backends=backends_from_settings(settings), settings=settings, render=False)
    # The new document, then once after each of the four stages.
    assert saves == [[], ["analyze"], ["analyze", "assets"], ["analyze", "assets", "layout"],
                     ["analyze", "assets", "layout", "export"]]
    # Each asset: the backend's answer read once (the procedural meshes are built to their
    # box, so it is stored as it came: no mesh-library parse) and the stored file's triangles
    # read once (kept for the checks and the solver; the export copies its bytes).
    assert len(checks) == len(scene.objects)
    assert parses == []
    assert len(reads) == len(scene.objects)


def test_the_stage_table_names_each_stage_once_in_order():
    from scenewright.pipeline import PIPELINE, STAGES

    assert STAGES == ("analyze", "assets", "layout", "export", "render")
    assert [s.name for s in PIPELINE] == list(STAGES)


def test_a_remote_model_run_does_not_run_the_offline_parser(tmp_path, monkeypatch):
    import scenewright.analysis.parser as parser

    settings = _settings()
    real = backends_from_settings(settings)

    def refuse(text):
        raise AssertionError("the offline parser ran for a remote model's scene")

    # Stands in for a remote model: it answers with the offline one's answers, and proposes the
    # room (here: none) with its objects, as a remote model does.
    class Proposing(Counting):
        def describe_objects(self, *args):
            self.calls["describe_objects"] += 1
            return dataclasses.replace(self.inner.describe_objects(*args), room=None, proposes_room=True)

    vlm = Proposing(real.vlm)
    vlm.name = "remote-model"
    monkeypatch.setattr(parser, "parse_scene", refuse)
    scene = generate(
        "A cartoon park on green grass: an oak tree with a bench in front of it.", tmp_path / "p",
        backends=Backends(vlm=vlm, images=real.images, meshes=real.meshes), settings=settings, render=False,
    )
    assert scene.style == "cartoon" and scene.ground.kind == "grass"
    assert vlm.calls["describe_objects"] == 1


def test_document_saver_checkpoints_at_most_once_per_interval(tmp_path):
    folder = SceneFolder(tmp_path / "s")
    folder.create()
    now = [0.0]
    saver = DocumentSaver(folder, Scene(text="a chair"), interval=2.0, clock=lambda: now[0])
    for t in (0.5, 1.0, 2.1, 2.5, 4.0, 4.2):
        now[0] = t
        saver.checkpoint()
    assert saver.saves == 2 and folder.is_scene()  # at 2.1 and at 4.1 or later
    saver.save()
    assert saver.saves == 3


def test_generate_passes_the_preview_quality_to_the_render_stage(tmp_path, monkeypatch):
    import scenewright.render

    asked = []

    def fake_render(scene, folder, **kwargs):
        asked.append(kwargs["preview"])
        folder.renders.mkdir(exist_ok=True)
        (folder.renders / "front.png").write_bytes(_png())
        return [folder.renders / "front.png"]

    monkeypatch.setattr(scenewright.render, "render", fake_render)
    settings = _settings()
    generate(TEXT, tmp_path / "s", backends=backends_from_settings(settings), settings=settings, preview="draft")
    assert asked == ["draft"]
