"""Result of one FE contact solve: :class:`ContactResult` with its stress maxima
(:class:`StressMax`, keys :data:`MAXIMA_KEYS`), the range of ``txz`` over one pass
(:class:`ShearRange`) and both bodies' surface stresses (:class:`SurfaceStress`).

The maxima and surface stresses are stored once per body (``max_by_body``,
``surface_by_body``); the over-both-bodies values (``von_mises_max``, ...) and the cam's surface
arrays (``x_surface``, ``sx``, ...) are properties derived from them. A result pickles; its
``model`` is the :class:`femcam.fe.model.ContactModel` that answered.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from .. import _validate
from .._repr import compact_repr
from .passrange import ShearRange, grid_shear_range
from .recovery import derived

if TYPE_CHECKING:
    from .model import ContactModel


@dataclass(frozen=True)
class StressMax:
    """A stress maximum and where it is.

    Parameters
    ----------
    value : float
        The stress [Pa].
    x, z : float
        Its location in the body's Johnson frame [m] (``z >= 0`` depth).
    body : str
        ``"cam"`` or ``"roller"``.
    """

    value: float
    x: float
    z: float
    body: str


#: (key, field, arg-extremum) of ``ContactResult.max_by_body[body]``: the first three are maxima
#: of non-negative quantities, ``<c>_max`` / ``<c>_min`` the largest / most negative value of
#: component ``<c>``
_EXTREMA = (("von_mises", "von_mises", np.argmax), ("tau1", "tau1", np.argmax),
            ("txz_abs", "txz_abs", np.argmax), ("sx_max", "sx", np.argmax), ("sx_min", "sx", np.argmin),
            ("sz_max", "sz", np.argmax), ("sz_min", "sz", np.argmin), ("sy_max", "sy", np.argmax),
            ("sy_min", "sy", np.argmin))
#: keys of ``ContactResult.max_by_body[body]`` (see ``_EXTREMA``)
MAXIMA_KEYS = tuple(k for k, _, _ in _EXTREMA)


def _over_bodies(key: str) -> property:
    """Read-only ``ContactResult`` attribute: the :class:`StressMax` ``key`` over both bodies
    (the most negative for ``*_min`` keys, else the largest; the cam's on a tie)."""
    pick = min if key.endswith("_min") else max

    def get(self) -> StressMax:
        return pick((m[key] for m in self.max_by_body.values()), key=lambda s: s.value)

    return property(get, doc=f"StressMax of ``{key}`` over both bodies")


def _cam_surface(name: str) -> property:
    """Read-only ``ContactResult`` attribute: field ``name`` of ``surface_by_body["cam"]``."""
    return property(lambda self: getattr(self.surface_by_body["cam"], name),
                    doc=f"cam surface ``{name}`` (``surface_by_body['cam'].{name}``)")


@dataclass(frozen=True, eq=False)
class SurfaceStress:
    """Stresses on the contact surface (z = 0) of one body in its Johnson frame, sorted by x, at
    the vertex and P2 midside nodes of the fine-zone contact curve ``|x| <= fine_half_width * a_ref``.

    Parameters
    ----------
    x : ndarray of float, shape (n,)
        Abscissae [m], increasing.
    sx, sz, txz : ndarray of float, shape (n,)
        In-plane stresses [Pa].
    sy : ndarray of float, shape (n,)
        Out-of-plane stress [Pa].
    body : str
        ``"cam"`` or ``"roller"``.
    """

    x: np.ndarray
    sx: np.ndarray
    sz: np.ndarray
    txz: np.ndarray
    sy: np.ndarray
    body: str

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)



