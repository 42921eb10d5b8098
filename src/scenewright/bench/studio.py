"""``scenewright bench studio``: how the editor feels in a real browser, measured headless.

Debian's chromium is driven by Playwright with software WebGL (SwiftShader), as the studio's
browser test does. Two figures answer the editor's targets:

- **load**: from opening the page until it shows the whole demo scene. ``page_ready_s`` is
  until the page has every object (the "N objects loaded" status comes after them in viser's
  ordered stream); ``page_drawn_s`` until it has drawn two more frames after that.
  ``server_start_s`` is what ``scenewright studio`` does before it prints the URL.
- **drag**: on a 100-object scene, a second WebSocket in the page (in a Web Worker, as viser's
  own is) sends the gizmo's messages (drag start, updates at ``rate`` a second, end) exactly
  as viser's client does when a gizmo is dragged (clicking a gizmo in software WebGL is not
  reliable enough to time). Every update
  carries a sequence number in its x, so each pose the editor shows is matched to the moment
  the page sent it: ``poses_shown_per_second`` (new poses of the dragged object sent back to
  the browsers), the latency from send to shown, how many pose checks the throttle let
  through, what the release committed, and the frame rate of the page meanwhile (software
  WebGL: a figure of this machine, not of the editor).
"""

from __future__ import annotations

import shutil
import socket
import statistics
import tempfile
import time
from importlib import resources
from pathlib import Path
from typing import Any

from scenewright.errors import InputError, MissingExtra
from scenewright.folder import SceneFolder
from scenewright.integrity import assemble_recorded
from scenewright.scene import Constraint, Vec3
from scenewright.settings import Settings


CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = ("--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader")
#: Metres between the x of two drag updates (the sequence number is read back from x).
STEP = 0.01

#: The sender runs in a Web Worker, as viser's own WebSocket does, so the page's drawing (slow
#: in software WebGL) cannot hold it back. A minimal msgpack encoder (maps, strings, numbers as
#: float64, arrays) is enough for the three gizmo messages; viser's client encodes the same
#: with @msgpack/msgpack.
_SENDER = """
self.onmessage = async ({data: {url, protocol, name, x0, y0, z, wxyz, count, rate, step}}) => {
  const bytes = [];
  const put = (...b) => bytes.push(...b);
  const str = (s) => {
    const u = new TextEncoder().encode(s);
    if (u.length < 32) put(0xa0 | u.length); else put(0xd9, u.length);
    put(...u);
  };
  const num = (n) => {
    const v = new DataView(new ArrayBuffer(8)); v.setFloat64(0, n);
    put(0xcb, ...new Uint8Array(v.buffer));
  };
  const val = (x) => {
    if (typeof x === "string") str(x);
    else if (typeof x === "number") num(x);
    else if (Array.isArray(x)) { put(0x90 | x.length); x.forEach(val); }
    else { const k = Object.keys(x); put(0x80 | k.length); k.forEach((key) => { str(key); val(x[key]); }); }
  };
  const encode = (m) => { bytes.length = 0; val(m); return new Uint8Array(bytes); };
  const ws = new WebSocket(url, [protocol]);
  ws.binaryType = "arraybuffer";
  await new Promise((ok, bad) => { ws.onopen = ok; ws.onerror = () => bad(new Error("no websocket")); });
  const sent = [];
  ws.send(encode({type: "TransformControlsDragStartMessage", name, owner: ""}));
  const start = performance.now();
  for (let k = 0; k < count; k++) {
    sent.push((performance.timeOrigin + performance.now()) / 1000);
    ws.send(encode({type: "TransformControlsUpdateMessage", name, wxyz, position: [x0 + k * step, y0, z], owner: ""}));
    const next = start + (k + 1) * 1000 / rate;
    await new Promise((ok) => setTimeout(ok, Math.max(0, next - performance.now())));
  }
  const seconds = (performance.now() - start) / 1000;
  ws.send(encode({type: "TransformControlsDragEndMessage", name, owner: ""}));
  await new Promise((ok) => setTimeout(ok, 200));
  ws.close();
  self.postMessage({sent, seconds});
};
"""

#: Drag from a worker while the page counts the frames it draws meanwhile.
_DRAG_SCRIPT = """
async ([sender, job]) => {
  const worker = new Worker(URL.createObjectURL(new Blob([sender], {type: "text/javascript"})));
  let frames = 0, counting = true;
  const frame = () => { if (counting) { frames += 1; requestAnimationFrame(frame); } };
  requestAnimationFrame(frame);
  const result = await new Promise((ok, bad) => {
    worker.onmessage = (e) => ok(e.data);
    worker.onerror = (e) => bad(new Error(e.message));
    worker.postMessage(job);
  });
  counting = false;
  worker.terminate();
  return {...result, page_frames_per_second: frames / result.seconds};
}
"""

