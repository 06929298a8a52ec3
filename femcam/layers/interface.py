r"""Interface stresses along the coating-substrate boundary, and the per-angle layer checks.

==============  ===========================================================  ====
symbol          meaning                                                      unit
==============  ===========================================================  ====
``phi``         slope of the interface arc at abscissa ``x``                 rad
``sigma_n``     interface normal stress (tension > 0)                        Pa
``tau_i``       interface shear stress                                       Pa
==============  ===========================================================  ====

The interface is the arc at depth ``t`` of radius ``R - t`` (signed ``R`` of the body). With
the body's Johnson-frame stresses ``(s_x, s_z, t_xz)`` (x along the tangent at the contact, z
into the body) and ``tan phi = dz/dx`` of the interface (Johnson 1985 §2.1 for the rotation):

.. math:: \sigma_n = s_x \sin^2\phi + s_z \cos^2\phi - 2 t_{xz}\sin\phi\cos\phi,\qquad
          \tau_i = (s_z - s_x)\sin\phi\cos\phi + t_{xz}(\cos^2\phi - \sin^2\phi)

The normal and shear tractions are continuous across a bonded interface, so the nodal average
of both sides' stresses (``femcam.fe`` recovery) is used at the interface vertices.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from .._columns import Column
from .._repr import compact_repr
from ..errors import InputError
from .case import Case, case_margin
from .coating import Coating


@dataclass(frozen=True)
class InterfaceStress:
    """Interface tractions of one load case along the coating-substrate interface.

    Parameters
    ----------
    x : ndarray of float, shape (n,)
        Abscissae of the interface nodes [m], sorted.
    sigma_n : ndarray of float, shape (n,)
        Interface normal stress [Pa] (tension > 0).
    tau : ndarray of float, shape (n,)
        Interface shear stress [Pa].
    tau_abs_max : float
        ``max |tau|`` [Pa].
    x_tau_max : float
        Abscissa of ``tau_abs_max`` [m].
    sigma_n_min, sigma_n_max : float
        Most compressive and most tensile ``sigma_n`` [Pa].
    """

    x: np.ndarray
    sigma_n: np.ndarray
    tau: np.ndarray
    tau_abs_max: float
    x_tau_max: float
    sigma_n_min: float
    sigma_n_max: float

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)



def _coated(model, body: str):
    g = model.bodies[body].geometry
    if g.coating is None:
        raise InputError(f"body {body} of this model has no coating band; build it with "
                         "femcam.layers.build_coated_model(..., body=...)")
    return g


def interface_stress(result, body: str = "roller", *, model=None) -> InterfaceStress:
    """Normal and shear stress along the coating-substrate interface of ``body`` within the
    contact fine zone.

    Parameters
    ----------
    result : femcam.fe.ContactResult
        A result of a coated model (:func:`femcam.layers.build_coated_model`), with its model.
    body : {"cam", "roller"}, optional
        The coated body.
    model : femcam.fe.ContactModel, optional
        The coated model that solved ``result``, used when ``result`` carries none (after
        unpickling); default: ``result.model``.

    Returns
    -------
    InterfaceStress
        The interface tractions and their extrema.

    Raises
    ------
    InputError
        ``body`` has no coating band, or ``result`` was unpickled (its model is not kept) and
        no ``model`` is given.
    """
    _validate.choice("body", body, ("cam", "roller"))
    model = result.model_or(model)
    g = _coated(model, body)
    _, f = result.field_at_nodes(body, model=model)
    nodes = g.groups[f"{body}_interface"].nodes
    x = f["xy"][0, nodes]
    keep = np.abs(x) <= model.x[-1] * (1 + 1e-9)
    nodes, x = nodes[keep], x[keep]
    o = np.argsort(x)
    nodes, x = nodes[o], x[o]
    sx, sz, txz = f["sx"][nodes], f["sz"][nodes], f["txz"][nodes]
    Ri = g.R - model.mesh.options.coat_thickness
    k = 0.0 if math.isinf(Ri) else 1.0 / Ri
    phi = np.arctan(k * x / np.sqrt(np.maximum(1.0 - (k * x) ** 2, 1e-300)))
    s, c = np.sin(phi), np.cos(phi)
    sn = sx * s**2 + sz * c**2 - 2.0 * txz * s * c
    tau = (sz - sx) * s * c + txz * (c**2 - s**2)
    i = int(np.argmax(np.abs(tau)))
    return InterfaceStress(x=x, sigma_n=sn, tau=tau, tau_abs_max=float(abs(tau[i])),
                           x_tau_max=float(x[i]), sigma_n_min=float(sn.min()),
                           sigma_n_max=float(sn.max()))


def _case_row(result, case: Case, body: str, model=None):
    """(U_max, z at max, margin) of ``case`` in ``body``: tau_1 / k(z) at every node of the
    stress window ``|x| <= fine zone``, ``z <= 4 max(a, depth)``; ``model``: the solving model
    when ``result`` carries none (unpickled)."""
    model = result.model_or(model)
    case.check_body(model.bodies[body].geometry.L, body)
    _, f = result.field_at_nodes(body, model=model)
    z, x = f["z"], f["xy"][0]
    w = (np.abs(x) <= model.x[-1]) & (z >= 0) & (z <= 4.0 * max(result.a, case.depth))
    m = case_margin(case, z[w], f["tau1"][w])
    return m.u_max, m.z_at_max, m.margin


def layer_rows(model, F, rho, mu, *, coating: Coating | None = None, coat_body: str = "roller",
               case: Case | None = None, case_body: str = "cam", sliding: int = 1) -> dict:
    """Per-angle layer checks (one FE solve per angle on the prepared ``model``).

    The coating's stresses are computed whether or not its strengths are given; only the
    utilisations need them (``interface_shear_strength``, ``hardness``) and are NaN without.

    Parameters
    ----------
    model : femcam.fe.ContactModel
        The prepared model (coated by :func:`femcam.layers.build_coated_model` for a coating).
    F : array_like of float, shape (n,)
        Contact force per angle [N].
    rho : array_like of float
        Cam radius of curvature per angle [m], signed; broadcast against ``F``.
    mu : array_like of float
        Friction coefficient per angle [-]; broadcast against ``F``.
    coating : Coating, optional
        The coating to check (its strengths, where given, for the utilisations).
    coat_body : {"cam", "roller"}, optional
        The coated body.
    case : Case, optional
        The hardened case to check.
    case_body : {"cam", "roller"}, optional
        The case-hardened body.
    sliding : {+1, -1}, optional
        Direction of the friction traction on the cam along x.

    Returns
    -------
    dict of str to ndarray, shape (n,)
        CSV-ready columns (nan for checks not requested): ``interface_tau_max_MPa``,
        ``interface_sn_min_MPa``, ``interface_sn_max_MPa`` [MPa], ``interface_utilisation``
        (``tau_max / tau_i``) [-], ``coating_sx_max_MPa`` (coating surface tension) [MPa],
        ``coating_sx_utilisation`` (``max(sx_max, 0) / (H_c / 3)``, the yield estimate of the
        coating) [-], ``case_utilisation_max`` [-], ``case_z_at_max_mm`` [mm], ``case_margin`` [-].

    Raises
    ------
    InputError
        Neither ``coating`` nor ``case``.
    """
    F, rho, mu = np.broadcast_arrays(np.atleast_1d(_validate.nonnegative_array("F", F, "N")),
                                     _validate.radius_array("rho", rho, "m"),
                                     _validate.nonnegative_array("mu", mu, ""))
    if coating is None and case is None:
        raise InputError("layer_rows: give a coating and/or a case (nothing to check)")
    _validate.record("model", model, "a ContactModel (femcam.fe or build_coated_model)", "solve", "bodies")
    out = {c: np.full(F.size, np.nan) for c in LAYER_COLUMNS}
    for j in range(F.size):
        r = model.solve(F=float(F.flat[j]), rho=float(rho.flat[j]), mu=float(mu.flat[j]),
                        sliding=sliding)
        for c, v in result_layer_row(r, coating=coating, coat_body=coat_body, case=case,
                                     case_body=case_body).items():
            out[c][j] = v
    return out


#: the columns of :func:`layer_rows` and :func:`result_layer_row` (CSV names, units in the names)
LAYER_COLUMNS = ("interface_tau_max_MPa", "interface_sn_min_MPa", "interface_sn_max_MPa",
                 "interface_utilisation", "coating_sx_max_MPa", "coating_sx_utilisation",
                 "case_utilisation_max", "case_z_at_max_mm", "case_margin")

#: the same checks as sweep columns, declared here by the package that computes them: SI names
#: (``layer_interface_tau_max`` in Pa, ``layer_case_z_at_max`` in m), the CSV names of
#: :data:`LAYER_COLUMNS` with their factors from SI (:mod:`femcam.sweep.extras`, provider
#: ``layers``)
SWEEP_COLUMNS = (Column("layer_interface_tau_max", "interface_tau_max_MPa", 1e-6,
                        "largest |shear| along the coating-substrate interface"),
                 Column("layer_interface_sn_min", "interface_sn_min_MPa", 1e-6,
                        "most compressive normal stress on the interface"),
                 Column("layer_interface_sn_max", "interface_sn_max_MPa", 1e-6,
                        "most tensile normal stress on the interface"),
                 Column("layer_interface_utilisation", "interface_utilisation", 1.0,
                        "interface shear / interface_shear_strength"),
                 Column("layer_coating_sx_max", "coating_sx_max_MPa", 1e-6,
                        "largest surface sx of the coated body"),
                 Column("layer_coating_sx_utilisation", "coating_sx_utilisation", 1.0,
                        "coating tension / (hardness / 3)"),
                 Column("layer_case_utilisation_max", "case_utilisation_max", 1.0,
                        "largest tau_1 / k(z) (shear strength at depth) through the case"),
                 Column("layer_case_z_at_max", "case_z_at_max_mm", 1e3,
                        "depth of that largest utilisation"),
                 Column("layer_case_margin", "case_margin", 1.0,
                        "case-core margin 1 / max_z U (femcam.layers.case_margin)"))


def result_layer_row(result, *, coating: Coating | None = None, coat_body: str = "roller",
                     case: Case | None = None, case_body: str = "cam", model=None) -> dict:
    """The layer checks of one solved load case, from its own stress field: the sweep takes
    them from the solve that answers its headline (no second model).

    The coating's stresses need no strength; only the utilisations do (NaN without
    ``interface_shear_strength``, ``hardness``).

    Parameters
    ----------
    result : femcam.fe.ContactResult
        The solved load case (of a coated model when ``coating`` is given).
    coating : Coating, optional
        The coating to check.
    coat_body : {"cam", "roller"}, optional
        The coated body.
    case : Case, optional
        The hardened case to check.
    case_body : {"cam", "roller"}, optional
        The case-hardened body.
    model : femcam.fe.ContactModel, optional
        The solving model when ``result`` carries none (unpickled).

    Returns
    -------
    dict of str to float
        The :data:`LAYER_COLUMNS` (units in the names: MPa, mm, - ; NaN for checks not asked).
    """
    out = dict.fromkeys(LAYER_COLUMNS, math.nan)
    if coating is not None:
        tau_i, Hc = coating.interface_shear_strength, coating.hardness
        it = interface_stress(result, coat_body, model=model)
        sx = float(np.max(result.surface_by_body[coat_body].sx))
        out.update(interface_tau_max_MPa=it.tau_abs_max / 1e6, interface_sn_min_MPa=it.sigma_n_min / 1e6,
                   interface_sn_max_MPa=it.sigma_n_max / 1e6,
                   interface_utilisation=it.tau_abs_max / tau_i if tau_i else math.nan,
                   coating_sx_max_MPa=sx / 1e6,
                   coating_sx_utilisation=max(sx, 0.0) / (Hc / 3.0) if Hc else math.nan)
    if case is not None:
        u, zm, mg = _case_row(result, case, case_body, model)
        out.update(case_utilisation_max=u, case_z_at_max_mm=zm * 1e3, case_margin=mg)
    return out
