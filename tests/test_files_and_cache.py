import pytest

from scenewright.cache import RequestCache, request_key
from scenewright.files import write_atomic


def test_write_atomic_replaces_whole_and_leaves_no_temp(tmp_path):
    target = tmp_path / "deep" / "f.txt"
    write_atomic(target, "one")
    write_atomic(target, b"two")
    assert target.read_bytes() == b"two"
    assert [p.name for p in target.parent.iterdir()] == ["f.txt"]


def test_write_atomic_keeps_the_old_file_when_writing_fails(tmp_path, monkeypatch):
    target = tmp_path / "f.txt"
    write_atomic(target, "old")

    def boom(*a, **k):
        raise OSError("disk full")

    monkeypatch.setattr("os.fsync", boom)
    with pytest.raises(OSError):
        write_atomic(target, "new")
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["f.txt"]


def test_request_key_is_stable_and_sensitive():
    a = request_key("mesh", {"size": [1, 2, 3], "style": "cartoon"}, b"\x89PNG")
    assert a == request_key("mesh", {"style": "cartoon", "size": [1, 2, 3]}, b"\x89PNG")
    assert a != request_key("mesh", {"style": "cartoon", "size": [1, 2, 3]}, b"\x89PNH")
    assert request_key("x") != request_key(b"x")


def test_cache_round_trip_and_disabled(tmp_path):
    cache = RequestCache(tmp_path)
    key = request_key("k")
    assert cache.get("images", key) is None
    cache.put("images", key, b"data")
    assert cache.get("images", key) == b"data"
    off = RequestCache(None)
    off.put("images", key, b"data")
    assert off.get("images", key) is None
