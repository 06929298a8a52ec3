"""``optimise``: minimise a worst-angle objective of a cam over continuous design variables.

Method (docs/optimise.md): SLSQP on the epigraph form over a grid of normalised angles
(:mod:`femcam.optimise.problem`), from several starts; then *exchange* refinement of the
semi-infinite problem: the worst angle of the objective and of each constraint on a fine grid
(``DENSE`` samples per rise/fall, refined by a parabola through its neighbours) is added to the
grid and SLSQP restarts from the optimum, until the fine-grid maximum is within ``GAP_TOL`` of
the grid's. The optimum is then checked with the FE (:func:`femcam.sweep.sweep` around the
worst angle) when asked.
"""

from __future__ import annotations

import math
import os

import numpy as np

from .. import _validate
from ..errors import FemcamError, InputError, SceneError
from ..scene import load_scene
from ..sweep import RunOptions, SweepOptions, sweep
from .chain import (
    CONSTRAINT_UNITS,
    OBJECTIVE_UNITS,
    OBJECTIVES,
    SCALAR_OBJECTIVES,
    check_objective,
    constraint_value,
)
from .design import BezierRise, Design, Variable
from .problem import FEAS_TOL, Problem
from .result import FECheck, OptimiseResult, StartRecord

__all__ = ["optimise", "DENSE", "GAP_TOL"]

#: samples per rise/fall of the fine check grid (0.05 deg for a 100 deg rise)
DENSE = 2001
#: relative gap between the fine-grid and the grid maximum that ends the exchange refinement
GAP_TOL = 1e-6
_EXCHANGE_ROUNDS = 4


def _variables(variables) -> tuple:
    if isinstance(variables, dict):
        out = []
        for name, b in variables.items():
            try:
                lo, hi = b
            except (TypeError, ValueError):
                raise InputError(f"variables[{name!r}] = {b!r}: must be (lower, upper) in SI") from None
            out.append(Variable(name=name, lower=lo, upper=hi))
        return tuple(out)
    out = tuple(variables)
    for v in out:
        if not isinstance(v, Variable):
            raise InputError(f"variables: {v!r} is not a femcam.optimise.Variable")
    return out


def _limits(constraints) -> dict:
    out = {}
    for name, lim in dict(constraints).items():
        if name not in CONSTRAINT_UNITS:
            raise InputError(f"constraint {name!r}: unknown; use {sorted(CONSTRAINT_UNITS)}")
        unit = CONSTRAINT_UNITS[name]
        if name == "phi_max":
            out[name] = _validate.in_range(name, lim, 0.0, math.pi / 2, unit, lo_open=True, hi_open=True)
        elif name in ("rho_min", "safety_min", "lambda_min"):
            out[name] = _validate.nonnegative(name, lim, unit)
        else:
            out[name] = _validate.positive(name, lim, unit)
    return out


def _starts(prob: Problem, design: Design, starts) -> np.ndarray:
    z0 = prob.z_of(design.start())
    if isinstance(starts, (int, np.integer)) and not isinstance(starts, bool):
        k = _validate.integer("starts", starts, 1)
        rng = np.random.default_rng(0)  # Latin hypercube in z, reproducible
        n = z0.size
        cells = np.array([rng.permutation(k - 1) for _ in range(n)]).T
        lhs = (cells + rng.random((k - 1, n))) / max(k - 1, 1)
        return np.vstack([z0, lhs]) if k > 1 else z0[None, :]
    xs = _validate.finite_array("starts", starts, "SI")
    if xs.ndim != 2 or xs.shape[1] != z0.size:
        raise InputError(f"starts: shape {xs.shape}: must be (k, {z0.size}) design vectors (SI)")
    lo, hi = design.bounds()
    if np.any(xs < lo) or np.any(xs > hi):
        raise InputError("starts: a start lies outside the variable bounds")
    return prob.z_of(xs)


