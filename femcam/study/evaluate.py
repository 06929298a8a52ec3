"""The Hertz evaluation of one variant (the analytic chain over a full revolution): what a
worker computes. Pure: a scene in, a record of SI numbers out; nothing is written.

Per variant, on ``n_angles`` cam angles over one revolution (default 720, 0.5 deg apart; the
undercut check is the scene's own dense check on 7200 angles):

* ``p0_max`` (Pa) and its angle ``theta`` (rad), ``Fc``/``a``/``R`` there; ``von_mises_max``
  and ``tau1_max`` (Pa) from the Hertz shape factors (:func:`femcam.hertz.conformity.shape_factors`:
  the maxima scale with p0, Johnson 1985 section 7.1);
* ``phi_max`` (rad, max ``|phi|``), ``rho_min`` (m, the smallest convex cam radius of
  curvature), ``undercut`` (1/0; also 1 where a concave cam radius is smaller than the
  roller's, ``1/R1 + 1/R2 <= 0``: the roller does not fit, and those angles get no Hertz
  values), ``Fc_min`` (N, < 0: lift-off), ``cam_radius_max`` (m, the
  largest distance of the cam surface from its axis: the cam's size, ``Rb + h`` for an in-line
  roller);
* ``sf_min`` (the assessment's smallest safety factor, :func:`femcam.assess.assess`) and
  ``lambda_min`` where the scene has the data (NaN otherwise);
* ``rpm_jump`` (rpm, NaN: none up to ``jump_factor_hi`` x the operating speed) where the scene
  has an elastic follower train (:func:`femcam.dynamics.jump_speed`);
* ``wear_depth_per_rev`` (m, the largest Archard cam wear depth after one revolution, Hertz
  pressure; :func:`femcam.wear.scene.scene_wear`) when ``EvalOptions(wear=True)``.

Only documented femcam errors become a ``failed`` record with the reason; programming errors
propagate.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..assess import assess
from ..dynamics import jump_speed
from ..errors import FemcamError, InputError
from ..hertz import HertzValidityWarning, LineContact
from ..hertz.conformity import shape_factors
from ..layers.from_scene import scene_coatings
from ..scene.case import contact_case
from ..wear.coating import coating_wear
from ..wear.scene import scene_wear
from .spec import whole

#: angles per revolution: 36 resolves a program's segments; above 1e5 a variant's arrays and
#: time grow without changing its worst values
MIN_ANGLES, MAX_ANGLES = 36, 100_000

#: the metrics of a record (SI), in table order
METRICS = ("theta", "p0_max", "Fc_at_p0", "a_at_p0", "R_at_p0", "von_mises_max", "tau1_max",
           "phi_max", "rho_min", "undercut", "Fc_min", "Fc_max", "cam_radius_max", "sf_min",
           "lambda_min", "rpm", "has_train", "rpm_jump", "wear_depth_per_rev")


@dataclass(frozen=True, kw_only=True)
class EvalOptions:
    """How a variant is evaluated (part of its content hash).

    Parameters
    ----------
    n_angles : int
        Cam angles over one revolution (>= 36).
    jump_factor_hi : float
        The jump-speed search runs up to this multiple of the operating speed (> 1).
    wear : bool
        Also compute the Archard wear map (:func:`femcam.wear.scene.scene_wear`, Hertz
        pressure): many times the cost of the rest of a variant (docs/performance.md), so off
        by default.
    """

    n_angles: int = 720
    jump_factor_hi: float = 2.0
    wear: bool = False

    def __post_init__(self):
        whole("n_angles", self.n_angles, MIN_ANGLES, MAX_ANGLES, "angles per revolution")
        if _validate.number("jump_factor_hi", self.jump_factor_hi, "x operating speed") <= 1.0:
            raise InputError(
                f"jump_factor_hi = {self.jump_factor_hi!r} (x operating speed): must be > 1")

    def as_dict(self) -> dict:
        """The options as JSON-able values (the content hash's part).

        Returns
        -------
        dict
            ``{"n_angles": ..., "jump_factor_hi": ..., "wear": ...}``.
        """
        return {"n_angles": int(self.n_angles), "jump_factor_hi": float(self.jump_factor_hi),
                "wear": bool(self.wear)}


def _contact_radius(scene) -> float:
    """R2 of the follower (m): the roller, a knife edge's tip, inf for a flat face."""
    if getattr(scene.follower, "flat_face", False):
        return math.inf
    r = float(getattr(scene.follower, "Rr", 0.0) or 0.0)
    if r <= 0.0:
        r = float(scene.tip_radius or 0.0)
    if r <= 0.0:
        raise FemcamError("a sharp knife edge has no Hertz contact width; give [follower] tip_radius_mm")
    return r


def _assessment(scene, theta) -> tuple:
    """(smallest safety factor, smallest lambda) of the assessment, NaN where not available."""
    if scene.tribology.empty:  # no assessment data: nothing to assess (a third of the time saved)
        return math.nan, math.nan
    lub = scene.tribology.lubricant is not None
    try:
        A = assess(contact_case(scene, theta), lubricated=lub, coatings=scene_coatings(scene.layers))
    except FemcamError:
        return math.nan, math.nan
    not_sf = ("film (lambda)", "contact temperature", "pitting life")
    sf = [v[0] for k, v in A.worst.items() if k not in not_sf]
    lam = A.worst.get("film (lambda)", (math.nan,))[0]
    return (min(sf) if sf else math.nan), float(lam)


def _jump(scene, factor_hi: float) -> tuple:
    """(jump speed in rpm, note): NaN and no note for a rigid train or no jump in the range; NaN
    and the reason when the search is refused (a train too soft for the range)."""
    if scene.train is None:
        return math.nan, ""
    try:
        r = jump_speed(scene.train, scene.program, 0.25 * scene.rpm, factor_hi * scene.rpm,
                       steps_per_rev=scene.steps_per_rev)
    except FemcamError as exc:
        return math.nan, f"jump speed not computed: {exc}".replace("\n", " ")
    return float(r.rpm_jump), ""


def _wear(scene, theta) -> tuple:
    """(largest cam wear depth after one revolution in m, note) of the Archard map."""
    try:
        coating = coating_wear(scene.layers, scene.wear, scene.cam.hardness)
        wm = scene_wear(contact_case(scene, theta), cycles=1.0, coating=coating)[0]
    except FemcamError as exc:
        return math.nan, f"wear not computed: {exc}".replace("\n", " ")
    return float(wm.max_depth), ""


def evaluate(scene, options: EvalOptions) -> dict:
    """The Hertz-chain record of one variant (module docstring for the metrics).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The variant (SI).
    options : EvalOptions
        Angles per revolution, jump-speed search range.

    Returns
    -------
    dict
        ``status`` ("ok" or "failed"), ``reason`` (text), ``model`` ("hertz") and the
        :data:`METRICS` (SI; NaN where not computed).
    """
    _validate.record("scene", scene, "a femcam Scene (a study variant)", "analyse", "train", "rpm")
    _validate.instance("options", options, EvalOptions)
    rec = {m: math.nan for m in METRICS}
    rec.update(status="ok", reason="", model="hertz", has_train=float(scene.train is not None))
    theta = np.linspace(0.0, 2.0 * math.pi, int(options.n_angles), endpoint=False)
    try:
        st = scene.analyse(theta, allow_undercut=True)
        rho = np.asarray(st.rho, float)
        convex = rho[np.isfinite(rho) & (rho > 0)]
        rec.update(phi_max=float(np.max(np.abs(st.phi))), undercut=float(bool(st.undercut_intervals)),
                   Fc_min=float(np.min(st.Fc)), Fc_max=float(np.max(st.Fc)), rpm=float(scene.rpm),
                   rho_min=float(np.min(convex)) if convex.size else math.inf,
                   cam_radius_max=float(np.max(np.hypot(st.profile.x, st.profile.y))))
        R2 = _contact_radius(scene)
        with np.errstate(divide="ignore"):
            conformal = (1.0 / rho + 1.0 / R2) <= 0.0  # a concave cam tighter than the roller
        if np.any(conformal):  # the roller does not fit: an undercut in the concave sense
            rec["undercut"] = 1.0
            rec["reason"] = (f"no Hertz contact at {int(conformal.sum())} angles: the concave cam radius "
                             "is smaller than the follower's (1/R1 + 1/R2 <= 0)")
        on = (st.Fc > 0) & ~conformal
        if not np.any(on):
            raise FemcamError("no contact angle: the follower is off the cam or does not fit at every angle")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", HertzValidityWarning)  # a/R flagged, not refused
            hc = LineContact(F=st.Fc[on], length=scene.length, R1=rho[on], R2=R2,
                             cam=scene.cam, roller=scene.roller, mu=scene.mu, plane=scene.plane)
            p0 = np.asarray(hc.p0, float) * np.ones(int(on.sum()))
            i = int(np.argmax(p0))
            f = shape_factors(scene.mu, scene.cam.nu, scene.plane)
            rec.update(theta=float(theta[on][i]), p0_max=float(p0[i]), Fc_at_p0=float(st.Fc[on][i]),
                       a_at_p0=float(np.broadcast_to(hc.a, p0.shape)[i]),
                       R_at_p0=float(np.broadcast_to(hc.R, p0.shape)[i]),
                       von_mises_max=float(p0[i] * f["von_mises"][0]), tau1_max=float(p0[i] * f["tau1"][0]))
        if not rec["undercut"]:
            rec["sf_min"], rec["lambda_min"] = _assessment(scene, theta)
        rec["rpm_jump"], note = _jump(scene, options.jump_factor_hi)
        rec["wear_depth_per_rev"], wnote = _wear(scene, theta) if options.wear else (math.nan, "")
        rec["reason"] = "; ".join(t for t in (rec["reason"], note, wnote) if t)
    except FemcamError as exc:
        rec.update(status="failed", reason=f"{type(exc).__name__}: {exc}".replace("\n", " "))
    return rec


def evaluate_batch(task: tuple) -> list:
    """Evaluate a batch of variants (the unit of parallel work; module-level, so it pickles).

    Parameters
    ----------
    task : tuple
        ``(options, [(content hash, scene), ...])``.

    Returns
    -------
    list of tuple
        ``(content hash, record)`` per variant (:func:`evaluate`).
    """
    options, items = task
    return [(h, evaluate(scene, options)) for h, scene in items]
