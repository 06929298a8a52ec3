"""``run_study``: the phases of a design study.

prepare (base scene, keys, each value checked by the scene loader with the other varied keys at
their first values: refused up front) ->
variants (mapping, content hash, loaded scene; a combination the loader refuses is a
``refused`` row) -> evaluate the distinct variants not in the store (Hertz chain, in batches,
serially, in local processes or on Dask; records stored atomically as they arrive) -> table
(margins, feasibility, Pareto set) -> FE on the candidates -> outputs (CSV, NPZ, plots).
"""

from __future__ import annotations

import hashlib
import json
import math
import tempfile
from pathlib import Path

import numpy as np

from .. import _validate
from ..errors import InputError, SceneError
from ..io import provenance
from ..scene import Scene, load_scene
from ..scene.origin import thaw
from ..sweep.parallel import run_tasks
from . import variants as _v
from .constraints import NAMES, Constraints, feasibility, infeasible_reason, margins
from .evaluate import METRICS, EvalOptions, evaluate_batch
from .fe import FEOptions, candidates, fe_check
from .outputs import columns as _columns
from .outputs import write_outputs
from .result import StudyResult, pareto_mask
from .spec import MAX_VARIANTS, StudySpec, whole
from .store import RecordStore

#: up-front checks of one key: at most this many of its values are loaded alone
MAX_PROBES = 64
#: objectives a study can rank by (SI columns)
OBJECTIVES = ("p0_max", "von_mises_max", "tau1_max", "cam_radius_max")


def _base(scene):
    """``(raw mapping, scene path, scene text)`` of the base scene (a path is loaded and checked)."""
    if isinstance(scene, Scene):
        if not scene.origin:
            raise InputError("scene: a Scene built in code has no file mapping to vary; pass the scene file")
        path = scene.source_path
    else:
        path = str(scene)
        scene = load_scene(path)
    text = ""
    if path and Path(path).is_file():
        text = Path(path).read_text(encoding="utf-8")
    return thaw(scene.origin), path, text


def _probe(raw: dict, spec: StudySpec, path: str) -> None:
    """Each value of each key, with the other varied keys at their first values (so coupled
    keys such as ``program.law=bezier`` and its control points are probed together), through
    the loader: a value refused there is refused up front."""
    firsts = {v.key: v.first() for v in spec.vary}
    for var in spec.vary:
        _v.check_key(raw, var.key)
        probes = var.probes()
        if len(probes) > MAX_PROBES:  # the ends and an even sample of the rest
            pick = np.unique(np.linspace(0, len(probes) - 1, MAX_PROBES).astype(int))
            probes = tuple(probes[i] for i in pick)
        for val in probes:
            try:
                _v.build_scene(_v.apply(raw, {**firsts, var.key: val}), source_path=path,
                               label=f"{var.key}={val}")
            except SceneError as exc:
                raise InputError(f"vary {var.key}={val}: refused by the scene checker with the other varied "
                                 f"keys at their first values: {' '.join(str(exc).split())}") from None


def _batches(items: list, workers: int, batch_size: int | None) -> list:
    """Cut ``items`` into batches: about four per worker, 1..32 variants each."""
    if batch_size is None:
        batch_size = max(1, min(32, math.ceil(len(items) / (4 * max(1, workers)))))
    return [items[i:i + batch_size] for i in range(0, len(items), batch_size)]


def _where(scheduler, workers: int) -> dict:
    """run_tasks keywords for ``scheduler`` (None/"local": this process; "processes": a local
    pool of ``workers``; else a Dask address or a Client/LocalCluster object)."""
    if scheduler is None or scheduler == "local":
        return {"workers": 1}
    if scheduler == "processes":
        return {"workers": int(workers)}
    if isinstance(scheduler, str):
        return {"scheduler": scheduler}
    return {"client": scheduler}


def _value_column(vals: list):
    """A varied key's column: float when every value is a number, else text (lists as JSON)."""
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in vals):
        return np.asarray(vals, float), True
    text = [json.dumps(v) if isinstance(v, list) or v is None else str(v) for v in vals]
    return np.array(text, dtype=str), False


