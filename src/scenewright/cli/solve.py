"""``scenewright solve``: the layout engine on the paper's JSON files; ``bench layout``."""

from __future__ import annotations

import json
import logging
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.console import Console

from scenewright.cli.app import app
from scenewright.cli.options import check_seed
from scenewright.errors import InfeasibleLayout, InputError
from scenewright.files import write_atomic

if TYPE_CHECKING:
    from scenewright.scene import SceneObject

log = logging.getLogger(__name__)
#: Metres a footprint may span (20 km: any scene, never an overflow).
MAX_BOUNDS = 20_000.0


def _read_json(path: Path) -> Any:
    try:
        raw = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    try:
        return json.loads(raw)
    except json.JSONDecodeError as exc:
        raise InputError(f"{path}: not valid JSON ({exc.msg} at line {exc.lineno})") from None


def load_objects(path: Path) -> tuple[list[dict], list[SceneObject]]:
    """The paper's object-properties file: ``{"items": [...]}``; raw items and objects."""
    from pydantic import ValidationError  # the document model is loaded by the command, not by --help

    from scenewright.scene import SceneObject, describe_validation_error

    fields = set(SceneObject.model_fields)
    data = _read_json(path)
    if not isinstance(data, dict) or not isinstance(data.get("items"), list):
        raise InputError(f'{path}: expected an object with an "items" list, as {{"items": [{{"id": ...}}]}}')
    raw, objects = [], []
    for k, item in enumerate(data["items"]):
        if not isinstance(item, dict):
            raise InputError(f"{path}: items[{k}] must be an object, got {item!r}")
        extra = sorted(set(item) - fields)
        if extra:
            log.warning("%s: items[%d]: ignoring unknown fields %s", path, k, ", ".join(extra))
        if "size" not in item:
            raise InputError(f"{path}: items[{k}].size: missing; every item needs id, name and size")
        try:
            objects.append(SceneObject.model_validate({f: v for f, v in item.items() if f in fields}))
        except ValidationError as exc:
            raise InputError(f"{path}: items[{k}]: {describe_validation_error(exc)}") from None
        raw.append(item)
    ids = [o.id for o in objects]
    repeated = sorted({x for x in ids if ids.count(x) > 1})
    if repeated:
        raise InputError(f"{path}: items: id {', '.join(map(repr, repeated))} used more than once")
    return raw, objects


def load_constraints(path: Path) -> list[dict]:
    """The paper's constraint list (or ``{"constraints": [...]}``).

    Structural faults (not a list, an entry without relation/source/target) are bad input;
    an unknown relation or object id is left for the solver to drop and report.
    """
    data = _read_json(path)
    if isinstance(data, dict) and isinstance(data.get("constraints"), list):
        data = data["constraints"]
    if not isinstance(data, list):
        raise InputError(f'{path}: expected a JSON list of constraints or {{"constraints": [...]}}')
    for k, c in enumerate(data):
        if not isinstance(c, dict):
            raise InputError(f"{path}: constraints[{k}] must be an object, got {c!r}")
        for field in ("relation", "source", "target"):
            if not isinstance(c.get(field), str):
                raise InputError(f"{path}: constraints[{k}].{field}: missing or not a string")
    return data


def parse_bounds(text: str | None) -> tuple[float, float] | None:
    if text is None:
        return None
    try:
        w, d = (float(v) for v in text.split(","))
    except ValueError:
        raise InputError(f"--bounds: expected W,D in metres (e.g. 8,6), got {text!r}") from None
    if not (0 < w < MAX_BOUNDS and 0 < d < MAX_BOUNDS):
        raise InputError(f"--bounds: width and depth must be finite, > 0 and < {MAX_BOUNDS:g} m, got {text!r}")
    return (w, d)


@app.command("solve")
def solve_command(
    objects_file: Annotated[Path, typer.Argument(metavar="OBJECTS.json", help='{"items": [...]} (paper format).')],
    constraints_file: Annotated[Path, typer.Argument(metavar="CONSTRAINTS.json", help="A list of constraints.")],
    output: Annotated[Path, typer.Option("-o", "--output", help="Where to write LAYOUT.json.")],
    bounds: Annotated[str | None, typer.Option("--bounds", help="Scene footprint W,D in metres, centred.")] = None,
    time_limit: Annotated[float, typer.Option("--time-limit", help="Search budget: seconds of counted work on the reference machine (the same layout on any machine); CPU time stops it at 3x.")] = 10.0,
    seed: Annotated[int, typer.Option("--seed", help="Candidate sampling seed.")] = 0,
) -> None:
    """Place objects so that their constraints hold without collisions; exit 3 if some cannot be."""
    if output.is_dir():
        raise InputError(f"-o {output} is a folder; give the path of the LAYOUT.json file to write")
    check_seed(seed)
    if not 0 < time_limit < float("inf"):
        raise InputError(f"--time-limit must be a finite number of seconds > 0, got {time_limit}")
    from scenewright.layout import feedback_text, solve  # the solver pulls trimesh and fcl: only when solving

    raw, objects = load_objects(objects_file)
    constraints = load_constraints(constraints_file)
    result = solve(objects, constraints, bounds=parse_bounds(bounds), time_limit=time_limit, seed=seed)
    solved = {o.id: o for o in result.objects}
    items = []
    for item in raw:
        o = solved[item["id"]]
        items.append({**item, "position": o.position.model_dump(), "rotation": o.rotation.model_dump()})
    layout = {"items": items, "constraints": [c.model_dump() for c in result.constraints],
              "report": result.report.model_dump(mode="json")}
    write_atomic(output, json.dumps(layout, indent=2) + "\n")
    err = Console(stderr=True)
    err.print(feedback_text(result.report, result.objects), highlight=False, markup=False)
    if result.report.unplaced:
        ids = ", ".join(u.id for u in result.report.unplaced)
        raise InfeasibleLayout(
            f"{len(result.report.unplaced)} of {len(objects)} objects could not be placed ({ids}); "
            f"the layout with them at their initial poses is in {output}"
        )
