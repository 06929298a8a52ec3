"""Coatings and cases from a scene's ``[materials.<body>.coating|case]`` tables, and the
per-angle layer checks of a scene (sweep-facing: one row per cam angle)."""

from __future__ import annotations

import math

import numpy as np

from .. import _validate
from ..errors import InputError
from ..fe import ContactModel, SolverOptions
from ..hertz import LineContact
from ..materials import Material
from ..mesh import MeshOptions
from .case import Case
from .coating import Coating, build_coated_model
from .interface import layer_rows


def scene_layers(scene) -> dict:
    """Coating and case of ``scene`` from its ``[materials.<body>.coating|case]`` tables.

    One coated body per model (the FE mesh has one coating band); a case must be shallower than
    half the body size (cam: base radius; roller: roller radius).

    Parameters
    ----------
    scene : femcam.scene.Scene
        A loaded scene (``scene.layers`` holds SI values under SI names).

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
    coated = [b for b, t in scene.layers.items() if "coating" in t]
    if len(coated) > 1:
        raise InputError(f"coatings on {coated}: femcam models one coated body per scene")
    for body, tabs in scene.layers.items():
        if "coating" in tabs:
            c = tabs["coating"]
            out["coating"] = (body, Coating(
                thickness=c["thickness"], material=Material(E=c["E"], nu=c["nu"],
                                                            name=c.get("name", "coating")),
                interface_shear_strength=c.get("interface_shear_strength"),
                hardness=c.get("hardness")))
        if "case" in tabs:
            c = tabs["case"]
            case = Case(depth=c["depth"], surface_hardness=c.get("surface_hardness"),
                        core_hardness=c.get("core_hardness"), surface_yield=c.get("surface_yield"),
                        core_yield=c.get("core_yield"), law=c.get("hardness_law", "exponential"))
            size = scene.follower.Rb if body == "cam" else getattr(scene.follower, "Rr", math.inf)
            case.check_body(size, body)
            out["case"] = (body, case)
    return out


def _build(scene, lay, F, rho, a_over_h):
    hc = LineContact(F=F, length=scene.length, R1=rho, R2=scene.follower.Rr, cam=scene.cam,
                     roller=scene.roller, plane=scene.plane)
    mesh = MeshOptions(a_over_h=a_over_h)
    solver = SolverOptions()
    if lay["coating"] is None:
        return ContactModel.build(Rr=scene.follower.Rr, rho_ref=rho, cam=scene.cam, roller=scene.roller,
                                  length=scene.length, a_ref=float(hc.a), mesh=mesh, solver=solver,
                                  plane=scene.plane)
    body, coat = lay["coating"]
    return build_coated_model(Rr=scene.follower.Rr, rho_ref=rho, cam=scene.cam, roller=scene.roller,
                              length=scene.length, a_ref=float(hc.a), coating=coat, body=body,
                              mesh=mesh, solver=solver, plane=scene.plane)


def scene_layer_rows(scene, theta, *, a_over_h: float = 10.0) -> dict:
    """Layer checks of ``scene`` at cam angles ``theta`` (rad): ``theta_deg``, ``F_N``,
    ``rho_mm``, ``models`` (models built) and the :func:`~femcam.layers.layer_rows` columns.
    A model is rebuilt (rho_ref, a_ref of the angle) whenever the current one does not cover
    the angle (``ContactModel.covers``); lift-off angles are NaN rows. Roller followers only.

    Parameters
    ----------
    scene : femcam.scene.Scene
        A loaded scene with a coating and/or a case table and a roller follower.
    theta : array_like of float, shape (n,)
        Cam angles [rad].
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
        Not a roller follower, or no coating or case table.
    """
    if not hasattr(scene.follower, "Rr"):
        raise InputError("scene_layer_rows: the FE contact model needs a roller follower")
    lay = scene_layers(scene)
    if lay["coating"] is None and lay["case"] is None:
        raise InputError(f"scene {scene.name!r} has no [materials.<body>.coating] or .case table")
    theta = _validate.finite_array("theta", theta, "rad").ravel()
    a_over_h = _validate.positive("a_over_h", a_over_h, "")
    st = scene.analyse(theta)
    sliding = -1 if scene.sliding == "-x" else 1
    rows, model, n_models = None, None, 0
    for j in range(theta.size):
        F, rho = float(st.Fc[j]), float(st.rho[j])
        if st.liftoff[j] or F <= 0:
            continue
        if model is None or not model.covers(F, rho):
            model, n_models = _build(scene, lay, F, rho, a_over_h), n_models + 1
        r = layer_rows(model, [F], [rho], [scene.mu], sliding=sliding,
                       coating=lay["coating"][1] if lay["coating"] else None,
                       coat_body=lay["coating"][0] if lay["coating"] else "roller",
                       case=lay["case"][1] if lay["case"] else None,
                       case_body=lay["case"][0] if lay["case"] else "cam")
        if rows is None:
            rows = {k: np.full(theta.size, np.nan) for k in r}
        for k, v in r.items():
            rows[k][j] = v[0]
    rows = rows or {}
    rows.update(theta_deg=np.degrees(theta), F_N=np.asarray(st.Fc, float),
                rho_mm=np.asarray(st.rho, float) * 1e3, models=n_models)
    return rows