@dataclass(frozen=True, eq=False)
class ContactResult:
    """Solution of one load case (per the model's face width ``length``).

    Attributes
    ----------
    F : float
        Contact force over ``length`` (N).
    rho : float
        Cam radius of curvature passed to the solve (m; inf flat, < 0 concave).
    mu : float
        Friction coefficient (-).
    sliding : int
        +1/-1, direction of the full-sliding traction on the cam (used when ``Q`` is None).
    a, x0 : float
        Fitted Hertz half-width and centre (m) (a Hertz-ellipse fit: near a curvature jump the
        pressure is not an ellipse, use ``p0_nodal``).
    p0 : float
        Fitted peak pressure (Pa).
    p0_nodal : float
        Largest nodal pressure (Pa).
    x, p : ndarray
        Contact vertex abscissae (m) and pressures (Pa).
    gap : ndarray
        Gap after loading at the vertices (m).
    delta : float
        Rigid approach (m).
    force, force_error : float
        Integral of p times length (N) and its relative error against F (-).
    max_by_body : dict
        ``{"cam"|"roller": {key: StressMax}}`` with the keys of :data:`MAXIMA_KEYS` over the
        stress window ``|x| <= fine_half_width * a_ref``, ``z <= eval_depth * a_ref``, and
        ``"txz_range"``: the body's :class:`ShearRange` (``txz_range`` over both bodies is the
        larger of the two: the fatigue check takes the weaker body's limit, and with friction
        or unlike materials the two fields differ); the nine
        over both bodies (``von_mises_max``, ``tau1_max``, ``txz_abs_max``, ``sx_max``,
        ``sx_min``, ``sz_max``, ``sz_min``, ``sy_max``, ``sy_min``; Pa) are properties derived
        from it (e.g. the trailing-edge tension ``sx_max`` ~ 2 mu p0 at x = -a on the cam for
        ``sliding = +1``).
    surface_by_body : dict
        ``{"cam"|"roller": SurfaceStress}`` (Pa, each in its own Johnson frame); ``x_surface``,
        ``sx``, ``sz``, ``txz`` are the cam's (properties).
    iterations, residual, history, active : int, float, tuple, ndarray
        Active-set diagnostics of the normal problem (residual dimensionless).
    converged : bool
        True when the normal (and tangential) active sets settled within tolerance; False with
        the reason in ``message``.
    timings : dict
        Seconds per phase (mesh, assembly, factorisation, condensation, contact, recovery);
        the two bodies are built in two threads, so assembly, factorisation and condensation
        are summed over bodies that ran side by side, and ``bodies_wall`` is their wall time.
    n_dofs : int
        Total degrees of freedom.
    hertz_a, hertz_p0 : float
        Hertz half-width (m) and peak (Pa) of the osculating arcs (nan if Hertz does not apply).
    outside_hertz : bool
        Hertz a / min radius > 0.1.
    q : ndarray
        Tangential traction at the vertices on the cam in +x (Pa): ``sliding mu p`` for full
        sliding, the partial-slip solution when ``Q`` was given.
    Q : float
        Tangential force carried, ``length * w . q`` (N, on the cam in +x).
    slip_state : str
        ``"none"``, ``"stick"``, ``"partial slip"`` or ``"sliding"``.
    stick : ndarray of bool
        Stick nodes (partial slip).
    stick_width : float
        Extent of the stick zone (m).
    creep, shift : float
        Carter creepage (-) when rolling, Cattaneo rigid shift (m) without (nan otherwise).
    message : str
        Why the solve did not converge (empty when it did).
    """

    F: float
    rho: float
    mu: float
    sliding: int
    a: float
    x0: float
    p0: float
    p0_nodal: float
    x: np.ndarray
    p: np.ndarray
    gap: np.ndarray
    delta: float
    force: float
    force_error: float
    max_by_body: dict
    surface_by_body: dict
    iterations: int
    residual: float
    history: tuple
    active: np.ndarray
    converged: bool
    timings: dict
    n_dofs: int
    hertz_a: float
    hertz_p0: float
    outside_hertz: bool
    model: ContactModel = field(repr=False)
    q: np.ndarray | None = None
    Q: float = 0.0
    slip_state: str = "none"
    stick: np.ndarray | None = None
    stick_width: float = 0.0
    creep: float = math.nan
    shift: float = math.nan
    message: str = ""

    # derived from max_by_body / surface_by_body (not stored twice)
    von_mises_max = _over_bodies("von_mises")
    tau1_max = _over_bodies("tau1")
    txz_abs_max = _over_bodies("txz_abs")
    sx_max = _over_bodies("sx_max")
    sx_min = _over_bodies("sx_min")
    sz_max = _over_bodies("sz_max")
    sz_min = _over_bodies("sz_min")
    sy_max = _over_bodies("sy_max")
    sy_min = _over_bodies("sy_min")
    txz_range = _over_bodies("txz_range")
    x_surface = _cam_surface("x")
    sx = _cam_surface("sx")
    sz = _cam_surface("sz")
    txz = _cam_surface("txz")

    def __repr__(self) -> str:
        """Load, p0, a, convergence and size of the solve (a compact line)."""
        return compact_repr(self, [
            f"F {self.F:.6g} N",
            f"rho {self.rho * 1e3:.6g} mm",
            f"mu {self.mu:g}",
            f"p0 {self.p0 * 1e-6:.6g} MPa",
            f"a {self.a * 1e6:.5g} um",
            f"p0 Hertz {self.hertz_p0 * 1e-6:.6g} MPa",
            f"force error {self.force_error:.2e}",
            f"converged {self.converged} in {self.iterations} iterations",
            f"{self.n_dofs} dofs",
            f"slip {self.slip_state}",
        ])

    def __getstate__(self):
        # a pickled result is independent of its model (the factorisation is large and bound
        # to this process): the full-field methods then take the model explicitly
        return {**self.__dict__, "model": None}

    def model_or(self, model=None) -> ContactModel:
        """``model``, else the model that solved this result (None after unpickling: pass it).

        Parameters
        ----------
        model : ContactModel, optional
            The model that solved this result.

        Returns
        -------
        ContactModel
            ``model`` if given, else ``self.model``.

        Raises
        ------
        InputError
            Neither is available (an unpickled result without ``model``).
        """
        m = model if model is not None else self.model
        if m is None:
            raise _validate.fail("model", None, "", "this ContactResult was unpickled without its "
                                 "factorised model; pass the ContactModel that solved it (model=...)")
        return m

    def field_at_nodes(self, body: str = "cam", model=None):
        """Full field at the scalar nodes of ``body`` (one back-solve); see
        :meth:`ContactModel.full_field`.

        Parameters
        ----------
        body : {"cam", "roller"}, optional
            The body.
        model : ContactModel, optional
            The solving model, needed for an unpickled result.

        Returns
        -------
        u : ndarray of float, shape (2, n)
            Nodal displacements ``(u_x, u_y)`` in the FE frame [m].
        fields : dict of str to ndarray
            ``sx, sz, txz, sy, tau1, von_mises`` [Pa], ``xy`` (2, n) [m] and depth ``z`` [m].
        """
        return self.model_or(model).full_field(self, body)

    def stress_at(self, x, z, body: str = "cam", model=None):
        """Stresses at arbitrary points of a body, interpolated from the nodal field.

        Parameters
        ----------
        x : array_like of float
            Abscissae [m].
        z : array_like of float
            Depths below the surface [m], >= 0; broadcast against ``x``.
        body : {"cam", "roller"}, optional
            The body.
        model : ContactModel, optional
            The solving model, needed for an unpickled result.

        Returns
        -------
        tuple of ndarray
            ``(sx, sz, txz, sy, tau1, von_mises)`` [Pa], each of the broadcast shape.
        """
        return self.model_or(model).stress_at(self, x, z, body)


