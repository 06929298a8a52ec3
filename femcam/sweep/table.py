"""The sweep's result table: its columns, statuses and flags, and how it is filled chunk by
chunk (:class:`TableBuilder`, from the typed chunk tables :class:`femcam.sweep.chunk.ChunkRows`).

One row per cam angle. Inside the library every column is SI (rad, m, m/s, N, Pa, s); the
CSV writer in :mod:`femcam.io` converts to the unit written in the column name through
:data:`COLUMNS`.

Per-angle ``status``:

* ``"ok"``        -- contact, the requested method answered;
* ``"liftoff"``   -- Fc <= 0: no contact. Contact half-widths, p0, stresses and wear are 0 (no
  contact has zero width and zero pressure); depths of maxima and relative errors are NaN
  (undefined);
* ``"undercut"``  -- the cam is concave with ``|rho| <= Rr``: the roller does not fit the
  concave cam (1/rho + 1/Rr <= 0; the pitch curve is undercut or the bodies interfere). No
  contact solution exists, Hertz or FE; every result column is NaN and ``message`` says why;
* ``"failed"``    -- the FE solve at this angle failed; ``message`` says why, the sweep went on.
* ``"edge_contact"`` -- flat-faced follower: the contact runs past the end of the face
  (``[follower] face_length_mm``); not modelled (never Hertz), ``message`` gives the angle range.

Column names say where a value is taken (one rule, also in docs/sweep.md):

* ``p0_hertz``, ``a_hertz``: Hertz line contact at ``Fc / length`` and ``rho`` (the reference);
* ``p0_fe``: the peak of the solved contact pressure, its largest nodal value (the peak of the
  P1 pressure interpolant, ``ContactResult.p0_nodal``), from the model the row's ``model``
  names;
* ``p0_fit``: the peak of the Hertz ellipse fitted to the solved pressure (nodes above 20 % of
  the peak) -- a fit; ``a_fe``: that ellipse's half-width (where it reaches 0), a fit too, not
  the extent of the active set;
* ``err_p0``, ``err_a``: ``p0_fe / p0_hertz - 1`` (the solved peak against Hertz),
  ``a_fe / a_hertz - 1``;
* ``vm_max`` + ``vm_depth``, ``tau1_max`` + ``tau1_depth``: the largest value over the stress
  windows of both bodies (subsurface) and its depth below that body's surface;
* ``surf_sx_min``, ``surf_sx_max``, ``surf_sz_min``, ``surf_txz_absmax``: on the cam's contact
  surface (z = 0), over the FE stress window or the Hertz surface field (Johnson 1985 §7.1,
  seed 002 eqs. 5-7).

On a row whose ``model`` is ``hertz`` every contact column is Hertz's (``p0_fe``, ``p0_fit``
and ``a_fe`` NaN, the stresses from the Hertz shape factors); on ``fe_arc``/``fe_exact`` rows
they come from that solve. Why the peak and not the fit: near a curvature jump the pressure is
no ellipse; over the junction scene's 21 exact-gap rows the peak agrees with an independent
exact-gap half-space solve within 0.15 %, the fit is off by up to 1.5 % (docs/sweep.md, "Which
column answers what").

Real-cam columns (:mod:`femcam.sweep.realcam`): ``model`` (``hertz``, ``fe_arc``, ``fe_exact``:
which model answered; ``+ring`` when the ring model answered the contact),
``est_err_arc_pct``/``est_err_hertz_pct`` (estimated p0 error of the
cheaper models), ``curvature_jump`` (1 inside a curvature jump's straddle span),
``exact_vs_arc_p0_pct`` (peak p0 of the arc-gap FE vs the exact-gap FE, jump rows), ``Q_N``
(tangential force on the cam along local x), ``Q_over_muFc``, ``stick_width_um``,
``slip_state``.

Error estimates (:mod:`femcam.sweep.estimate`): ``err_est_p0_pct``, ``err_est_a_pct``,
``err_est_vm_pct``, ``err_est_tau1_pct`` (percent of the row's own value): the estimated
discretisation error of ``p0_fe``, ``a_fe``, ``vm_max``, ``tau1_max`` of an FE row (two-level
estimate on its family's model, carried to the row's ``a_over_h_row``; p0 includes the family's
reuse error); ``a_over_h_row``: elements per the row's Hertz half-width on the mesh that solved
it (dimensionless). NaN on Hertz rows. Coated rows: the estimate on the coated family model
(the interface stresses' in the layers provider's ``err_est_interface_*_pct``); ring rows
(``+ring``): p0 and a the ring model's own two-level estimate carried to its contact mesh
(``a_over_h_row`` is that mesh's; the bore, pin and needle estimates in the bodies provider's
``err_est_*_pct``; :mod:`femcam.sweep.ringhead`), the stresses NaN on ``hertz+ring``.

``flags`` is a ``;``-separated list of remarks on ``ok`` rows:

* ``hertz_large_a`` -- Hertz a / min(Rr, |rho|) > 0.1 (``LineContact.valid`` is False, or the FE
  result reports ``outside_hertz``): Hertz itself is questionable, the FE answer stands;
* ``nearly_conformal`` -- a concave cam close to the roller radius, where Hertz's parabolic gap
  is off by more than 0.1 % at the contact edge (quartic gap term / quadratic term at x = a,
  :func:`femcam.hertz.conformity.gap_nonparabolicity`); the FE uses the exact circular surfaces,
  so ``err_a``/``err_p0`` there measure Hertz's error as much as the FE's;
* ``Q_without_friction`` -- a Hertz-answered row (method auto) whose mechanism asks for a
  tangential force Q with friction 0: none can be carried, Q is set to 0;
* ``rebuilt`` -- the model of the angle's family did not cover it (``model.covers``) and a
  model was built for this angle alone (its reuse error is 0).
* ``surf_edge_dominated:<column>`` -- an FE surface extreme (``surf_*``) sits within one
  element of the contact edge and exceeds the value the contact can carry there by more than the
  FE's surface error (:data:`femcam.sweep.headline.SURF_EDGE_TOL` p0): a value of the
  discretisation's edge singularity, not a result (:func:`femcam.sweep.headline.edge_flags`);
* ``headline_omits_coating``, ``headline_2d_mean_load`` -- the scene holds physics the
  headline contact model leaves out (:func:`femcam.sweep.headline.omitted_physics`): a coating,
  a finite length (the headline is the 2D contact at the mean load ``Fc / length``; the most
  loaded slice is ``p0_peak_slice_MPa``, ``a_peak_slice_um``, ``*_peak_slice_MPa``, the 3D
  half-space peak ``p_axial_peak_MPa``).

A roller on a pin or needles is no omission: the ring model answers ``p0_fe``, ``p0_fit``,
``a_fe``, ``err_*`` and scales the solid roller's stresses to its contact (``model``
``fe_arc+ring``, ``fe_exact+ring``, ``hertz+ring``; :mod:`femcam.sweep.ringhead`); nor is a cam
on its shaft (the local cam body, checked against the fully refined disk once per sweep).

Subsurface orthogonal shear: ``txz_range_max`` is the largest range of ``txz`` over one pass,
``max_z [max_x txz(x, z) - min_x txz(x, z)]`` (Johnson 1985 §9.2; the stress cycle of
subsurface rolling-contact fatigue, fed to the assessment's ``dtau_orth``), at the depth
``txz_range_depth`` below the surface of the body where it is larger. FE rows: from the FE
subsurface field on rows of equal depth through the stress window, the contact-surface layer
left out (:attr:`femcam.fe.ContactResult.txz_range`; NaN where the window cuts the pass);
Hertz rows: McEwen's field with the row's traction ratio (:func:`femcam.hertz.max_shear_range`;
0.5 p0 at z = 0.5 a for mu up to ~0.5). It is not twice ``surf_txz_absmax``, which is a surface value.

Wear: ``wear_source`` says which pressure the ``wear_depth`` column used (``fe``, ``hertz`` or
``none``), see :mod:`femcam.sweep.wear`.
"""

