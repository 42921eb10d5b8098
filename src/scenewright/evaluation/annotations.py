"""Annotated scene descriptions (``benchmarks/prompts*``) and matching scene objects to their keys.

An annotation names things by *key*: the catalogue category when the thing is in the catalogue,
else the head noun as written with underscores (``camel``, ``ferris_wheel``). Older files have
catalogue keys only, no ``between`` entries and no ``supports`` map (everything on the ground);
they load unchanged.

Matching is what lets one scorer judge both the parser's output and the final scene, whatever
category an unknown thing was guessed as: an object belongs to the key its category names, or,
for a key outside the catalogue, to the key whose words all appear in the object's name.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from scenewright.core.catalogue import load_catalogue, singular, words
from scenewright.errors import InputError
from scenewright.scene import RELATION_TYPES

#: Supports that are not another object; the scorer cannot check them and counts them apart.
UNCHECKED_SUPPORTS = ("wall", "ceiling", "air")
GROUND = "ground"


@dataclass(frozen=True)
class Prompt:
    id: str
    domain: str
    style: str
    text: str
    #: key → (least, most)
    objects: dict[str, tuple[int, int]]
    #: (source key, relation, target key)
    relations: frozenset[tuple[str, str, str]]
    #: (source key, first target key, second target key): the source stands between the two
    between: frozenset[tuple[str, str, str]] = frozenset()
    #: key → the key it rests on, or wall / ceiling / air; keys left out stand on the ground
    supports: Mapping[str, str] = field(default_factory=dict)

    def support_of(self, key: str) -> str:
        return self.supports.get(key, GROUND)

    @property
    def stated(self) -> int:
        """How many relations the text states (a between entry is one)."""
        return len(self.relations) + len(self.between)


def default_prompt_dir() -> Path:
    """``benchmarks/prompts`` of the source tree this package runs from, else of the cwd."""
    here = Path(__file__).resolve().parents[3] / "benchmarks" / "prompts"
    return here if here.is_dir() else Path("benchmarks/prompts")


def _count(value) -> tuple[int, int]:
    lo, hi = (int(value[0]), int(value[1])) if isinstance(value, list) else (int(value), int(value))
    if lo < 0 or hi < lo:
        raise ValueError(f"count {value!r} must be N or [least, most] with 0 <= least <= most")
    return lo, hi


def parse_prompt(raw: dict) -> Prompt:
    """One annotation from its JSON; raises ``KeyError``/``TypeError``/``ValueError`` naming the problem."""
    objects = {str(key): _count(v) for key, v in raw["objects"].items()}
    relations, between = set(), set()
    for entry in raw["relations"]:
        if len(entry) == 4 and entry[1] == "between":
            between.add((entry[0], entry[2], entry[3]))
            names = (entry[0], entry[2], entry[3])
        elif len(entry) == 3 and entry[1] in RELATION_TYPES:
            relations.add(tuple(entry))
            names = (entry[0], entry[2])
        else:
            raise ValueError(
                f"relation {entry!r} must be [source, relation, target] with one of {', '.join(RELATION_TYPES)}, "
                "or [source, 'between', A, B]"
            )
        unknown = [n for n in names if n not in objects]
        if unknown:
            raise ValueError(f"relation {entry!r} names {', '.join(unknown)}, not among the objects")
    supports = dict(raw.get("supports", {}))
    for key, host in supports.items():
        if key not in objects or (host not in objects and host not in UNCHECKED_SUPPORTS):
            raise ValueError(
                f"supports {key!r}: {host!r} needs an object key on both sides, or {', '.join(UNCHECKED_SUPPORTS)}"
            )
    return Prompt(
        id=str(raw["id"]),
        domain=str(raw["domain"]),
        style=str(raw["style"]),
        text=str(raw["text"]),
        objects=objects,
        relations=frozenset(relations),  # type: ignore[arg-type]
        between=frozenset(between),  # type: ignore[arg-type]
        supports=supports,
    )


def load_prompts(folder: Path | str | None = None) -> list[Prompt]:
    """Every ``*.json`` annotation in ``folder`` (default: the shipped ``benchmarks/prompts``), by file name."""
    folder = Path(folder) if folder else default_prompt_dir()
    if folder.is_file():
        files = [folder]
    else:
        files = sorted(folder.glob("*.json"))
    if not files:
        raise InputError(f"{folder}: no prompt files (*.json); pass --prompts DIR")
    prompts = []
    for path in files:
        try:
            prompts.append(parse_prompt(json.loads(path.read_text(encoding="utf-8"))))
        except (json.JSONDecodeError, KeyError, TypeError, ValueError, IndexError) as exc:
            raise InputError(f"{path}: not a prompt file ({exc})") from None
    return prompts


def _name_words(name: str) -> set[str]:
    return {singular(w) for w in words(name)}


def assign_keys(objects: Iterable[tuple[str, str | None, str]], keys: Iterable[str]) -> dict[str, str]:
    """Object id → the annotation key it counts as, for ``(id, category, name)`` triples.

    Its category when that is a key, unless a key outside the catalogue has all its words, the
    name's last word among them, in the name and the category's words are not all there (a "bot"
    drawn as a robot is the ``bot``, a "gas lamp post" the ``lamp_post``); else, among the keys
    outside the catalogue, the one with the most words that all appear in the name or the
    category (``fuel_tank`` in "white fuel tank"). Objects matching no key are left out.
    """
    keys = list(keys)
    catalogue = load_catalogue()
    open_keys = sorted(
        ((k, {singular(w) for w in k.split("_") if w}) for k in keys if k not in catalogue),
        key=lambda item: -len(item[1]),
    )
    out: dict[str, str] = {}
    for object_id, category, name in objects:
        named, said = _name_words(name), words(name)
        head = singular(said[-1]) if said else ""
        own = next((key for key, need in open_keys if need and need <= named and head in need), None)
        if category in keys and (own is None or _name_words(category.replace("_", " ")) <= named):
            out[object_id] = category  # (a "gas lamp post" is the lamp post its name says, not a post)
            continue
        if own is not None:
            out[object_id] = own
            continue
        have = named | (_name_words(category) if category else set())
        for key, need in open_keys:
            if need and need <= have:
                out[object_id] = key
                break
    return out


def find_annotation(prompts: Iterable[Prompt], *, text: str, name: str) -> Prompt | None:
    """The annotation of a scene: the one with the same text (whitespace aside), else the one whose id is ``name``."""
    prompts = list(prompts)
    wanted = " ".join(text.split())
    for p in prompts:
        if " ".join(p.text.split()) == wanted:
            return p
    return next((p for p in prompts if p.id == name), None)