def _worst_u(prob: Problem, z) -> tuple[list, float, dict]:
    """Exchange points (segment, u) of the fine grid, the relative gap, and the fine-grid values."""
    fine = prob.raw(z, dense=DENSE)
    grid = prob.raw(z)
    q_f, q_g = fine["objective"], grid["objective"]
    gap = float((np.max(q_f) - np.max(q_g)) / max(abs(np.max(q_g)), 1e-300))
    # a scalar objective (residual vibration) has no angle to exchange: only the constraints
    objective_rows = [] if prob.objective in SCALAR_OBJECTIVES else list(np.atleast_2d(fine["objective"]))
    arrays = objective_rows + [row for c in prob.limits for row in -np.atleast_2d(fine[c])]
    for c in prob.limits:
        gap = max(gap, float(np.min(grid[c]) - np.min(fine[c])))
    seg, u = fine["seg_u"][:, 0].astype(int), fine["seg_u"][:, 1]
    pts = []
    du = 1.0 / (DENSE - 1)
    for j, f in enumerate(arrays):
        top = float(np.max(f))
        near = top - 1e-3 * (abs(top) if j < len(objective_rows) else 1.0)  # margins: scale 1
        for k in np.unique(seg):
            idx = np.flatnonzero(seg == k)
            if idx.size < 3:
                continue
            g = f[idx]
            peak = (g >= np.r_[-np.inf, g[:-1]]) & (g >= np.r_[g[1:], -np.inf]) & (g >= near)
            for i in np.flatnonzero(peak):
                i = min(max(int(i), 1), idx.size - 2)
                y0, y1, y2 = g[i - 1], g[i], g[i + 1]
                den = y0 - 2.0 * y1 + y2
                shift = float(np.clip(0.5 * (y0 - y2) / den, -1.0, 1.0)) if den < 0 else 0.0
                pts.append((int(k), float(np.clip(u[idx[i]] + shift * du, 0.0, 1.0))))
    return pts, gap, fine


def optimise(scene_or_path, *, objective: str = "p0", variables, constraints=None, starts=1,
             bezier: BezierRise | None = None, n_motion: int = 181, verify_fe: bool = True,
             maxiter: int = 200) -> OptimiseResult:
    """Minimise the worst-angle ``objective`` of a cam over continuous design variables.

    Parameters
    ----------
    scene_or_path : femcam.scene.Scene or str or Path
        The scene (roller or knife-edge follower) or its TOML file.
    objective : str
        ``"p0"`` (peak Hertz pressure, Pa), ``"von_mises"``/``"tau1"`` (Pa; Hertz shape factors
        with the scene's friction), ``"acceleration"`` (peak ``|a|``, m/s^2), ``"size"``
        (largest cam radius, m), ``"utilisation"`` (largest 1/safety factor of the assessment:
        maximises the smallest safety factor), ``"lambda"`` (largest 1/lambda of the assessment's
        film ratio: maximises the smallest lambda; needs [lubricant]), ``"residual_vibration"``
        (m: largest ``|x - s - e_static|`` of the follower in the dwell after each rise, periodic
        steady state of the scene's elastic train at its speed) or ``"wear"`` (largest Archard
        cam wear depth per revolution at the contact, m; slide-to-roll roller model).
    variables : dict or sequence of Variable
        ``{name: (lower, upper)}`` in SI, or :class:`Variable` objects: ``base_radius`` (m),
        ``roller_radius`` (m), ``rise_angle`` (rad), ``control_point_<i>`` (free Bezier
        ordinates of ``bezier``).
    constraints : dict, optional
        ``{"phi_max": rad, "rho_min": m, "liftoff_omega": rad/s, "safety_min": -,
        "lambda_min": -}``; ``rho_min = 0`` is "no undercut"; the last two need the scene's
        assessment data (femcam.assess, every safety factor of
        :data:`femcam.optimise.chain.SF_COLUMNS`). Default: none.
    starts : int or array_like, shape (k, n_variables)
        Number of starts (the scene's design, then a seeded Latin hypercube) or the starts (SI).
    bezier : BezierRise, optional
        Family of the Bezier rise when control points vary (default degree 9, v = a = 0 at the
        ends). Every rise/fall segment uses it.
    n_motion : int
        Grid samples per rise/fall (exchange points are added).
    verify_fe : bool
        Run the FE sweep at the worst angle and +-2 deg (Hertz objectives only).
    maxiter : int
        SLSQP iterations per run.

    Returns
    -------
    OptimiseResult

    Raises
    ------
    InputError
        Unknown objective, variable or constraint; empty/inverted bounds; a constraint set with
        no feasible point in the bounds (names the constraint that is infeasible on its own, or
        says that only their combination is).
    """
    scene = _scene(scene_or_path)
    maxiter = _validate.integer("maxiter", maxiter, 1)
    if objective not in OBJECTIVES:
        raise InputError(f"objective = {objective!r}: unknown; use one of {list(OBJECTIVES)}")
    check_objective(scene, objective)
    limits = _limits(constraints or {})
    design = Design(scene=scene, variables=_variables(variables), bezier=bezier or BezierRise())
    prob = Problem(design, objective, limits, _validate.integer("n_motion", n_motion, 3))
    zs = _starts(prob, design, starts)
    q_start = prob.raw(zs[0], dense=DENSE)
    start_value = float(np.max(q_start["objective"]))
    prob.ref = max(abs(float(np.max(prob.vector(zs[0])[0]))), 1e-300)
    prob._cache.clear()
    records, runs = [], []
    for z0 in zs:
        res = prob.run(z0, maxiter=maxiter)
        q, m = prob.vector(res.z)
        feas = bool(m.size == 0 or np.min(m) >= -FEAS_TOL)
        records.append(StartRecord(x0=tuple(prob.x_of(z0)), x=tuple(prob.x_of(res.z)),
                                   value=float(np.max(q)) * prob.ref,
                                   feasible=feas, converged=bool(res.success), iterations=int(res.nit),
                                   message=str(res.message)))
        runs.append(res)
    ok = [i for i, r in enumerate(records) if r.feasible]
    if not ok:
        _diagnose(prob, runs, records)
    best = min(ok, key=lambda i: records[i].value)
    res, iters, rounds = runs[best], int(runs[best].nit), 0
    gap, fine = math.inf, None
    for rounds in range(_EXCHANGE_ROUNDS + 1):
        pts, gap, fine = _worst_u(prob, res.z)
        if gap <= GAP_TOL or rounds == _EXCHANGE_ROUNDS:
            break
        prob.extra_u.extend(pts)
        prob._cache.clear()
        res = prob.run(res.z, maxiter=maxiter)
        iters += int(res.nit)
    good = [records[i].value for i in ok if records[i].converged]
    spread = float(max(abs(v / records[best].value - 1.0) for v in good)) if good else math.nan
    return _result(prob, design, res, fine, start_value, records, iters, rounds, gap, spread, verify_fe)


