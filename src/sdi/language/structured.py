"""Commands written as data — JSON, YAML or key=value lines, as a developer writes them
(`{"shape": "tower", "height": 4}`, `- type: wall\\n  length: 5`, `towers: [3, 5, 2]`,
`tower.height=5`, `gap_cm=5`) — read into the words the rest of the front end reads, with a
note. The data is parsed by `json` and PyYAML's safe loader; text that looks like data but does
not parse is refused with the parser's message, never guessed at. Keys SDI does not know are
kept as words, so the reading reports them."""

from __future__ import annotations

import json
import re
from typing import Any

import yaml

from sdi.errors import SpecError
from sdi.spec import lexicon as lx

_FENCE = re.compile(r"^\s*```[\w-]*\s*\n?|\n?\s*```\s*$")
_COMMENT = re.compile(r"^\s*(?://|#).*$", re.MULTILINE)
_KEY_VALUE = re.compile(r"^\s*[A-Za-z_][\w.]*\s*=\s*\S.*$")
_KEY_VALUE_STRICT = re.compile(
    r"^\s*[A-Za-z_][\w.]*\s*=\s*(?:[^\s,]+|\([^)]*\)|\[[^\]]*\]|\{[^}]*\})\s*$"
)
_YAML_LINE = re.compile(r"^\s*(?:-\s+)?[A-Za-z_][\w.]*\s*:(?:\s|$)")

_SHAPE_KEYS = ("shape", "type", "kind", "structure", "family", "item", "object")
_KIND_WORDS = frozenset({"square", "flat", "solid", "hollow", "stepped", "2d", "3d", "open",
                         "closed"})  # fmt: skip
"""What a "kind:" says of the family named under another key ("item: pyramid / kind: square")."""
_COUNT_KEYS = ("count", "n", "number", "qty", "quantity", "copies")
_SIZE_WORDS = {
    "height": "high", "h": "high", "levels": "levels", "tiers": "levels", "layers": "layers",
    "steps": "steps", "length": "long", "len": "long", "l": "long", "width": "wide", "w": "wide",
    "depth": "deep", "d": "deep",
}  # fmt: skip
_RELATIONS = {
    "left_of": "to the left of", "right_of": "to the right of", "behind": "behind",
    "in_front_of": "in front of", "front_of": "in front of", "on_top_of": "on top of",
    "on": "on top of", "on_top": "on top of", "next_to": "next to", "beside": "next to",
}  # fmt: skip


def looks_like_data(text: str) -> bool:
    """The command is written as data rather than words: JSON (braces or brackets round it
    all), key=value lines whose values are single tokens, or YAML (several keyed lines, or
    one key with a list or mapping)."""
    body = _COMMENT.sub("", _FENCE.sub("", text)).strip()
    if not body:
        return False
    if body[0] + body[-1] in ("{}", "[]"):
        return ":" in body or body[0] == "["
    lines = [ln for ln in body.splitlines() if ln.strip() and ln.strip() != "---"]
    if all(_KEY_VALUE_STRICT.match(ln) for ln in lines):
        return True
    keyed = [ln for ln in lines if _YAML_LINE.match(ln)]
    flow = bool(re.match(r"^\s*[A-Za-z_][\w.]*\s*:\s*[\[{]", body))  # "size: [2, 3, 4]"
    return len(keyed) == len(lines) and (len(lines) > 1 or flow)


def as_words(text: str, notes: list[str]) -> str:
    """`text` as words when it is data; unchanged otherwise."""
    if not looks_like_data(text):
        return text
    body = _COMMENT.sub("", _FENCE.sub("", text)).strip()
    data = _parse(body)
    empty = _empty_key(data)
    if empty is not None:
        raise SpecError(
            f"the key '{empty}' in the command's data has no value; give one (e.g. "
            f'"{empty}": 4) or leave the key out',
            understood={},
        )
    said = _describe(data)
    if not said.strip():
        raise SpecError(
            "the command is data with nothing SDI can build in it; give a 'shape' (e.g. "
            '{"shape": "tower", "height": 4})',
            understood={},
        )
    notes.append(f"read the data as '{said.strip()}'")
    return said


