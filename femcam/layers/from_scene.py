"""Coatings and cases from a scene's ``[materials.<body>.coating|case]`` records
(``Scene.layers``), and the per-angle layer checks of a scene (sweep-facing: one row per cam
angle), from the records and the contact force and cam curvature at the angles."""

from __future__ import annotations

import math
import threading

import numpy as np

from .. import _validate
from ..errors import InputError
from ..fe import ContactModel, SolverOptions
from ..hertz import LineContact
from ..materials import Material
from ..mesh import MeshOptions
from ..scene.layers import CoatingSpec
from ..scene.pair import ContactPair
from .case import Case
from .coating import Coating, build_coated_model
from .interface import layer_rows


def scene_coatings(layers) -> tuple[tuple[str, CoatingSpec], ...]:
    """The coated bodies of a scene: ``(body, coating)`` pairs (SI: ``thickness`` [m], ``E``
    [Pa], ...). The one scene test of "is a body coated" used by the
    sweep's headline flag (:func:`femcam.sweep.headline.omitted_physics`) and by the assessment
    (:func:`femcam.assess.assess_rows`, ``omits_coating``), whose contact models are homogeneous.

    Parameters
    ----------
    layers : tuple of femcam.scene.layers.BodyLayers
        The scene's coatings and cases (``Scene.layers``).

    Returns
    -------
    tuple of (str, femcam.scene.layers.CoatingSpec)
        One pair per ``[materials.<body>.coating]`` table (empty for an uncoated scene).
    """
    return tuple((b.body, b.coating) for b in layers if b.coating is not None)


def coating_phrase(body: str, c: CoatingSpec) -> str:
    """``"the roller's 2.5 um coating (E 170 GPa)"``: a coating as the flags' sentences name it.

    Parameters
    ----------
    body : str
        The coated body (``cam`` or ``roller``).
    c : femcam.scene.layers.CoatingSpec
        Its coating (SI: ``thickness`` [m], ``E`` [Pa]).

    Returns
    -------
    str
        The phrase (thickness in um, E in GPa).
    """
    return f"the {body}'s {c.thickness * 1e6:g} um coating (E {c.E / 1e9:g} GPa)"


def scene_layers(layers, follower) -> dict:
    """Coating and case of a scene from its ``[materials.<body>.coating|case]`` records.

    One coated body per model (the FE mesh has one coating band); a case must be shallower than
    half the body size (cam: base radius; roller: roller radius).

    Parameters
    ----------
    layers : tuple of femcam.scene.layers.BodyLayers
        The scene's coatings and cases (``Scene.layers``, SI).
    follower : femcam.profile follower
        The scene's follower (its ``Rb`` and, for a roller, ``Rr``; m).

    Returns
    -------
    dict
        ``{"coating": (body, Coating) or None, "case": (body, Case) or None}``.

    Raises
    ------
    InputError
        More than one coated body, or a case too deep for its body.
    """
    out = {"coating": None, "case": None}
    coated = [body for body, _ in scene_coatings(layers)]
    if len(coated) > 1:
        raise InputError(f"coatings on {coated}: femcam models one coated body per scene")
    for b in layers:
        if (c := b.coating) is not None:
            out["coating"] = (b.body, Coating(
                thickness=c.thickness, material=Material(E=c.E, nu=c.nu, name=c.name),
                interface_shear_strength=c.interface_shear_strength, hardness=c.hardness))
        if (c := b.case) is not None:
            case = Case(depth=c.depth, surface_hardness=c.surface_hardness,
                        core_hardness=c.core_hardness, surface_yield=c.surface_yield,
                        core_yield=c.core_yield, law=c.hardness_law)
            case.check_body(follower.Rb if b.body == "cam" else getattr(follower, "Rr", math.inf), b.body)
            out["case"] = (b.body, case)
    return out