def _result(prob, design, res, fine, start_value, records, iters, rounds, gap, spread, verify_fe):
    x = prob.x_of(res.z)
    q = fine["objective"]
    cons = {c: {"limit": lim, "value": constraint_value(c, fine, lim), "margin": float(np.min(fine[c]))}
            for c, lim in prob.limits.items()}
    feas = all(v["margin"] >= -FEAS_TOL for v in cons.values())
    converged = bool(res.success) and feas and gap <= GAP_TOL
    msg = (f"SLSQP: {res.message}; {len(records)} start(s), exchange rounds {rounds}, grid gap {gap:.2e}"
           + ("" if feas else "; a constraint is violated on the fine grid"))
    P = design.control_points(x)
    theta_worst = float(fine["theta_worst"] if "theta_worst" in fine
                        else fine["theta"][int(np.argmax(fine["objective"])) % fine["theta"].size])
    scene = fine["scene"]
    hertz = prob.objective in ("p0", "von_mises", "tau1")
    fe = _verify_fe(scene, theta_worst) if verify_fe and hertz else None
    return OptimiseResult(objective=prob.objective, unit=OBJECTIVE_UNITS[prob.objective],
                          value=float(np.max(q)),
                          start_value=start_value, names=design.names, x=tuple(float(v) for v in x),
                          control_points=None if P is None else tuple(float(p) for p in P),
                          program=scene.program, follower=scene.follower, constraints=cons,
                          theta_worst=theta_worst, optimiser="SLSQP", iterations=iters, nfev=prob.nfev,
                          converged=converged, message=msg, starts=tuple(records), spread=spread,
                          exchange_rounds=rounds, grid_gap=gap, fe=fe)


