"""Stated sizes ("2 meters wide", "a 3 m tall statue") and how they rescale a thing.
"""

from __future__ import annotations

from scenewright.analysis.parser.tokens import _Tok
from scenewright.analysis.parser.words import _DIMENSIONS, _NUMBERS, _UNITS


_NUM_WORD = {**{k: float(v) for k, v in _NUMBERS.items() if k not in ("single", "dozen")}, "half": 0.5}


def _read_sizes(toks: list[_Tok]) -> list[tuple[int, int, str, float]]:
    """(start, end, dimension, metres) for each "N unit dimension" phrase."""
    out = []
    for i, t in enumerate(toks):
        value = None
        if t.text.replace(".", "", 1).isdigit():
            value = float(t.text)
        elif t.text in _NUM_WORD:
            value = _NUM_WORD[t.text]
        if value is None or i + 2 >= len(toks) + 1:
            continue
        j = i + 1
        if j < len(toks) and toks[j].text in _UNITS:
            unit = _UNITS[toks[j].text]
            j += 1
            if j < len(toks) and toks[j].text in ("in", "of") and j + 1 < len(toks) and toks[j + 1].text in _DIMENSIONS:
                j += 1
            if j < len(toks) and toks[j].text in _DIMENSIONS:
                out.append((i, j + 1, _DIMENSIONS[toks[j].text], value * unit))
    return out


def _apply_sizes(base: tuple[float, float, float], dims: list[tuple[str, float]]) -> tuple[float, float, float]:
    x, y, z = base
    stated: dict[str, float] = {}
    named = {d for d, _ in dims}
    for dim, value in dims:
        if dim == "long":  # the longer side, unless the width or depth is named too
            dim = "y" if "x" in named else "x" if "y" in named else "y" if y > x else "x"
        if dim == "d":
            stated["x"] = stated["y"] = value
        else:
            stated[dim] = value
    first_dim = next(iter(stated))
    scale = stated[first_dim] / {"x": x, "y": y, "z": z}[first_dim]
    result = {"x": x * scale, "y": y * scale, "z": z * scale}
    result.update(stated)
    return (round(result["x"], 4), round(result["y"], 4), round(result["z"], 4))
