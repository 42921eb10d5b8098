"""Speed a user feels: start-up, offline ``generate --no-render``, a move edit, a preview render.

Every figure is a whole ``scenewright`` process, as a user runs it, timed from outside: wall
seconds and CPU seconds (user + system of the process and its children, which is what a
loaded machine cannot inflate). With ``--baseline REV`` the same measurements run on that
git revision's sources too (extracted with ``git archive`` into a temporary folder, run with
the same interpreter and packages), interleaved repeat by repeat so both see the same load,
and the JSON holds both side by side.

Run: ``.venv/bin/python benchmarks/speed.py --baseline 9091e14 [--render]``; prints one JSON
object. ``--prompts FILE...`` times annotated scenes too (the slow layouts of a batch). ``make bench`` runs it against the revision before the speed work.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HEAVY = ("trimesh", "scipy", "fcl", "bpy", "networkx")
#: Five kinds of furniture, ``k`` of each: 15, 30, 60 and 120 objects from one sentence.
TEXT = "a furniture showroom with {k} sofas, {k} armchairs, {k} bookshelves, {k} floor lamps and {k} potted plants"
SIZES = (15, 30, 60, 120)
MOVE = "move the armchair_1 to the left of the bookshelf_2"


def environment(src: Path) -> dict[str, str]:
    """The environment a run of ``src`` gets: its sources first, and bytecode read from the
    caches :func:`compiled` wrote (any value of ``PYTHONDONTWRITEBYTECODE``, "0" too, would
    leave a tree that was never compiled compiling every module on every start)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    return {**env, "PYTHONPATH": str(src)}


def compiled(src: Path) -> Path:
    """``src`` with its bytecode written, as an installed package has it and a user's first run
    leaves it: both columns then start from cached bytecode."""
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(src)], check=True, capture_output=True)
    return src


