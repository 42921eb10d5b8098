"""Hunyuan3D backend against local servers speaking its protocol, faults included."""

from __future__ import annotations

import pytest

from hunyuan_server import png, servers
from scenewright.assets.normalise import check_glb, parse_glb
from scenewright.backends import MeshRequest, create_backend
from scenewright.backends.hunyuan3d import DEFAULT_PARAMS, Hunyuan3D
from scenewright.errors import BackendError, InputError
from scenewright.scene import Vec3
from scenewright.settings import Settings


def requests(n: int, prefix: str = "crate") -> list[MeshRequest]:
    return [
        MeshRequest(id=f"{prefix}_{i}", name=prefix, category=None, description="", style="realistic",
                    size=Vec3(x=1, y=1, z=1), image=png((i * 20 % 256, 10, 10)))
        for i in range(1, n + 1)
    ]


def backend(started, **kwargs) -> Hunyuan3D:
    kwargs.setdefault("poll_interval", 0.01)
    return Hunyuan3D([s.url for s in started], **kwargs)


def assert_good(results: dict[str, bytes], reqs) -> None:
    assert set(results) == {r.id for r in reqs}
    for glb in results.values():
        assert check_glb(glb) is None
        assert parse_glb(glb).extents == pytest.approx((0.8, 1.2, 0.6))


def test_jobs_spread_over_servers_within_their_concurrency():
    with servers({}, {}) as started:
        reqs = requests(6)
        seen: list[str] = []
        results = backend(started, concurrency=1).generate(reqs, progress=seen.append)
        assert_good(results, reqs)
        sends = [s.counts["send"] for s in started]
        # Both servers take jobs; the exact split follows which one frees its slot first, which a
        # loaded machine decides, so it is not pinned to 3/3.
        assert sum(sends) == 6 and min(sends) >= 1, sends
        assert all(s.counts["health"] == 1 for s in started)
        assert all(s.peak == 1 for s in started)  # never two jobs on a one-slot server
        assert any("completed" in line for line in seen)
        # Every job sent the server's parameters with the image.
        assert sorted(img for s in started for img in s.submitted) == sorted(r.image for r in reqs)


def test_two_slots_per_server_run_two_jobs_at_once():
    with servers({"delay": 0.2}) as started:
        results = backend(started, concurrency=2).generate(requests(4))
        assert len(results) == 4 and started[0].peak == 2


@pytest.mark.parametrize(
    ("fault", "reason"),
    [
        ("die", "connection failed"),
        ("error", "CUDA out of memory"),
        ("bad_base64", "does not decode"),
        ("not_glb", "not a GLB"),
    ],
)
def test_a_failing_server_is_bypassed_and_taken_out_of_rotation(fault, reason, caplog):
    with servers({"fault": fault}, {}) as (bad, good):
        reqs = requests(6)
        h = backend([bad, good], max_failures=2)
        assert_good(h.generate(reqs), reqs)
        assert good.counts["send"] >= 4
        retired = {s.url: s.retired for s in h.servers}
        assert retired[good.url] is None
        assert retired[bad.url] is not None and reason in retired[bad.url]
        assert "taken out of rotation" in caplog.text
        assert h.slots == 1


def test_a_server_that_errors_once_stays_in_rotation():
    with servers({"fault": "error", "fault_jobs": 1}, {}) as (flaky, good):
        reqs = requests(6)
        h = backend([flaky, good], max_failures=2)
        assert_good(h.generate(reqs), reqs)
        assert all(s.retired is None for s in h.servers)
        assert flaky.counts["send"] >= 2  # it kept getting work after its one failure


def test_a_job_lost_to_a_server_restart_is_noticed_and_built_elsewhere(caplog):
    with servers({"fault": "restart", "fault_jobs": 1, "delay": 0.1}, {"delay": 0.1}) as (restarting, good):
        reqs = requests(4)
        h = backend([restarting, good], health_interval=0.02, job_timeout=5)
        assert_good(h.generate(reqs), reqs)
        assert "restarted during job" in caplog.text
        assert h.servers[0].retired is None  # one failure does not retire it
        assert restarting.counts["send"] + good.counts["send"] == 5  # four jobs, one of them twice


def test_untextured_jobs_use_generate_because_status_never_completes_them():
    with servers({}) as (server,):
        reqs = requests(2)
        assert_good(backend([server], params={"texture": False}).generate(reqs), reqs)
        assert server.counts["send"] == 0 and server.counts["generate"] == 2


def test_a_server_with_only_generate_is_used_through_generate():
    with servers({"fault": "generate_only"}) as (old,):
        reqs = requests(3)
        h = backend([old])
        assert_good(h.generate(reqs), reqs)
        assert old.counts["send"] == 0 and old.counts["generate"] == 3
        assert h.servers[0].jobs_api is False


def test_generate_errors_are_seen_even_when_the_status_code_is_not_an_error():
    with servers({"fault": "generate_only"}) as (old,):
        old.fault = "not_glb"  # /generate answers 200 with HTML
        old.counts.clear()
        h = backend([old])
        h.servers[0].jobs_api = False
        with pytest.raises(BackendError, match="without a GLB"):
            h.generate(requests(1))