def run_study(scene, spec: StudySpec, *, constraints: Constraints | None = None,
              options: EvalOptions | None = None, fe: FEOptions | None = None,
              objective: str = "p0_max", out=None, resume: bool = True, overwrite: bool = False,
              scheduler=None, workers: int = 1, batch_size: int | None = None,
              plots: bool = False, command: str | None = None) -> StudyResult:
    """Run a design study: every variant of ``spec`` through the Hertz chain, FE on the candidates.

    Parameters
    ----------
    scene : str or Path or femcam.scene.Scene
        The base scene file (or a loaded scene with its file mapping, ``Scene.origin``).
    spec : StudySpec
        What varies (grid or Latin hypercube).
    constraints : Constraints, optional
        The limits (default: phi <= 30 deg, no undercut, no lift-off, safety factors >= 1 where
        assessed, jump speed above the operating speed where the train is elastic).
    options : EvalOptions, optional
        Angles per revolution and the jump-speed search range.
    fe : FEOptions, optional
        FE candidates (default: none).
    objective : str
        The SI column the candidates are ranked by: one of :data:`OBJECTIVES`.
    out : str or Path, optional
        Output directory (records in ``out/variants``; ``study.csv``, ``study.npz``, plots);
        None: memory only.
    resume : bool
        Reuse the records already in ``out`` (content-addressed: always the same variant).
    overwrite : bool
        Delete an earlier study's records in ``out`` first.
    scheduler : None, "local", "processes", str or dask Client/cluster
        Where the variants run: this process, ``workers`` local processes, or Dask.
    workers : int
        Local processes for ``scheduler="processes"``.
    batch_size : int, optional
        Variants per task (default: about four tasks per worker, at most 32 variants each).
    plots : bool
        Write the Pareto plot and, for two varied numeric keys, the constraint map (needs ``out``).
    command : str, optional
        Command line for the provenance.

    Returns
    -------
    StudyResult
        The table (one row per variant), counts, message and written paths.

    Raises
    ------
    InputError
        Unknown key (did-you-mean), empty values, a value the scene checker refuses on its own,
        an unknown objective, ``out`` holding another study without ``resume``/``overwrite``.
    """
    _validate.instance("spec", spec, StudySpec)
    constraints = Constraints() if constraints is None else _validate.instance("constraints", constraints,
                                                                               Constraints)
    options = EvalOptions() if options is None else _validate.instance("options", options, EvalOptions)
    fe = FEOptions() if fe is None else _validate.instance("fe", fe, FEOptions)
    whole("workers", workers, 1, 1024, "processes")
    if batch_size is not None:
        whole("batch_size", batch_size, 1, MAX_VARIANTS, "variants per task")
    if objective not in OBJECTIVES:
        raise InputError(f"objective = {objective!r}: must be one of {', '.join(OBJECTIVES)}")
    raw, path, text = _base(scene)
    _probe(raw, spec, path)
    store = RecordStore(out, resume=resume, overwrite=overwrite)
    opt = options.as_dict()

    combos = spec.variants()
    hashes, first, scenes, refused = [], {}, {}, {}
    with tempfile.TemporaryDirectory(prefix="femcam-study-") as tmp:  # the client's, not a worker's
        _variants(raw, combos, opt, store, path, tmp, hashes, first, scenes, refused)
    todo = [(h, s) for h, s in scenes.items()]
    n_reused = len(first) - len(todo) - len(refused)
    kw = _where(scheduler, workers)
    tasks = [(options, b) for b in _batches(todo, kw.get("workers", 2), batch_size)]
    for _, recs in run_tasks(evaluate_batch, tasks, **kw):
        for h, rec in recs:  # stored as they arrive: a killed study resumes from here
            store.put(h, rec)

    table = _table(spec, combos, hashes, first, store, refused, constraints, options)
    message = infeasible_reason({k: table[f"margin_{k}"] for k in NAMES}, table["status"] == "ok")
    fe_info = _fe(table, fe, objective, raw, combos, path, store, scheduler, workers)
    for k in ("model", "reason"):
        table[k] = table[k].astype(str)
    cols, text_cols = _columns(spec, combos, table)
    prov = provenance(scene_path=path or None,
                      scene_hash=hashlib.sha256(text.encode()).hexdigest() if text else None,
                      command=command,
                      options={"study": {"vary": [v.key for v in spec.vary], "lhs": spec.lhs,
                                         "seed": spec.seed, "n_variants": len(combos)},
                               "constraints": constraints.as_dict(), "evaluation": opt,
                               "fe": fe.as_dict(), "objective": objective})
    res = StudyResult(table=table, columns=cols, text_columns=text_cols, keys=spec.keys,
                      n_variants=len(combos), n_unique=len(first), n_computed=len(todo),
                      n_reused=n_reused, n_feasible=int(np.sum(table["feasible"])), message=message,
                      fe=fe_info, provenance=prov)
    if out is None:
        return res
    paths = write_outputs(res, out, scene_toml=text, plots=plots)
    return StudyResult(**{**res.__dict__, "paths": paths})