def timed(command: list[str], src: Path, cwd: Path) -> dict[str, float]:
    """Wall and CPU seconds of one process (with its children) running ``command``."""
    env = environment(src)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode not in (0, 3):  # 3: a layout left objects unplaced, still a whole run
        raise RuntimeError(f"{' '.join(command)} failed ({done.returncode}):\n{done.stderr[-2000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"wall": wall, "cpu": cpu}


def scenewright(*args: str) -> list[str]:
    return [sys.executable, "-m", "scenewright", *args]


def median(runs: list[dict[str, float]]) -> dict[str, float]:
    return {key: round(statistics.median(r[key] for r in runs), 3) for key in ("wall", "cpu")}


def heavy_imports(src: Path) -> list[str]:
    code = (
        "import json, sys, scenewright, scenewright.cli\n"
        f"print(json.dumps(sorted({{m.split('.')[0] for m in sys.modules}} & set({HEAVY!r}))))"
    )
    out = subprocess.run([sys.executable, "-c", code], env=environment(src),
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def slope(points: list[tuple[int, float]]) -> dict[str, float]:
    """Least-squares seconds per object and fixed seconds, and how straight the line is (r²)."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    a = my - b * mx
    total = sum((y - my) ** 2 for y in ys)
    r2 = 1.0 - sum((y - a - b * x) ** 2 for x, y in zip(xs, ys)) / total if total else 1.0
    return {"seconds_per_object": round(b, 4), "fixed_seconds": round(a, 3), "r2": round(r2, 4)}


def render_cpu(src: Path, scene: Path, work: Path, preview: str | None) -> dict[str, float]:
    """CPU seconds of ``scenewright render`` (one view: the chosen one) on a copy of ``scene``."""
    copy = work / f"render-{time.perf_counter_ns()}"
    shutil.copytree(scene, copy)
    args = ["render", str(copy)] + (["--preview", preview] if preview else [])
    try:
        return timed(scenewright(*args), src, work)
    finally:
        shutil.rmtree(copy, ignore_errors=True)


def measure(sources: dict[str, Path], repeats: int, work: Path, render: bool, sizes: tuple[int, ...] = SIZES,
            prompts: dict[str, str] | None = None) -> dict:
    runs: dict[str, dict[str, list]] = {name: {} for name in sources}

    def add(name: str, key: str, value: dict[str, float]) -> None:
        runs[name].setdefault(key, []).append(value)

    scenes: dict[str, dict[int, Path]] = {name: {} for name in sources}
    for rep in range(repeats):
        for name, src in sources.items():  # interleaved: both versions see the same machine load
            add(name, "help", timed(scenewright("--help"), src, work))
            for n in sizes:
                out = work / f"{name}-{n}-{rep}"
                add(name, f"generate_{n}", timed(scenewright("generate", TEXT.format(k=n // 5), "--out", str(out),
                                                               "--no-render"), src, work))
                if rep == 0:
                    scenes[name][n] = out
                else:
                    shutil.rmtree(out, ignore_errors=True)
            for pid, text in (prompts or {}).items():  # annotated scenes: the layouts users wait for
                out = work / f"{name}-{pid}-{rep}"
                add(name, f"generate_{pid}", timed(scenewright("generate", text, "--out", str(out), "--no-render"),
                                                   src, work))
                shutil.rmtree(out, ignore_errors=True)
            for n in [n for n in (15, 60) if n in sizes]:
                copy = work / f"{name}-edit-{n}-{rep}"
                shutil.copytree(scenes[name][n], copy)
                add(name, f"edit_move_{n}", timed(scenewright("edit", str(copy), MOVE), src, work))
                shutil.rmtree(copy, ignore_errors=True)
    result: dict = {}
    for name, src in sources.items():
        figures = {key: median(values) for key, values in runs[name].items()}
        figures["heavy_modules_on_import"] = heavy_imports(src)
        if len(sizes) > 1:
            figures["generate_slope_cpu"] = slope([(n, figures[f"generate_{n}"]["cpu"]) for n in sizes])
            figures["generate_slope_wall"] = slope([(n, figures[f"generate_{n}"]["wall"]) for n in sizes])
        if render and 15 in sizes:  # the render times the 15-object scene
            # One render per version (a before-render is a minute of CPU): the 15-object scene,
            # each version's own default preview, best view only.
            figures["render_default_15"] = {
                k: round(v, 3) for k, v in render_cpu(src, scenes[name][15], work, None if name == "before" else "default").items()
            }
        result[name] = figures
    if len(sources) == 2:
        result["ratio_cpu_before_over_after"] = {
            key: round(result["before"][key]["cpu"] / result["after"][key]["cpu"], 2)
            for key in result["after"] if isinstance(result["after"][key], dict) and "cpu" in result["after"][key]
        }
    result["targets"] = {
        "help_wall_s": 0.5, "generate_15_wall_s": 1.5, "generate_120_wall_s": 5.0,
        "edit_move_15_wall_s": 1.0, "edit_move_60_wall_s": 1.5, "render_default_cpu_s_per_view": 15.0,
    }
    return result


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", help="git revision to measure side by side (the 'before' column)")
    parser.add_argument("--repeats", type=int, default=3, help="runs per figure; medians are reported")
    parser.add_argument("--render", action="store_true", help="also time a default preview render (needs bpy)")
    parser.add_argument("--sizes", default=",".join(map(str, SIZES)),
                        help="object counts to generate (multiples of 5; the edits use 15 and 60 when listed)")
    parser.add_argument("--prompts", nargs="+", type=Path, default=[],
                        help="annotated prompt files (benchmarks/prompts-*/NN_id.json) to generate too, each timed")
    args = parser.parse_args(argv)
    if args.repeats < 1:
        parser.error("--repeats must be at least 1")
    try:
        sizes = tuple(int(n) for n in args.sizes.split(","))
    except ValueError:
        parser.error(f"--sizes takes numbers separated by commas, got {args.sizes!r}")
    if not sizes or any(n < 5 or n % 5 for n in sizes):
        parser.error("--sizes: each count must be a positive multiple of 5 (five kinds of furniture)")
    prompts = {}
    for path in args.prompts:
        entry = json.loads(path.read_text(encoding="utf-8"))
        prompts[entry.get("id", path.stem)] = entry["text"]
    with tempfile.TemporaryDirectory(prefix="scenewright-speed-") as tmp:
        work = Path(tmp)
        sources = {}
        if args.baseline:
            before = work / "before"
            before.mkdir()
            archive = subprocess.run(["git", "-C", str(ROOT), "archive", args.baseline, "src"],
                                     capture_output=True, check=True).stdout
            subprocess.run(["tar", "-x", "-C", str(before)], input=archive, check=True)
            sources["before"] = compiled(before / "src")
        sources["after"] = compiled(ROOT / "src")
        result = {"baseline": args.baseline, "repeats": args.repeats, "cpus": os.cpu_count(),
                  "load_average": [round(x, 2) for x in os.getloadavg()],
                  **measure(sources, args.repeats, work, args.render, sizes, prompts)}
    print(json.dumps(result, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