def _parse(body: str) -> Any:
    if body[0] in "{[":
        try:
            return json.loads(body)
        except json.JSONDecodeError as exc:
            try:  # a trailing comma, unquoted keys: YAML's flow style reads them
                return yaml.safe_load(body)
            except yaml.YAMLError:
                raise SpecError(
                    f"the command looks like JSON but does not parse: {exc.msg} at line "
                    f"{exc.lineno} column {exc.colno}; fix it or say it in words",
                    understood={},
                ) from None
    if all(_KEY_VALUE.match(ln) for ln in body.splitlines() if ln.strip()):
        out: dict[str, Any] = {}
        for ln in body.splitlines():
            if not ln.strip():
                continue
            key, value = (p.strip() for p in ln.split("=", 1))
            _set(out, key.split("."), _value(value))
        return out
    try:
        docs = [d for d in yaml.safe_load_all(body) if d is not None]
    except yaml.YAMLError as exc:
        raise SpecError(
            f"the command looks like YAML but does not parse ({str(exc).splitlines()[0]}); fix "
            "it or say it in words",
            understood={},
        ) from None
    return docs[-1] if docs else {}  # a later document revises the one before


def _empty_key(data: Any) -> str | None:
    """The first key whose value is missing (`{"height": }` read leniently as null)."""
    if isinstance(data, dict):
        for key, value in data.items():
            found = str(key) if value is None else _empty_key(value)
            if found is not None:
                return found
    if isinstance(data, list):
        return next((f for item in data if (f := _empty_key(item)) is not None), None)
    return None


def _value(said: str) -> Any:
    try:
        return yaml.safe_load(said)
    except yaml.YAMLError:
        return said


def _set(out: dict[str, Any], path: list[str], value: Any) -> None:
    for key in path[:-1]:
        nxt = out.setdefault(key, {})
        if not isinstance(nxt, dict):
            nxt = out[key] = {}
        out = nxt
    out[path[-1]] = value


def family_word(name: Any) -> str | None:
    """The family word a key or value names, singular ("towers" → "tower")."""
    word = str(name).lower().strip()
    single = word[:-1] if word.endswith("s") else word
    if single in lx.SHAPE_WORDS:
        return single
    return word if word in lx.SHAPE_WORDS else None


_OPS = ("build", "add", "remove", "make", "place", "put")


def _describe(data: Any) -> str:
    if isinstance(data, list):
        parts = [_describe(item) for item in data]
        return " . then ".join(p for p in parts if p.strip())
    if not isinstance(data, dict):
        return str(data)
    if len(data) == 1 and str(next(iter(data))).lower() in _OPS:
        op, value = next(iter(data.items()))  # "- add: {cubes: 2, to: tower}"
        return _structure({**value, "op": op} if isinstance(value, dict) else {"op": op}, None)
    if isinstance(data.get("base"), dict) and isinstance(data.get("on_top"), dict):
        return f"{_describe(data['base'])} . then {_describe(data['on_top'])} , on top of it"
    for key in ("items", "structures", "objects", "steps", "parts"):
        if isinstance(data.get(key), list):
            rest = {k: v for k, v in data.items() if k != key}
            return " . then ".join(p for p in (_describe(data[key]), _loose(rest)) if p.strip())
    said = [data[k] for k in _SHAPE_KEYS if k in data]
    kinds = [v for v in said if isinstance(v, str) and v.lower() in _KIND_WORDS]
    shape = next((v for v in said if v not in kinds), said[0] if said else None)
    if kinds and shape is not None and shape not in kinds:
        # "item: pyramid / kind: square": a square pyramid (the kind was read as the family)
        shape = f"{kinds[0]} {shape}"
    if shape is not None or "op" in data:
        return _structure(data, shape)
    named = [k for k in data if family_word(k) and not isinstance(data[k], int | float | str)]
    lists = [k for k in data if family_word(k) and isinstance(data[k], list)]
    if named or lists:
        said = []
        for key in data:
            family = family_word(key)
            value = data[key]
            if family and isinstance(value, list) and all(isinstance(v, int) for v in value):
                heights = ", ".join(str(v) for v in value[:-1]) + f" and {value[-1]}"
                said.append(f"{len(value)} {family}s of {heights}" if len(value) > 1
                            else f"a {family} of {value[0]}")  # fmt: skip
            elif family and isinstance(value, dict):
                said.append(_structure(value, family))
        rest = {k: v for k, v in data.items() if not family_word(k)}
        return " . ".join([*said, _loose(rest)])
    size = next((data[k] for k in data if str(k).lower().startswith(("size", "dims"))), None)
    if size is not None:  # "size: [2, 3, 4]": a block (two sides: a slab)
        flat = isinstance(size, list) and len(size) == 2
        return f"{'a slab' if flat else 'a block'} {_loose(data)}"
    return _loose(data)


