"""``[program]`` and its ``[[program.segment]]`` tables: the cam program (kinematics).

Segment angles ``beta_deg`` (deg) and lifts ``lift_mm`` (mm) are converted to rad and m by
the checker; the closure (sum of beta = 360 deg, rises = falls) is reported even when another
key of the file has a problem, since it depends on the angles and lifts only.
"""

from __future__ import annotations

from ..errors import InputError
from ..kinematics import CamProgram, dwell, fall, law, rise
from .checker import _Checker, _fmt
from .schema import _PROGRAM, _SEGMENT


def _law_from(ck: _Checker, key: str, tab: dict, default):
    if "law" in tab and "control_points" in tab:
        ck.add(key, "give either law or control_points, not both")
        return None
    if "control_points" in tab:
        try:
            return law("bezier", control_points=tab["control_points"])
        except InputError as exc:
            ck.add(f"{key}.control_points", str(exc))
            return None
    if "law" in tab:
        try:
            return law(tab["law"])
        except InputError as exc:
            ck.add(f"{key}.law", str(exc))
            return None
    return default



def _program(ck: _Checker, raw: dict) -> CamProgram | None:
    """The cam program from [program] and its [[program.segment]] tables."""
    g = raw.get("program", {})
    prog_tab = ck.table(g, "program", _PROGRAM)
    default_law = _law_from(ck, "program", prog_tab, None)
    segments = []
    closure = []  # same betas and lifts, a placeholder law where the law is bad: closure check
    segs_raw = g.get("segment", []) if isinstance(g, dict) else []
    if "program" in raw and not (isinstance(segs_raw, list) and segs_raw):
        ck.add("program.segment", "must be an array of tables [[program.segment]] with at least one segment")
        segs_raw = []
    prog_law = isinstance(g, dict) and ("law" in g or "control_points" in g)
    fo = raw.get("follower")
    lift_key = "lift_deg" if isinstance(fo, dict) and fo.get("motion") == "oscillating" else "lift_mm"
    for i, sr in enumerate(segs_raw):
        _segment(ck, f"program.segment[{i}]", sr, default_law, prog_law, segments, closure, lift_key)
    program = None
    if closure and len(closure) == len(segs_raw):
        # closure (sum of beta = 360 deg, rises = falls) depends on betas and lifts only, so it is
        # reported even when other keys (a law, another table) have problems too
        try:
            program = CamProgram(closure)
        except InputError as exc:
            ck.add("program.segment", str(exc))
        else:
            program = CamProgram(segments) if len(segments) == len(segs_raw) else None
    return program


def _segment(ck: _Checker, key: str, sr, default_law, prog_law: bool, segments: list,
             closure: list, lift_key: str = "lift_mm") -> None:
    """One [[program.segment]]: appended to ``segments`` (if valid) and ``closure``. ``lift_key``:
    ``lift_mm`` (translating follower, m in SI) or ``lift_deg`` (oscillating arm, rad in SI)."""
    sg = ck.table(sr, key, _SEGMENT)
    kind = sg.get("kind")
    other = "lift_mm" if lift_key == "lift_deg" else "lift_deg"
    if isinstance(sr, dict) and other in sr:
        what = "an oscillating" if lift_key == "lift_deg" else "a translating"
        ck.add(f"{key}.{other}", f"= {_fmt(sr[other])}: {what} follower's segments take {lift_key}")
        return
    if kind is None or "beta_deg" not in sg:
        return
    if kind == "dwell":
        for k in ("lift_mm", "lift_deg", "law", "control_points"):
            if k in sg:
                ck.add(f"{key}.{k}", f"= {_fmt(sr[k])}: a dwell takes only kind and beta_deg")
        segments.append(dwell(sg["beta_deg"]))
        closure.append(segments[-1])
        return
    if lift_key not in sg:
        if isinstance(sr, dict) and lift_key not in sr:
            ck.add(f"{key}.{lift_key}", f"missing required key for a {kind} (unit: {lift_key[5:]})")
        return
    make = rise if kind == "rise" else fall
    lw = _law_from(ck, key, sg, default_law)
    closure.append(make(sg["beta_deg"], sg[lift_key], lw or "cycloidal"))
    if lw is None:
        if "law" not in sg and "control_points" not in sg and not prog_law:  # else reported
            ck.add(f"{key}.law", "missing: give law (e.g. 'cycloidal') or control_points, "
                   "here or in [program]")
        return
    segments.append(make(sg["beta_deg"], sg[lift_key], lw))