#: model grading bins (:func:`model_grading`): log of the Hertz half-width in steps of ln 1.25
#: and the cam curvature ``Rr / rho`` in steps of 0.25, both well inside the range a model covers
#: (``SolverOptions.a_range = (0.6, 1.6)``, ``kappa_tol = 0.5``)
A_BIN = math.log(1.25)
K_BIN = 0.25
_MODELS: dict = {}
#: models kept per process, least recently used dropped first: a coated model at a/h = 20 holds
#: ~190 MB (mesh, factorisation, stress operators); a call solves its angles bin by bin, so it
#: builds each bin's model once, and a rebuilt model is the same model (the rows do not change)
_MODELS_MAX = 2
_LOCK = threading.Lock()


def model_grading(a: float, rho: float, Rr: float) -> tuple[float, float]:
    """``(rho_ref, a_ref)`` of the layer model that answers a load case of Hertz half-width ``a``
    at cam radius of curvature ``rho``: the centre of the case's bin (:data:`A_BIN` in ``log a``,
    :data:`K_BIN` in ``Rr / rho``). It depends on the load case alone, so a cam angle's layer
    rows never depend on which other angles are solved with it (sweep chunks, resumes).

    Parameters
    ----------
    a : float
        Hertz half-width of the load case [m], > 0.
    rho : float
        Cam radius of curvature [m] (signed; ``inf`` flat).
    Rr : float
        Roller radius [m].

    Returns
    -------
    rho_ref, a_ref : float
        Grading of the model [m] (``rho_ref`` is never infinite: the flat bin's centre is
        ``8 Rr``).

    >>> rho_ref, a_ref = model_grading(1e-4, math.inf, 0.01)
    >>> round(rho_ref, 6), round(a_ref / 1e-4, 4)
    (0.08, 0.9511)
    """
    i = math.floor(math.log(a) / A_BIN)
    k = 0.0 if math.isinf(rho) else Rr / rho
    j = math.floor(k / K_BIN)
    return Rr / ((j + 0.5) * K_BIN), math.exp((i + 0.5) * A_BIN)


def _build(pair, Rr, lay, rho_ref, a_ref, a_over_h):
    """The layer model graded for ``(rho_ref, a_ref)`` (the last :data:`_MODELS_MAX` kept per process)."""
    key = (repr(pair), Rr, repr(lay), rho_ref, a_ref, a_over_h)
    with _LOCK:
        if key in _MODELS:
            _MODELS[key] = _MODELS.pop(key)   # most recently used last
            return _MODELS[key]
    mesh = MeshOptions(a_over_h=a_over_h)
    solver = SolverOptions()
    if lay["coating"] is None:
        model = ContactModel.build(Rr=Rr, rho_ref=rho_ref, cam=pair.cam, roller=pair.roller,
                                   length=pair.length, a_ref=a_ref, mesh=mesh, solver=solver,
                                   plane=pair.plane)
    else:
        body, coat = lay["coating"]
        model = build_coated_model(Rr=Rr, rho_ref=rho_ref, cam=pair.cam, roller=pair.roller,
                                   length=pair.length, a_ref=a_ref, coating=coat, body=body,
                                   mesh=mesh, solver=solver, plane=pair.plane)
    with _LOCK:
        while len(_MODELS) >= _MODELS_MAX:
            _MODELS.pop(next(iter(_MODELS)))
        _MODELS[key] = model
    return model


def _hertz_a(pair, Rr, F, rho) -> float:
    """Hertz half-width [m] of the pair's contact at ``(F, rho)`` on a roller of radius ``Rr``."""
    return float(LineContact(F=F, length=pair.length, R1=rho, R2=Rr, cam=pair.cam,
                             roller=pair.roller, plane=pair.plane).a)


