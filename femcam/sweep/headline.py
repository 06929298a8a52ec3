"""What the sweep's headline columns are, and where they cannot be taken at face value.

The headline contact model of every row is the 2D contact of the scene's bodies at ``Fc /
length`` (:mod:`femcam.sweep.table`, "which column answers what"): a coating is in it (the
coated model answers: ``model`` reads ``fe_arc+coating``, :data:`COATED`), except on Hertz rows
(method hertz) and flat-faced followers; a roller on a pin or needles is the ring model's
(:mod:`femcam.sweep.ringhead`, ``model`` ``...+ring``), a cam on its shaft the local cam body
verified against the whole disk (:func:`answered_by`). Two things are said
per row in ``flags``, never left silent:

* :func:`omitted_physics` -- the scene holds physics that model leaves out (a coating, a finite
  contact length); the flag also goes into the summary line and ``report.md``
  (``provenance["extras"]["headline"]``, with the sentences of :func:`answered_by`);
* :func:`edge_flags` -- an FE surface extreme (``surf_*``) that is a value of the
  discretisation's contact-edge singularity, not a result.
"""

from __future__ import annotations

import math

import numpy as np

from ..bodies.cam_rows import has_cam_bore
from ..fe import ContactResult
from ..halfspace.rows import has_finite_length
from ..layers.from_scene import coating_phrase, scene_coatings
from .providers import has_support

#: FE surface error away from the contact edge, as a fraction of p0: the FE surface sx, sz, txz
#: of a Hertzian row (a/h = 10, steel, stick and full sliding at mu = 0.1) differ from the Hertz
#: surface field (Johnson 1985 §7.1) by <= 14 MPa at p0 = 742 MPa (1.9 %) beyond one element
#: from the edge; within it the edge singularity of the discretisation gives up to 27 MPa of
#: txz where the contact carries none (docs/sweep.md, "Surface columns at the contact edge")
SURF_EDGE_TOL = 0.02

#: suffix of the ``model`` column on a row the coated contact FE answered (``fe_arc+coating``)
COATED = "+coating"


def edge_flags(r: ContactResult) -> list[str]:
    """``surf_edge_dominated:<column>`` for each FE surface extreme that lies within one element
    of the contact edge and exceeds what the contact can carry by more than :data:`SURF_EDGE_TOL`
    ``p0``: a value of the discretisation's edge singularity, not a result.

    What the contact can carry, from bounds that hold for every slip state: ``|txz| <= max |q|``
    (the surface traction boundary condition, ``q`` the solved traction), ``sz >= -p0``, and
    ``sx`` within the Hertz surface field at full sliding (Johnson 1985 §7.1, seed 002 eqs. 5-7;
    the tensile peak ``2 mu p0`` at the trailing edge bounds the partial-slip one).

    Parameters
    ----------
    r : femcam.fe.ContactResult
        The solved load case (``x``, ``p``, ``q``, ``a``, ``x0`` [m, Pa], cam surface stresses).

    Returns
    -------
    list of str
        The flags (empty when no extreme is edge-dominated).
    """
    S = r.surface_by_body.get("cam")
    if S is None or not S.sx.size or r.x.size < 2 or not r.a > 0:
        return []
    p0, h = float(r.p0_nodal), float(np.median(np.diff(r.x)))
    # Hertz surface field at full sliding (seed 002 eqs. 5-7): sx = -p0 (sqrt(1 - X^2) + 2 mu X)
    # inside, so min sx = -p0 sqrt(1 + 4 mu^2); the tensile peak is 2 mu p0 at the trailing edge
    sx_max, sx_min = 2.0 * r.mu * p0, -p0 * math.sqrt(1.0 + 4.0 * r.mu**2)
    q = float(np.max(np.abs(r.q))) if r.q is not None and np.size(r.q) else 0.0
    near = np.abs(np.abs(S.x - r.x0) - r.a) <= h
    tol = SURF_EDGE_TOL * p0
    out = []
    for name, v, j, limit in (("surf_sx_max", S.sx, np.argmax(S.sx), sx_max),
                              ("surf_sx_min", -S.sx, np.argmin(S.sx), -sx_min),
                              ("surf_sz_min", -S.sz, np.argmin(S.sz), p0),
                              ("surf_txz_absmax", np.abs(S.txz), np.argmax(np.abs(S.txz)), q)):
        if near[j] and v[j] > limit + tol:
            out.append(f"surf_edge_dominated:{name}")
    return out


