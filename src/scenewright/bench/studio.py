"""``scenewright bench studio``: how the editor feels in a real browser, measured headless.

Debian's chromium is driven by Playwright with software WebGL (SwiftShader), as the studio's
browser test does. Two figures answer the editor's targets:

- **load**: from opening the URL until the whole demo scene is drawn and answers clicks
  (``drawn_s``: the first frame with every object, fully opaque, after which the page compiles
  no shader and uploads no texture), with the steps on the way: the HTML received, viser's
  client code decoded and started, the WebSocket open (server clock), the first message, the
  scene's messages handled (the "N objects loaded" status comes after the objects in viser's
  ordered stream), the first frame. A first visit (fresh browser context) and the median of
  reloads; the same for the environment light, and a bare viser page for scale.
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

#: Installed in every page before viser's client runs: marks the client's start-up steps and
#: records, for each frame the page draws, its draw calls, the canvas's opacity (viser keeps it
#: at 5 % while an environment map loads) and whether it compiled a shader program or uploaded
#: a texture (what makes a frame slow in software WebGL). Times are ms since navigation start.
_WATCH = r"""
(() => {
  const T = (window.__studioLoad = {marks: {}, frames: []});
  const mark = (k) => { if (!(k in T.marks)) T.marks[k] = performance.now(); };
  const append = Element.prototype.appendChild;
  Element.prototype.appendChild = function (child) {
    if (child && child.tagName === "SCRIPT" && child.type === "module") mark("client_code_decoded");
    return append.call(this, child);
  };
  const NativeWorker = window.Worker;
  window.Worker = function (...args) {
    mark("client_started");
    const worker = new NativeWorker(...args);
    worker.addEventListener("message", () => mark("first_message"));
    return worker;
  };
  window.Worker.prototype = NativeWorker.prototype;
  let tick = 0, tickTime = -1, frame = null;
  const raf = window.requestAnimationFrame;
  window.requestAnimationFrame = (cb) => raf((ts) => { if (ts !== tickTime) { tickTime = ts; tick++; } return cb(ts); });
  const current = (gl) => {
    if (!frame || frame.tick !== tick) {
      frame = {tick, start: performance.now(), end: 0, draws: 0, work: false,
               opacity: gl.canvas.style ? gl.canvas.style.opacity : ""};
      T.frames.push(frame);
    }
    return frame;
  };
  const P = WebGL2RenderingContext.prototype;
  for (const f of ["drawElements", "drawArrays", "drawElementsInstanced", "drawArraysInstanced"]) {
    const native = P[f];
    P[f] = function (...a) { const r = native.apply(this, a); const fr = current(this); fr.draws++; fr.end = performance.now(); return r; };
  }
  for (const f of ["linkProgram", "texImage2D", "texStorage2D", "compressedTexImage2D"]) {
    const native = P[f];
    P[f] = function (...a) { const r = native.apply(this, a); current(this).work = true; return r; };
  }
  new MutationObserver((records) => {
    for (const m of records) {
      const node = m.type === "characterData" ? m.target : null;
      const texts = node ? [node.textContent] : [...m.addedNodes].map((n) => n.textContent);
      if (texts.some((t) => t && t.includes("objects loaded"))) mark("scene_messages_handled");
    }
  }).observe(document, {childList: true, subtree: true, characterData: true});
})();
"""

#: Whether the page has settled: a second since the scene's messages were handled, and the
#: last two frames compiled nothing, uploaded nothing and drew the canvas fully opaque.
_SETTLED = """
() => { const T = window.__studioLoad, f = T.frames, h = T.marks.scene_messages_handled;
  if (h === undefined || performance.now() - h < 1000 || f.length < 2) return false;
  return f.slice(-2).every((x) => !x.work && (x.opacity === "" || x.opacity === "1")); }
"""

_REPORT = """
() => ({origin: performance.timeOrigin, marks: window.__studioLoad.marks, frames: window.__studioLoad.frames,
        nav: performance.getEntriesByType("navigation")[0].toJSON()})