from __future__ import annotations

import numpy as np

from .._columns import Column

__all__ = ["COLUMNS", "EXTRA_COLUMNS", "INTEGER_COLUMNS", "NUMERIC", "PROFILE_PREFIX", "STATUSES",
           "TEXT_COLUMNS", "WALL_CLOCK", "TableBuilder", "worst_row"]

#: prefix of the worst angle's surface-profile arrays in ``sweep.npz`` (for re-plotting)
PROFILE_PREFIX = "profile__"

#: the sweep's own columns (:class:`femcam._columns.Column`). Order = CSV column order.
COLUMNS: tuple[Column, ...] = (
    Column("theta", "theta_deg", 180.0 / np.pi),
    Column("s", "s_mm", 1e3),
    Column("v", "v_m_s", 1.0),
    Column("a", "a_m_s2", 1.0),
    Column("j", "j_m_s3", 1.0),
    Column("phi", "phi_deg", 180.0 / np.pi),
    Column("rho", "rho_mm", 1e3),
    Column("Fc", "Fc_N", 1.0),
    Column("a_hertz", "a_hertz_um", 1e6),
    Column("p0_hertz", "p0_hertz_MPa", 1e-6),
    Column("a_fe", "a_fe_um", 1e6),
    Column("p0_fe", "p0_fe_MPa", 1e-6),
    Column("err_a", "err_a_pct", 100.0),
    Column("err_p0", "err_p0_pct", 100.0),
    Column("vm_max", "vm_max_MPa", 1e-6),
    Column("vm_depth", "vm_depth_um", 1e6),
    Column("tau1_max", "tau1_max_MPa", 1e-6),
    Column("tau1_depth", "tau1_depth_um", 1e6),
    Column("txz_range_max", "txz_range_max_MPa", 1e-6),
    Column("txz_range_depth", "txz_range_depth_um", 1e6),
    Column("surf_sx_min", "surf_sx_min_MPa", 1e-6),
    Column("surf_sx_max", "surf_sx_max_MPa", 1e-6),
    Column("surf_sz_min", "surf_sz_min_MPa", 1e-6),
    Column("surf_txz_absmax", "surf_txz_absmax_MPa", 1e-6),
    Column("v_slip", "v_slip_m_s", 1.0),
    Column("V_cam", "V_cam_m_s", 1.0),
    Column("wear_depth", "wear_depth_per_rev_nm", 1e9),
    # FE on the real cam (femcam.sweep.realcam): model choice, curvature jumps, traction
    Column("p0_fit", "p0_fit_MPa", 1e-6),
    Column("curvature_jump", "curvature_jump", 1.0),
    Column("exact_vs_arc_p0", "exact_vs_arc_p0_pct", 100.0),
    Column("est_err_hertz", "est_err_hertz_pct", 100.0),
    Column("est_err_arc", "est_err_arc_pct", 100.0),
    # a posteriori discretisation-error estimates of the FE rows (femcam.sweep.estimate)
    Column("err_est_p0", "err_est_p0_pct", 100.0),
    Column("err_est_a", "err_est_a_pct", 100.0),
    Column("err_est_vm", "err_est_vm_pct", 100.0),
    Column("err_est_tau1", "err_est_tau1_pct", 100.0),
    Column("a_over_h_row", "a_over_h_row", 1.0),
    Column("Q", "Q_N", 1.0),
    Column("Q_over_muFc", "Q_over_muFc", 1.0),
    Column("stick_width", "stick_width_um", 1e6),
    Column("fe_time", "fe_time_ms", 1e3),
    Column("build_time", "build_time_ms", 1e3),
)