def scene_layer_rows(layers, pair: ContactPair, follower, theta, Fc, rho, *,
                     a_over_h: float = 10.0) -> dict:
    """Layer checks of a scene at cam angles ``theta`` (rad): ``theta_deg``, ``F_N``,
    ``rho_mm``, ``models`` (models built) and the :func:`~femcam.layers.layer_rows` columns.
    Each angle is solved with the model of its load case's bin (:func:`model_grading`; the last
    two models kept per process), or one of its own where that model does not cover it, so an angle's row does
    not depend on the other angles of the call; lift-off angles are NaN rows. Roller followers
    only.

    Parameters
    ----------
    layers : tuple of femcam.scene.layers.BodyLayers
        The scene's coatings and cases (``Scene.layers``), a coating and/or a case.
    pair : femcam.scene.pair.ContactPair
        The contact pair (``Scene.pair``: materials, length, plane, friction, sliding).
    follower : femcam.profile follower
        A roller follower (its ``Rr`` and ``Rb``; m).
    theta : array_like of float, shape (n,)
        Cam angles [rad].
    Fc : array_like of float, shape (n,)
        Contact force at ``theta`` [N] (``Scene.analyse``); ``<= 0`` or NaN (lift-off): a NaN row.
    rho : array_like of float, shape (n,)
        Cam radius of curvature at ``theta`` [m] (< 0 concave, inf flat).
    a_over_h : float, optional
        Mesh grading: contact half-width over element size [-].

    Returns
    -------
    dict
        Arrays of shape (n,): ``theta_deg`` [deg], ``F_N`` [N], ``rho_mm`` [mm] and the
        :func:`~femcam.layers.layer_rows` columns; ``models`` (int) the number of models built.

    Raises
    ------
    InputError
        Not a roller follower, no coating or case table, or arrays that do not match.
    """
    if not hasattr(follower, "Rr"):
        raise InputError("scene_layer_rows: the FE contact model needs a roller follower")
    _validate.instance("pair", pair, ContactPair, "a femcam.scene ContactPair (Scene.pair)")
    lay = scene_layers(layers, follower)
    if lay["coating"] is None and lay["case"] is None:
        raise InputError("scene_layer_rows: the scene has no [materials.<body>.coating] or .case table")
    theta = _validate.finite_array("theta", theta, "rad").ravel()
    Fc = _validate.data_array("Fc", Fc, "N").ravel()   # NaN or <= 0: no contact at that angle
    rho_all = _validate.radius_array("rho", rho, "m").ravel()
    if not (theta.shape == Fc.shape == rho_all.shape):
        raise InputError(f"theta, Fc, rho: shapes {theta.shape}, {Fc.shape}, {rho_all.shape} must match")
    a_over_h = _validate.positive("a_over_h", a_over_h, "")
    Rr = follower.Rr
    sliding = -1 if pair.sliding == "-x" else 1
    cases = []   # (grading, j, F, rho, a) of the angles in contact, solved bin by bin
    for j in range(theta.size):
        F, rho = float(Fc[j]), float(rho_all[j])
        if F > 0:
            a = _hertz_a(pair, Rr, F, rho)
            cases.append((model_grading(a, rho, Rr), j, F, rho, a))
    rows, used = None, set()
    for grading, j, F, rho, a in sorted(cases, key=lambda c: (c[0], c[1])):
        key = grading
        model = _build(pair, Rr, lay, *key, a_over_h)
        if not model.covers(F, rho):   # the bin's model does not cover it: one of its own
            key = (rho, a)
            model = _build(pair, Rr, lay, *key, a_over_h)
        used.add(key)
        r = layer_rows(model, [F], [rho], [pair.mu], sliding=sliding,
                       coating=lay["coating"][1] if lay["coating"] else None,
                       coat_body=lay["coating"][0] if lay["coating"] else "roller",
                       case=lay["case"][1] if lay["case"] else None,
                       case_body=lay["case"][0] if lay["case"] else "cam")
        if rows is None:
            rows = {k: np.full(theta.size, np.nan) for k in r}
        for k, v in r.items():
            rows[k][j] = v[0]
    rows = rows or {}
    rows.update(theta_deg=np.degrees(theta), F_N=Fc.astype(float), rho_mm=rho_all * 1e3, models=len(used))
    return rows