"""


def load_stages(report: dict[str, Any], connected: float | None) -> dict[str, Any]:
    """Seconds from opening the URL to each step of the load (see :func:`measure_load`).

    ``drawn_s`` is the end of the first frame drawn fully opaque with as many draw calls as the
    settled page draws, after which no frame compiled a shader or uploaded a texture: from then
    on the whole scene is on the screen, lit as it stays, and answers clicks.
    """
    s = 1000.0
    frames = [f for f in report["frames"] if f["draws"]]
    settled = frames[-1]["draws"] if frames else 0
    last_work = max((i for i, f in enumerate(frames) if f["work"]), default=-1)
    drawn = next((f for i, f in enumerate(frames) if i >= last_work and f["draws"] >= settled
                  and f["opacity"] in ("", "1")), None)
    marks = report["marks"]
    stages = {"html_received_s": report["nav"]["responseEnd"] / s,
              **{f"{k}_s": marks[k] / s for k in ("client_code_decoded", "client_started", "first_message") if k in marks},
              "websocket_open_s": connected - report["origin"] / s if connected is not None else None,
              "scene_messages_handled_s": marks["scene_messages_handled"] / s,
              "first_frame_s": frames[0]["start"] / s if frames else None,
              "drawn_s": drawn["end"] / s if drawn else None,
              "frames_until_drawn": frames.index(drawn) + 1 if drawn else None,
              "slowest_frame_s": max((f["end"] - f["start"]) / s for f in frames) if frames else None}
    return {k: (round(v, 3) if isinstance(v, float) else v) for k, v in stages.items()}


def load_page(context, url: str, connected: list[float]) -> dict[str, Any]:
    """Open ``url`` in a new page of ``context`` and time its load (``connected`` receives the
    server's clock when the page's WebSocket opens)."""
    page = context.new_page()
    try:
        page.goto(url)
        page.wait_for_function(_SETTLED, polling=100, timeout=180_000)
        return load_stages(page.evaluate(_REPORT), connected[0] if connected else None)
    finally:
        page.close()


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


def measure_load(browser, folder: SceneFolder, settings: Settings, *, runs: int = 3,
                 detailed_light: bool = False) -> dict[str, Any]:
    """The load as a user feels it: from opening the URL until the whole scene is drawn and
    answers clicks (``drawn_s``, see :func:`load_stages`), with the steps in between.

    The first load is in a fresh browser context (nothing cached: a user's first visit); the
    next ``runs`` open the page again in the same context (a reload; the browser keeps what it
    caches). Each load gets a new editor, as ``scenewright studio`` is started anew.
    """
    from scenewright.studio.server import Studio

    loads, server_starts = [], []
    context = browser.new_context(viewport={"width": 1280, "height": 800})
    context.add_init_script(_WATCH)
    try:
        for _ in range(runs + 1):
            start = time.perf_counter()
            studio = Studio(_session(folder, settings), port=free_port(), detailed_light=detailed_light)
            server_starts.append(time.perf_counter() - start)
            connected: list[float] = []
            studio.server.on_client_connect(lambda _client: connected.append(time.time()))
            try:
                loads.append(load_page(context, studio.url, connected))
            finally:
                studio.stop()
    finally:
        context.close()
    warm = loads[1:]
    drawn = [x["drawn_s"] for x in warm if x["drawn_s"] is not None]
    return {"objects": len(studio.session.scene.objects),
            "server_start_s": round(statistics.median(server_starts), 3),
            "drawn_s_median": round(statistics.median(drawn), 3) if drawn else None,
            "drawn_s_runs": [x["drawn_s"] for x in warm],
            "first_visit": loads[0],
            "reload_median": {k: round(statistics.median(v), 3) for k in warm[0]
                              if (v := [x[k] for x in warm if isinstance(x.get(k), (int, float))])}}


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


def measure_empty(browser, *, runs: int = 3) -> dict[str, Any]:
    """The same loads of a bare viser page (one line of text): what the browser costs by itself."""
    import viser

    loads = []
    context = browser.new_context(viewport={"width": 1280, "height": 800})
    context.add_init_script(_WATCH)
    try:
        for _ in range(runs + 1):
            server = viser.ViserServer(host="127.0.0.1", port=free_port(), verbose=False)
            server.gui.add_markdown("0 objects loaded")
            connected: list[float] = []
            server.on_client_connect(lambda _client: connected.append(time.time()))
            try:
                loads.append(load_page(context, f"http://127.0.0.1:{server.get_port()}", connected))
            finally:
                server.stop()
    finally:
        context.close()
    warm = loads[1:]
    return {"first_visit": loads[0],
            "reload_median": {k: round(statistics.median(v), 3) for k in warm[0]
                              if (v := [x[k] for x in warm if isinstance(x.get(k), (int, float))])}}


def run(*, objects: int = 100, seconds: float = 5.0, rate: float = 60.0, runs: int = 3) -> dict[str, Any]:
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
                empty = measure_empty(browser, runs=runs)
                load = measure_load(browser, demo, settings, runs=runs)
                detailed = measure_load(browser, demo, settings, runs=runs, detailed_light=True)
                large_load = measure_load(browser, large, settings, runs=runs)
                drag = measure_drag(browser, large, settings, seconds=seconds, rate=rate)
            finally:
                browser.close()
    return {
        "browser": f"chromium headless, SwiftShader ({CHROMIUM})",
        "load_empty_viser_page": empty,
        "load_demo": load,
        "load_demo_environment_light": detailed,
        "load_large": large_load,
        "drag": drag,
        "targets": {"drag_updates_per_second": 20, "demo_load_s": 3.0},
        "load_average_1min_before": round(load_before, 2),
        "load_average_1min_after": round(os.getloadavg()[0], 2),
    }