def traction_fields(trac, q, w, x, length) -> dict:
    """ContactResult traction fields from a TractionSolution (or the friction-free/sliding q).

    Parameters
    ----------
    trac : TractionSolution or None
        The partial-slip solution; None for frictionless or full sliding without ``Q``.
    q : ndarray of float, shape (n_c,)
        Tangential traction on the cam in +x [Pa] (used when ``trac`` is None).
    w : ndarray of float, shape (n_c,)
        Trapezoid weights [m].
    x : ndarray of float, shape (n_c,)
        Contact vertex abscissae [m].
    length : float
        Face width [m].

    Returns
    -------
    dict
        ``Q`` [N], ``slip_state`` (str), ``stick`` (bool, shape (n_c,)), ``stick_width`` [m],
        ``creep`` [-] and ``shift`` [m] (nan when not applicable).
    """
    if trac is None:
        state = "sliding" if np.any(q) else "none"
        return {"Q": float(w @ q) * length, "slip_state": state, "stick": np.zeros(x.size, bool),
                "stick_width": 0.0, "creep": math.nan, "shift": math.nan}
    return {"Q": float(w @ trac.q) * length, "slip_state": trac.slip_state, "stick": trac.stick,
            "stick_width": trac.stick_width, "creep": trac.creep, "shift": trac.shift}


def window_extrema(name: str, ev, sx, sz, txz, sy) -> tuple[dict, SurfaceStress]:
    """Stress extrema over the stress window of one body, the range of ``txz`` over one pass
    below its surface, and its surface stresses.

    Parameters
    ----------
    name : str
        Body name, ``"cam"`` or ``"roller"``.
    ev : femcam.fe.recovery.EvalSet
        Its stress window (``ev.x, ev.z`` [m], ``ev.surface`` the surface points, ``ev.pass_*``
        the rows of equal depth).
    sx, sz, txz, sy : ndarray of float, shape (n_eval,)
        Stresses at the window points, Johnson frame [Pa].

    Returns
    -------
    maxima : dict of str to StressMax or ShearRange
        One :class:`StressMax` per key of :data:`MAXIMA_KEYS` and the :class:`ShearRange`
        ``"txz_range"`` [Pa, m] (on the window's rows of equal depth,
        :func:`femcam.fe.passrange.pass_grid`; NaN without them).
    surface : SurfaceStress
        The stresses at the surface points, sorted by x.
    """
    tau1, vm = derived(sx, sz, txz, sy)
    fields = {"von_mises": vm, "tau1": tau1, "txz_abs": np.abs(txz), "sx": sx, "sz": sz, "sy": sy}
    m = {}
    for key, comp, arg in _EXTREMA:
        i = int(arg(fields[comp]))
        m[key] = StressMax(float(fields[comp][i]), float(ev.x[i]), float(ev.z[i]), name)
    k = ev.surface
    if ev.pass_P is None:                                   # no rows of equal depth: not computed
        m["txz_range"] = ShearRange(np.nan, np.nan, np.nan, np.nan, name, False)
    else:
        m["txz_range"] = ShearRange(**grid_shear_range(ev.pass_P @ txz, ev.pass_x, ev.pass_z,
                                                       ev.pass_ok), body=name)
    return m, SurfaceStress(x=ev.x[k], sx=sx[k], sz=sz[k], txz=txz[k], sy=sy[k], body=name)