def test_when_every_server_fails_the_error_names_each_object_and_server():
    with servers({"fault": "error"}, {"fault": "not_glb"}) as started:
        h = backend(started, max_failures=2)
        with pytest.raises(BackendError) as info:
            h.generate(requests(2, "sofa"))
        text = str(info.value)
        assert "sofa_1" in text and "sofa_2" in text
        assert "CUDA out of memory" in text and "not a GLB" in text
        assert "out of rotation" in text and started[0].url in text


def test_an_unhealthy_server_never_gets_a_job():
    with servers({"fault": "unhealthy"}, {}) as (sick, good):
        h = backend([sick, good])
        assert len(h.generate(requests(2))) == 2
        assert sick.counts["send"] == 0 and "health check failed" in h.servers[0].retired


def test_no_usable_server_is_a_clear_error():
    with servers({"fault": "unhealthy"}) as (sick,):
        with pytest.raises(BackendError, match="no Hunyuan3D server is usable.*health check failed"):
            backend([sick]).generate(requests(1))
    with pytest.raises(BackendError, match="unreachable"):
        Hunyuan3D(["http://127.0.0.1:9"], timeout=2).generate(requests(1))


def test_requests_without_images_say_an_image_backend_is_needed():
    reqs = [MeshRequest(id="sofa_1", name="sofa", category="sofa", description="", style="realistic",
                        size=Vec3(x=2, y=1, z=1))]
    with pytest.raises(BackendError, match="sofa_1.*image backend"):
        Hunyuan3D(["http://127.0.0.1:9"]).generate(reqs)


def test_from_spec_reads_urls_concurrency_and_parameters():
    settings = Settings(meshes="hunyuan3d:http://a:8081,http://b:8081/", mesh_concurrency=2, timeout=30)
    settings.extra["hunyuan3d"] = {"texture": False, "seed": 7, "poll_interval": 0.5, "health_interval": 9}
    h = create_backend("meshes", settings.meshes, settings)
    assert [s.url for s in h.servers] == ["http://a:8081", "http://b:8081"]
    assert h.slots == 4 and h.poll_interval == 0.5 and h.health_interval == 9
    assert h.params == {**DEFAULT_PARAMS, "texture": False, "seed": 7}
    with pytest.raises(InputError, match="not an http"):
        Hunyuan3D.from_spec("gpu1:8081", Settings())
    with pytest.raises(InputError, match="at least one server"):
        Hunyuan3D.from_spec("", Settings())
    bad = Settings()
    bad.extra["hunyuan3d"] = {"steps": 30}
    with pytest.raises(InputError, match="num_inference_steps"):
        Hunyuan3D.from_spec("http://a:8081", bad)


def test_bench_assets_prints_one_json_object(capsys):
    import json

    from scenewright.cli import main

    args = ["bench", "assets", "--assets", "4", "--servers", "2", "--delay", "0.05", "--poll", "0.01"]
    assert main([*args, "--fault", "none"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["assets"] == 4 and result["ideal_seconds"] == pytest.approx(0.1)
    assert result["jobs_per_server"] == [2, 2]
    assert result["wall_seconds"] > 0
    assert main([*args, "--fault", "transient"]) == 0
    result = json.loads(capsys.readouterr().out)
    # the flaky server loses one round to its failed job: 3 rounds of 0.05 s hold the 4 assets
    assert result["failed_attempts"] == 1 and result["ideal_seconds"] == pytest.approx(0.15)
    assert sum(result["jobs_per_server"]) == 5


def test_ideal_rounds_count_the_capacity_left_after_failures():
    from scenewright.bench.assets import ideal_rounds

    assert ideal_rounds(16, 4, 0, permanent=False) == 4
    assert ideal_rounds(16, 4, 1, permanent=False) == 5
    assert ideal_rounds(16, 4, 3, permanent=True) == 6
    assert ideal_rounds(12, 4, 1, permanent=False) == 4


def test_a_status_answer_trickled_a_byte_at_a_time_times_out_after_the_deadline():
    # Each byte arrives well within the read timeout; only a total deadline stops the request.
    with servers({"fault": "drip", "fault_jobs": 1}) as started:
        with pytest.raises(BackendError, match=r"timed out after 1 s"):
            backend(started, timeout=1.0, max_failures=1).generate(requests(1))


def test_a_status_answer_without_end_is_cut_at_max_download_bytes():
    with servers({"fault": "flood", "fault_jobs": 1}) as started:
        with pytest.raises(BackendError, match=r"larger than max_download_bytes \(4,194,304 bytes\)"):
            backend(started, timeout=30.0, max_failures=1, max_download_bytes=4 << 20).generate(requests(1))


def test_a_job_turned_away_at_once_is_built_elsewhere_while_that_server_takes_the_next():
    with servers({"fault": "reject", "fault_jobs": 1, "delay": 0.2}, {"delay": 0.2}) as (rejecting, good):
        reqs = requests(4)
        h = backend([rejecting, good])
        assert_good(h.generate(reqs), reqs)
        record = h.provenance([r.id for r in reqs])
        (failed,) = record["failed_attempts"]
        assert failed["server"] == rejecting.url and "HTTP 500" in failed["error"]
        assert rejecting.counts["send"] >= 2  # it kept taking work after turning one away