def _scene(scene_or_path):
    """The scene of ``optimise``'s first argument (a Scene or a TOML path)."""
    if hasattr(scene_or_path, "program") and hasattr(scene_or_path, "follower"):
        return scene_or_path
    if not isinstance(scene_or_path, (str, os.PathLike)):
        raise _validate.fail("scene_or_path", scene_or_path, "",
                             "must be a femcam.scene.Scene or a scene file path")
    try:
        return load_scene(scene_or_path)
    except SceneError as exc:
        raise InputError(f"scene_or_path = {scene_or_path!r}: {exc}") from None


def _fmt_limit(name: str, value: float) -> str:
    unit = CONSTRAINT_UNITS[name]
    extra = {"phi_max": f" ({math.degrees(value):.4g} deg)",
             "liftoff_omega": f" ({value * 30.0 / math.pi:.5g} rpm)",
             "rho_min": f" ({value * 1e3:.4g} mm)"}.get(name, "")
    return f"{name} = {value:.6g} {unit}{extra}"


def _diagnose(prob: Problem, runs, records) -> None:
    """No start is feasible: maximise each constraint's smallest margin alone and raise."""
    names = list(prob.limits)
    z0 = runs[int(np.argmax([np.min(prob.vector(r.z)[1]) for r in runs]))].z
    alone = {}
    for c in names:
        r = prob.run(z0, only=c)
        alone[c] = (float(r.t), prob.x_of(r.z))
    bad = [c for c in names if alone[c][0] < -FEAS_TOL]
    if bad:
        c = bad[0]
        fine = prob.raw(prob.z_of(alone[c][1]), dense=DENSE)
        where = ", ".join(f"{n} = {v:.6g}" for n, v in zip(prob.design.names, alone[c][1], strict=True))
        raise InputError(f"{_fmt_limit(c, prob.limits[c])}: infeasible on its own within the variable "
                         "bounds: "
                         f"its best reachable worst value is {constraint_value(c, fine, prob.limits[c]):.6g} "
                         f"{CONSTRAINT_UNITS[c] if c != 'liftoff_omega' else '(Fc/Fpl)'} at {where} (SI)")
    raise InputError(f"constraints {', '.join(_fmt_limit(c, prob.limits[c]) for c in names)}: each is "
                     "feasible alone within the bounds but not all together (no start found a feasible "
                     "point; "
                     f"best margins {', '.join(f'{c} {np.min(prob.raw(runs[0].z)[c]):.3g}' for c in names)})")


def _verify_fe(scene, theta_worst: float) -> FECheck:
    """FE sweep at the worst angle and +-2 deg; never raises for a femcam physics failure."""
    theta = theta_worst + np.radians([-2.0, 0.0, 2.0])
    try:
        r = sweep(scene,
                  SweepOptions(angles=theta, method="fe", plots=False),
                  RunOptions(workers=1, progress=False))
    except FemcamError as exc:
        reason = " ".join(str(exc).split())       # the mesher's/solver's own text, on one line
        return FECheck(theta=tuple(theta), p0_hertz=(), p0_fe=(), rel_diff=math.nan, status=(),
                       message=f"the FE check of the optimum failed: the FE model of the optimal design "
                       f"could not be built or solved ({type(exc).__name__}: {reason})")
    ph = np.asarray(r.table["p0_hertz"], float)
    pf = np.asarray(r.table["p0_fe"], float)
    rel = float(np.nanmax(np.abs(pf / ph - 1.0))) if np.any(np.isfinite(pf)) else math.nan
    status = tuple(str(s) for s in r.table["status"])
    bad = [i for i, s in enumerate(status) if s != "ok" or not np.isfinite(pf[i])]
    if bad:   # asked for and not delivered: one line with the first row's reason, wrapped
        why = " ".join(str(np.asarray(r.table.get("message", [""] * len(status)))[bad[0]]).split())
        msg = (f"the FE check of the optimum failed at {len(bad)} of {len(status)} angles (statuses "
               f"{', '.join(status)}; at {math.degrees(theta[bad[0]]):.1f} deg: {why or 'no FE p0'})")
    else:
        msg = (f"FE peak p0 within {100 * rel:.3g} % of Hertz at the worst angle and +-2 deg (statuses "
               f"{', '.join(status)})")
    return FECheck(theta=tuple(float(t) for t in theta), p0_hertz=tuple(ph), p0_fe=tuple(pf), rel_diff=rel,
                   status=status, message=msg)
