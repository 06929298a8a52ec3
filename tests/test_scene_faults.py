"""Fault injection generated from the scene schema: every key of every table
(:data:`femcam.scene.schema.TABLES`) given missing (if required), the wrong type, negative,
zero, NaN, inf, 1e30 and just outside its stated range (:data:`femcam.scene.ranges.RANGES`)
must give one :class:`~femcam.errors.SceneError` naming the dotted key (and, for a number, the
value and the unit), never another exception; the range ends and the example values are
accepted. A key added to the schema later is covered without anyone listing it here.

References: the expected outcome is the rule itself (issue 29: "each key needs a stated physical
range and a clear refusal outside it"); no numbers are computed. Only load/check: no analysis.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path

import pytest
import tomllib

import femcam.scene.load as scene_load
from femcam.errors import SceneError
from femcam.scene import load_scene
from femcam.scene.checker import _Checker, _fmt
from femcam.scene.ranges import RANGES, group_of
from femcam.scene.schema import _CHOICES, TABLES

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
#: base scenes, in the order searched for one that holds a key (the first is the default)
BASES = ("seed002_study_model", "seed002_assess", "seed002_coated", "seed002_crowned",
         "seed002_needle_roller", "seed002_cam_on_shaft", "seed002_dynamic", "seed003_knife_edge",
         "flat_faced", "seed000_rise")
RAW = {b: tomllib.loads((EXAMPLES / f"{b}.toml").read_text(encoding="utf-8")) for b in BASES}
# a two-DOF train (the second_* keys) and a scene with [fe], [sweep] and [wear] tables, built
# from the shipped examples
RAW["two_dof"] = copy.deepcopy(RAW["seed002_dynamic"])
RAW["two_dof"]["dynamics"].update(model="two_dof", second_mass_kg=0.1, second_stiffness_N_per_m=1e6,
                                  second_damping_ratio=0.05, steps_per_rev=3600)
RAW["study"] = copy.deepcopy(RAW["seed002_study_model"])
RAW["study"].update(fe={"a_over_h": 10.0, "tolerance": 2e-3}, wear={"k_mm3_per_N_m": 1e-6, "srr": 0.05},
                    sweep={"method": "fe", "angles_deg": "0:360:1", "chunk_size": 30, "vtk_every": 10,
                           "plots": False})
ORDER = ("study", "two_dof") + BASES


def _table(raw: dict, group: str):
    """``(table dict, dotted name)`` of ``group`` in ``raw``, or None when absent."""
    if group == "":
        return raw, ""
    if group == "program.segment":
        return raw["program"]["segment"][0], "program.segment[0]"  # a rise: all keys apply
    parts = group.split(".")
    if parts[0] == "materials":
        for body, tab in raw["materials"].items():
            t = tab if len(parts) == 2 else tab.get(parts[2])
            if isinstance(t, dict):
                return t, ".".join(["materials", body] + parts[2:])
        return None
    return (raw[group], group) if group in raw else None


def _base(group: str, key: str) -> tuple:
    """``(raw scene, table, dotted table)``: the first base holding ``key``, else the first
    holding the table (the key added there)."""
    found = [(b, _table(RAW[b], group)) for b in ORDER]
    found = [(b, t) for b, t in found if t is not None]
    b, (_, name) = next(((b, t) for b, t in found if key in t[0]), found[0])
    raw = copy.deepcopy(RAW[b])
    return raw, _table(raw, group)[0], name


def _cases():
    """``(group, key, fault, value)`` for every key of the schema."""
    out = []
    for group, spec in TABLES.items():
        for key, (_, factor, check, required) in spec.items():
            if required:
                out.append((group, key, "missing", None))
            if factor is None:  # text, list, segment array, boolean: numbers and lists are wrong
                wrong = {"str": [5.0, [1.0]], "list": ["x", 5.0, ["a"]], "seglist": [5.0, "x"],
                         "strlist": ["p0", 5.0, [1.0], [], ["nonsense"]],
                         "bool": ["yes", 1.0]}[check]
                out += [(group, key, "wrong type", w) for w in wrong]
                if key in _CHOICES:
                    out.append((group, key, "not a choice", "nonsense"))
                continue
            r = RANGES[group][key]
            lo_open = r.open_ or check == "pos" and r.lo == 0.0
            step = lambda b: max(abs(b) * 1e-3, 1e-12)  # noqa: E731 - just outside
            values = {"string": "10", "list": [1.0], "bool": True, "nan": math.nan, "inf": math.inf,
                      "-inf": -math.inf, "1e30": 1e30, "-1e30": -1e30, "above range": r.hi + step(r.hi),
                      "below range": r.lo if lo_open else r.lo - step(r.lo)}
            for name, v in (("negative", -1.0), ("zero", 0.0)):
                outside = v < r.lo or v == r.lo and lo_open or v > r.hi
                if outside:
                    values[name] = v
            out += [(group, key, name, v) for name, v in values.items()]
    return out


CASES = _cases()


@pytest.fixture
def load_raw(monkeypatch):
    """Load a parsed scene dict through :func:`load_scene` (no file: ``_read_toml`` patched)."""
    def load(raw):
        monkeypatch.setattr(scene_load, "_read_toml", lambda path: raw)
        return load_scene("fault.toml")
    return load


def test_every_numeric_key_has_a_stated_range_with_its_source():
    numeric = {(g, k) for g, spec in TABLES.items() for k, (_, f, _, _) in spec.items() if f is not None}
    ranged = {(g, k) for g, keys in RANGES.items() for k in keys}
    assert numeric == ranged, f"keys without a range: {numeric - ranged}; of no key: {ranged - numeric}"
    kinds = ("physical", "handbook", "standard", "femcam")
    for g, keys in RANGES.items():
        for k, r in keys.items():
            assert math.isfinite(r.lo) and r.lo < r.hi, (g, k, r)
            assert r.source.startswith(kinds), f"[{g}] {k}: the source must say its kind {kinds}"


def test_the_base_scenes_load(load_raw):
    for b in ORDER:
        load_raw(copy.deepcopy(RAW[b]))


KEYS = sorted({(g, k) for g, k, _, _ in CASES}, key=lambda gk: list(TABLES).index(gk[0]))


def _problem(load_raw, group, key, fault, value) -> str | None:
    """What is wrong with the refusal of one fault (None: one SceneError naming the key)."""
    raw, table, name = _base(group, key)
    unit, factor = TABLES[group][key][:2]
    if fault == "missing":
        table.pop(key, None)
    else:
        table[key] = value
    dotted = f"{name}.{key}" if name else key
    try:
        load_raw(raw)
    except SceneError as exc:
        lines = [ln for ln in str(exc).splitlines() if dotted in ln]
        if not lines:
            return f"{fault} {dotted} = {value!r}: the error does not name the key: {exc}"
        if factor is not None and fault != "missing" and not any(
                _fmt(value) in ln and (unit or "(dimensionless)") in ln for ln in lines):
            return f"{fault} {dotted}: value {_fmt(value)} and unit {unit!r} not both named: {exc}"
        return None
    except Exception as exc:  # noqa: BLE001 - any other exception type is the fault under test
        return f"{fault} {dotted} = {value!r}: {type(exc).__name__}: {exc}"
    return f"{fault} {dotted} = {value!r}: accepted"


# one test a key (all its faults inside): a key's failures are reported together, and the
# suite pays the per-test overhead once a key, not once a fault
@pytest.mark.parametrize("group, key", KEYS, ids=[f"{g or 'top'}.{k}" for g, k in KEYS])
def test_every_fault_of_a_key_is_one_scene_error_naming_it(load_raw, group, key):
    faults = [(f, v) for g, k, f, v in CASES if (g, k) == (group, key)]
    assert faults
    bad = [m for f, v in faults if (m := _problem(load_raw, group, key, f, v))]
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("group", [g for g in TABLES if g in RANGES])
def test_range_ends_and_middle_are_accepted_by_the_key_check(group):
    ck = _Checker("ranges")
    for key, r in RANGES[group].items():
        unit, factor, check, _ = TABLES[group][key]
        lo_open = r.open_ or check == "pos" and r.lo == 0.0
        mid = math.sqrt(r.lo * r.hi) if r.lo > 0 else 0.5 * (r.lo + r.hi)
        ends = [mid] + ([] if lo_open else [r.lo]) + ([] if r.open_ else [r.hi])
        for x in ends:
            if group in ("sweep",) or key in ("steps_per_rev",):
                x = float(round(x))
            assert ck.value(f"{group}.{key}", key, x, unit, factor, check, group=group) is not None, \
                f"[{group}] {key} = {x:g} {unit} is inside its range {r} but refused: {ck.problems}"


def test_group_of_is_the_schema_table():
    assert {group_of(t) for t in ("materials.roller.coating", "materials.pin", "program.segment[3]", "cam")} \
        <= set(TABLES)