def _structure(data: dict[str, Any], shape: Any) -> str:
    op = str(data.get("op", "build")).lower()
    if str(shape).strip() in ("*", "any", "anything", "?"):
        count = next((data[k] for k in _COUNT_KEYS if k in data), 1)  # "shape=*": SDI's choice
        many = f"{count} towers" if isinstance(count, int) and count > 1 else "something"
        return f"{many}, your call"
    if op in ("remove", "delete", "take_off", "take_away"):
        target = str(data.get("target", data.get("what", "it"))).replace("_", " ")
        return f"remove the {target}"
    if op == "add" or ("cubes" in data and shape is None):
        n = data.get("cubes", data.get("count", 1))
        return f"add {n} more cubes to it"
    if shape is None and op in _OPS:
        shape = data.get("shape", "structure")
    family = family_word(shape) or str(shape)
    count = next((data[k] for k in _COUNT_KEYS if k in data), None)
    head = f"{count} {family}s" if isinstance(count, int) and count > 1 else f"a {family}"
    used = {*_SHAPE_KEYS, *_COUNT_KEYS, "op", "to"}
    return f"{head} {_loose({k: v for k, v in data.items() if k not in used})}"


def _loose(data: dict[str, Any]) -> str:
    """Sizes, places and spacing said as key and value."""
    words: list[str] = []
    for key, value in data.items():
        k = str(key).lower()
        base, _, unit = k.rpartition("_")
        if base in _SIZE_WORDS and unit in ("cubes", "parts", "cm", "mm", "m"):
            k, value = base, value if unit in ("cubes", "parts") else f"{value} {unit}"
        if k in _SIZE_WORDS and isinstance(value, int | float | str):
            words.append(f", {value:g} {_SIZE_WORDS[k]}" if isinstance(value, int | float)
                         else f", {value} {_SIZE_WORDS[k]}")  # fmt: skip
        elif k in ("size", "dims", "dimensions") and isinstance(value, list):
            names = ("deep", "wide", "high")  # x (front to back), y (across), z
            words.append(", " + ", ".join(f"{v} {n}" for v, n in zip(value, names, strict=False)))
        elif k.startswith("dims") and isinstance(value, dict):
            unit = k.rsplit("_", 1)[1] if "_" in k else ""
            for sub, v in value.items():
                if sub.lower() in _SIZE_WORDS:
                    words.append(f", {v} {unit} {_SIZE_WORDS[sub.lower()]}")
        elif k in ("gap", "spacing", "apart") or k.startswith(("gap_", "spacing_")):
            unit = k.split("_", 1)[1] if "_" in k else "cubes"
            words.append(f", {value} {unit} apart")
        elif k in ("touching", "touch") and value is False:
            words.append(", not touching")
        elif k in ("use_beams", "beams") and value is False:
            words.append(", without beams")
        elif k in ("position", "at", "place", "where", "region"):
            words.append(_place(value))
        elif k.startswith("pos"):
            unit = k.split("_", 1)[1] if "_" in k else "m"
            xy = (
                list(value)
                if isinstance(value, list | tuple)
                else re.findall(r"[\d.]+", str(value))
            )
            if len(xy) == 2:
                words.append(f", at x = {xy[0]} {unit}, y = {xy[1]} {unit}")
        elif k in _RELATIONS and not isinstance(value, dict):
            words.append(f", {_RELATIONS[k]} it")
        elif k.startswith("n_") and family_word(k[2:]) and isinstance(value, int):
            words.append(f"{value} {family_word(k[2:])}s")
        elif k in ("on_top", "base") and isinstance(value, dict):
            words.append(_describe(value))
        else:
            words.append(f", {k.replace('_', ' ')} {value}")
    return " ".join(words)


def _place(value: Any) -> str:
    said = str(value).lower().replace("_", " ").replace("-", " ")
    relation = re.match(r"(left|right)\s+of\s*\(?\s*\w*\s*\)?|(behind|in front of)", said)
    if relation:
        side = relation.group(1)
        return f", to the {side} of it" if side else f", {relation.group(2)} it"
    if said in ("center", "centre", "middle"):
        return ", in the centre"
    return f", at the {said}"