#: string columns (in the CSV with ``,``, ``#``, quotes and newlines replaced, see femcam.io)
TEXT_COLUMNS = ("status", "flags", "wear_source", "message", "model", "slip_state")

#: numeric diagnostics stored in the NPZ only
EXTRA_COLUMNS = ("iterations", "residual", "n_dofs", "family")

NUMERIC = tuple(c.si for c in COLUMNS) + EXTRA_COLUMNS
#: numeric columns that are counts or ids: int64 in the NPZ (-1 where undefined)
INTEGER_COLUMNS = ("iterations", "n_dofs", "family")
STATUSES = ("ok", "liftoff", "undercut", "failed", "edge_contact")

#: wall-clock columns (differ from run to run; excluded from equality checks)
WALL_CLOCK = ("fe_time", "build_time")


def worst_row(table: dict, column: str = "p0_fe") -> int:
    """Row index of the largest ``column`` among ``ok`` rows (falls back to Hertz p0, then 0).

    Parameters
    ----------
    table : dict[str, ndarray]
        A sweep table.
    column : str
        Column name (SI).

    Returns
    -------
    int
    """
    ok = table["status"] == "ok"
    vals = np.where(ok, table[column], np.nan)
    if not np.any(np.isfinite(vals)):
        vals = np.where(ok, table["p0_hertz"], np.nan)
    if not np.any(np.isfinite(vals)):
        return 0
    return int(np.nanargmax(vals))


class TableBuilder:
    """The sweep table filled chunk by chunk as chunks finish (any order), without keeping the
    chunks: one float array per numeric column, preallocated (memory ~ one copy of the table).

    Parameters
    ----------
    bounds : list of (int, int)
        Row ranges of the chunks.
    """

    def __init__(self, bounds):
        self.bounds = list(bounds)
        n = self.bounds[-1][1] if self.bounds else 0
        self.n = n
        self.numeric = {name: np.full(n, np.nan) for name in NUMERIC}
        self.text = {name: [np.zeros(0, str)] * len(self.bounds) for name in TEXT_COLUMNS}

    def put(self, c: int, rows) -> None:
        """Chunk ``c``'s rows into the table.

        Parameters
        ----------
        c : int
            Chunk index into ``bounds``.
        rows : femcam.sweep.chunk.ChunkRows
            The chunk's columns (SI numeric arrays and text arrays, each of the chunk's
            length): :meth:`~femcam.sweep.chunk.ChunkRows.items`, the sweep's columns and then
            the provider columns the chunk holds.
        """
        a, b = self.bounds[c]
        for name, v in rows.items():
            if rows.is_text(name):
                parts = self.text.setdefault(name, [np.zeros(0, str)] * len(self.bounds))
                parts[c] = np.asarray(v).astype(str)
            else:
                self.numeric.setdefault(name, np.full(self.n, np.nan))[a:b] = np.asarray(v, dtype=float)

    def table(self) -> dict:
        """The whole table: the chunks stacked in angle order.

        Returns
        -------
        dict[str, ndarray]
            Float columns (SI; NaN in rows of chunks not yet put) and ``str`` text columns.
        """
        out = dict(self.numeric)
        for name in self.text:
            out[name] = np.concatenate(self.text[name]) if self.text[name] else np.zeros(0, str)
        return out