#: Seconds until the page has drawn two more frames (the first whole one after the data).
_FRAMES = """
() => new Promise((ok) => { const t0 = performance.now();
  requestAnimationFrame(() => requestAnimationFrame(() => ok((performance.now() - t0) / 1000))); })
"""


def _playwright():
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        raise MissingExtra("scenewright bench studio", "test", "playwright") from None
    if not CHROMIUM.is_file():
        raise InputError(f"no chromium at {CHROMIUM}: install it with `make chromium` (apt-get install chromium)")
    return sync_playwright


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def demo_scene(root: Path, settings: Settings) -> SceneFolder:
    """The bundled example scene (``make demo``), offline, without renders."""
    from scenewright.backends import backends_from_settings
    from scenewright.pipeline import generate

    text = (resources.files("scenewright") / "data" / "examples" / "living_room.txt").read_text(encoding="utf-8")
    folder = SceneFolder(root)
    generate(text, folder, backends=backends_from_settings(settings), settings=settings, render=False)
    return folder


def tiled_scene(source: SceneFolder, root: Path, count: int) -> SceneFolder:
    """``count`` objects: copies of ``source``'s objects (its meshes, constraints among each
    copy) side by side on a grid, as a large room of many furnished corners is."""
    scene = source.load()
    if not scene.objects:
        raise InputError(f"{source.root} has no objects to tile")
    for sub in (source.assets, source.root / "images"):
        if sub.is_dir():
            shutil.copytree(sub, root / sub.name)
    lo = [min(o.position.x - o.size.x for o in scene.objects), min(o.position.y - o.size.y for o in scene.objects)]
    hi = [max(o.position.x + o.size.x for o in scene.objects), max(o.position.y + o.size.y for o in scene.objects)]
    width, depth = hi[0] - lo[0] + 1.0, hi[1] - lo[1] + 1.0
    copies = -(-count // len(scene.objects))
    side = max(1, round(copies**0.5))
    objects, constraints = [], []
    for k in range(copies):
        dx, dy = (k % side) * width, (k // side) * depth
        ids = {o.id: f"{o.id}_c{k}" for o in scene.objects}
        for o in scene.objects:
            p = o.position
            objects.append(o.model_copy(update={"id": ids[o.id], "position": Vec3(x=p.x + dx, y=p.y + dy, z=p.z)}))
        constraints += [Constraint(relation=c.relation, source=ids[c.source], target=ids[c.target])
                        for c in scene.constraints]
    kept = {o.id for o in objects[:count]}
    rows = -(-copies // side)
    tiled = scene.model_copy(update={
        "objects": objects[:count],
        "constraints": [c for c in constraints if c.source in kept and c.target in kept],
        "bounds": (side * width + 2.0, rows * depth + 2.0) if scene.bounds else None,
        "layout": None,
    })
    folder = SceneFolder(root)
    assemble_recorded(tiled, folder)
    folder.save(tiled)
    return folder


def _session(folder: SceneFolder, settings: Settings):
    from scenewright.backends import backends_from_settings
    from scenewright.studio.session import Session

    return Session(folder, backends=backends_from_settings(settings), settings=settings)


def measure_load(browser, folder: SceneFolder, settings: Settings) -> dict[str, Any]:
    from scenewright.studio.server import Studio

    start = time.perf_counter()
    studio = Studio(_session(folder, settings), port=free_port())
    server_start = time.perf_counter() - start
    try:
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        start = time.perf_counter()
        page.goto(studio.url)
        page.get_by_text(f"{len(studio.session.scene.objects)} objects loaded").wait_for(timeout=120_000)
        ready = time.perf_counter() - start
        drawn = ready + page.evaluate(_FRAMES)
        page.close()
    finally:
        studio.stop()
    return {"objects": len(studio.session.scene.objects), "server_start_s": round(server_start, 3),
            "page_ready_s": round(ready, 3), "page_drawn_s": round(drawn, 3)}


def drag_from_page(page, studio, *, count: int, rate: float, step: float = STEP) -> dict[str, Any]:
    """Drag the selected object's gizmo from ``page`` along +x, ``step`` metres an update:
    ``{"sent": [send time of each update, epoch seconds], "seconds", "page_frames_per_second"}``."""
    import viser

    obj = studio.session.scene.get(studio.selected)
    return page.evaluate(_DRAG_SCRIPT, [_SENDER, {
        "url": studio.url.replace("http", "ws", 1), "protocol": f"viser-v{viser.__version__}", "name": "/gizmo",
        "x0": obj.position.x, "y0": obj.position.y, "z": obj.position.z,
        "wxyz": [float(v) for v in studio._gizmo.wxyz], "count": count, "rate": rate, "step": step}])


def measure_drag(browser, folder: SceneFolder, settings: Settings, *, seconds: float, rate: float) -> dict[str, Any]:
    from scenewright.studio.server import Studio

    studio = Studio(_session(folder, settings), port=free_port())
    applied: list[tuple[float, float]] = []
    shown = studio.move_node

    def recording(obj, x, y, yaw):  # the editor's own step, timed
        shown(obj, x, y, yaw)
        applied.append((time.time(), x))

    studio.move_node = recording
    try:
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        page.goto(studio.url)
        scene = studio.session.scene
        page.get_by_text(f"{len(scene.objects)} objects loaded").wait_for(timeout=120_000)
        middle = sorted(scene.objects, key=lambda o: o.position.x**2 + o.position.y**2)[0]
        studio.select(middle.id)
        checks_before = studio.checks_run
        x0 = middle.position.x
        result = drag_from_page(page, studio, count=int(seconds * rate), rate=rate)
        deadline = time.monotonic() + 120
        while "edit 1" not in studio.status.content and "not done" not in studio.status.content:
            if time.monotonic() > deadline:
                break
            time.sleep(0.05)
        release = studio.status.content
        checks = studio.checks_run - checks_before
        page.close()
    finally:
        studio.stop()
    sent = result["sent"]
    # viser hands each gizmo callback the gizmo's pose as it is when the callback runs, so a
    # callback that starts late shows the newest pose and the ones in between are skipped
    # (never shown out of order). What counts is how many new poses are shown a second.
    first: dict[int, float] = {}  # when each pose was first shown
    for when, x in applied:
        k = round((x - x0) / STEP)
        if 0 <= k < len(sent):
            first.setdefault(k, when)
    latencies = [when - sent[k] for k, when in first.items()]
    times = sorted(first.values())
    span = times[-1] - times[0] if len(times) > 1 else float("nan")
    return {
        "objects": len(scene.objects),
        "dragged": middle.id,
        "updates_sent": len(sent),
        "send_rate_per_second": round(len(sent) / result["seconds"], 1),
        "callbacks": len(applied),
        "poses_shown": len(first),
        "poses_shown_per_second": round((len(times) - 1) / span, 1) if len(times) > 1 else 0.0,
        "latency_ms_median": round(1000 * statistics.median(latencies), 1) if latencies else None,
        "latency_ms_p95": round(1000 * sorted(latencies)[int(0.95 * (len(latencies) - 1))], 1) if latencies else None,
        "pose_checks": checks,
        "pose_checks_per_second": round(checks / result["seconds"], 1),
        "page_frames_per_second": round(result["page_frames_per_second"], 1),
        "on_release": release,
    }


def measure_empty(browser) -> dict[str, Any]:
    """The same load of a bare viser page (one line of text): what the browser costs by itself."""
    import viser

    server = viser.ViserServer(host="127.0.0.1", port=free_port(), verbose=False)
    server.gui.add_markdown("0 objects loaded")
    try:
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        start = time.perf_counter()
        page.goto(f"http://127.0.0.1:{server.get_port()}")
        page.get_by_text("0 objects loaded").wait_for(timeout=120_000)
        ready = time.perf_counter() - start
        drawn = ready + page.evaluate(_FRAMES)
        page.close()
    finally:
        server.stop()
    return {"page_ready_s": round(ready, 3), "page_drawn_s": round(drawn, 3)}


def run(*, objects: int = 100, seconds: float = 5.0, rate: float = 60.0) -> dict[str, Any]:
    """Both measurements; the scenes are made offline in a temporary folder."""
    import os

    sync_playwright = _playwright()
    settings = Settings(cache_dir=None)
    with tempfile.TemporaryDirectory(prefix="scenewright-bench-studio-") as tmp:
        demo = demo_scene(Path(tmp) / "demo", settings)
        large = tiled_scene(demo, Path(tmp) / "large", objects)
        load_before = os.getloadavg()[0]
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=str(CHROMIUM), args=list(CHROMIUM_ARGS))
            try:
                empty = measure_empty(browser)
                load = measure_load(browser, demo, settings)
                large_load = measure_load(browser, large, settings)
                drag = measure_drag(browser, large, settings, seconds=seconds, rate=rate)
            finally:
                browser.close()
    return {
        "browser": f"chromium headless, SwiftShader ({CHROMIUM})",
        "load_empty_viser_page": empty,
        "load_demo": load,
        "load_large": large_load,
        "drag": drag,
        "targets": {"drag_updates_per_second": 20, "demo_load_s": 3.0},
        "load_average_1min_before": round(load_before, 2),
        "load_average_1min_after": round(os.getloadavg()[0], 2),
    }