def coating_in_headline(scene, method: str = "fe") -> bool:
    """True when the sweep's headline contact carries the scene's coating: the FE answers
    (method ``fe`` or ``auto``, which gives a coated scene's rows to the FE) and the follower
    is not flat-faced (its real-cam model has no coating band).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.
    method : str, optional
        The sweep's method (``fe``, ``auto`` or ``hertz``).

    Returns
    -------
    bool
        The coated model answers the headline (False for an uncoated scene).
    """
    return (bool(scene_coatings(scene.layers)) and method != "hertz"
            and not getattr(scene.follower, "flat_face", False))


def omitted_physics(scene, method: str = "fe") -> tuple[tuple[str, str], ...]:
    """What the scene holds that the sweep's headline contact model (the 2D two-body contact of
    the solid bodies at ``Fc / length``) leaves out: ``(flag, sentence)`` pairs. The flag goes
    into the ``flags`` of every ``ok`` row, the sentence into the summary line and
    ``report.md``, so a headline never omits physics silently.

    A coating is listed only where the coated FE does not answer (:func:`coating_in_headline`:
    method hertz, a flat-faced follower). A hardened case is not listed: it changes no elastic
    constant, so the headline contact is the case-hardened body's; the case's strength is
    checked in the ``case_*`` columns, from the headline solve's stress field. A ring on a pin
    or needles and a cam on its shaft are not listed either: their models answer the headline
    (:func:`answered_by`).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.
    method : str, optional
        The sweep's method (``fe``, ``auto`` or ``hertz``).

    Returns
    -------
    tuple of (str, str)
        ``headline_omits_coating``, ``headline_2d_mean_load`` as they apply, each with its
        sentence.
    """
    out = []
    for body, c in () if coating_in_headline(scene, method) else scene_coatings(scene.layers):
        out.append(("headline_omits_coating",
                    f"headline_omits_coating: {coating_phrase(body, c)} is not in the contact "
                    "model that answers here (method hertz, or a flat-faced follower's real-cam "
                    "FE: homogeneous bodies); its own stresses are the interface_* and coating_* "
                    "columns"))
    if has_finite_length(scene.finite_length, scene.length):
        out.append(("headline_2d_mean_load",
                    "headline_2d_mean_load: finite length, two answers side by side: p0_fe_MPa, "
                    "a_fe_um and the stress columns are the 2D contact at the MEAN load Fc / length; "
                    "p0_peak_slice_MPa, a_peak_slice_um and *_peak_slice_MPa are the 2D FE at the "
                    "MOST LOADED slice (method fe, F = w_max * length; the 3D half-space peak is "
                    "p_axial_peak_MPa); wear and the assessment use the most loaded slice"))
    return tuple(out)


def answered_by(scene) -> tuple[str, ...]:
    """Which model answers the headline where the scene holds real bodies (one sentence each,
    for the summary line and ``report.md``; no row flag: the row's ``model`` column says it).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    tuple of str
        ``headline_ring: ...`` (a roller on a pin or needles) and ``headline_cam_disk: ...``
        (a cam on its shaft) as they apply.
    """
    out = []
    if has_support(scene):
        out.append(f"headline_ring: the roller runs on {scene.bodies.roller.support}; p0_fe, a_fe and "
                   "err_* are the ring model's contact (model ...+ring), its stresses the solid "
                   "roller's scaled to it (global-local); p0_hertz is the solid roller's Hertz")
    if has_cam_bore(scene.bodies):
        out.append("headline_cam_disk: the cam sits on its shaft; the contact columns are the "
                   "local cam body's (global-local), checked once against the fully refined "
                   "disk at the peak force (cam disk check below); the disk is in the cam_bore_* "
                   "and shaft_* columns")
    return tuple(out)