def _variants(raw, combos, opt, store, path, tmp, hashes, first, scenes, refused) -> None:
    """Hash every variant; load the distinct ones not in the store (a refusal is recorded)."""
    for i, vals in enumerate(combos):
        rv = _v.apply(raw, vals)
        h = _v.content_hash(rv, opt)
        hashes.append(h)
        if h in first:
            continue
        first[h] = i
        if store.get(h) is not None:
            continue
        try:
            scenes[h] = _v.build_scene(rv, source_path=path, label=f"variant {i}", tmpdir=tmp)
        except SceneError as exc:
            refused[h] = " ".join(str(exc).split())


def _table(spec, combos, hashes, first, store, refused, constraints, options) -> dict:
    """One row per variant: varied values, the record (or the refusal), margins, flags."""
    n = len(combos)
    recs = []
    for h in hashes:
        rec = store.get(h)
        if rec is None:
            rec = {m: math.nan for m in METRICS}
            rec.update(status="refused", reason=refused.get(h, "not evaluated"), model="")
        recs.append(rec)
    t = {m: np.array([float(r.get(m, math.nan)) for r in recs]) for m in METRICS}
    t["status"] = np.array([str(r.get("status", "")) for r in recs], dtype=str)
    for k in ("reason", "model"):  # object arrays: the FE stage appends to them
        t[k] = np.array([str(r.get(k, "")) for r in recs], dtype=object)
    t["hash"] = np.array(hashes, dtype=str)
    t["variant"] = np.arange(n, dtype=float)
    t["duplicate_of"] = np.array([first[h] if first[h] != i else -1 for i, h in enumerate(hashes)], float)
    mg = [margins(r, constraints, options.jump_factor_hi) for r in recs]
    for k in NAMES:
        t[f"margin_{k}"] = np.array([m[k] for m in mg], float)
    feas, binding = feasibility({k: t[f"margin_{k}"] for k in NAMES}, t["status"] == "ok")
    t["feasible"] = feas.astype(float)
    t["binding"] = binding
    t["pareto"] = pareto_mask(t["p0_max"], t["cam_radius_max"], feas).astype(float)
    t["p0_fe"] = np.full(n, np.nan)
    t["theta_fe"] = np.full(n, np.nan)
    for key in spec.keys:
        t[key] = _value_column([c[key] for c in combos])[0]
    return t


def _fe(table, fe: FEOptions, objective, raw, combos, path, store, scheduler, workers) -> dict:
    """FE sweeps of the candidates (records stored under ``hash-fe-<options hash>``)."""
    rows = candidates(table, fe, objective)
    info = {"top": fe.top, "select": fe.select, "angles_offsets_deg": fe.as_dict()["offsets_deg"],
            "rows": rows, "failed": 0}
    if not rows:
        return info
    tag = hashlib.sha256(json.dumps(fe.as_dict(), sort_keys=True).encode()).hexdigest()[:16]
    keys = {i: f"{table['hash'][i]}-fe-{tag}" for i in rows}
    need = [i for i in rows if store.get(keys[i]) is None]
    if need:
        # a candidate's scene is rebuilt from its hash's mapping: the same loader, the same checks
        scenes = {i: _v.build_scene(_v.apply(raw, combos[i]), source_path=path) for i in need}
        tasks = [(scenes[i], float(table["theta"][i]), fe) for i in need]
        for j, rec in run_tasks(fe_check, tasks, **_where(scheduler, workers)):
            store.put(keys[need[j]], rec)
    for i in rows:
        rec = store.get(keys[i])
        for r in np.flatnonzero(table["hash"] == table["hash"][i]):
            table["p0_fe"][r], table["theta_fe"][r] = rec["p0_fe"], rec["theta_fe"]
            table["model"][r] = "hertz+fe" if rec["status"] == "ok" else "hertz"
            if rec["status"] != "ok":
                table["reason"][r] = (table["reason"][r] + "; " if table["reason"][r] else "") + rec["reason"]
        info["failed"] += rec["status"] != "ok"
    return info
