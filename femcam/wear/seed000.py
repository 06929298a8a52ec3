r"""Seed 000's wear estimate (Desai et al. 2026), reproduced from first principles.

Seed 000 ranks motion laws by an Archard wear volume whose sliding distance is scaled by the
RMS follower velocity over the rise:

.. math::

    v_{rms} = \sqrt{\frac{1}{\beta}\int_0^\beta v(\theta)^2\,d\theta}, \qquad
    S = h\,\frac{v_{rms}}{v_{rms,SHM}}, \qquad W = \frac{K L S}{H}

Symbols
-------
=========  ==============================================  =========  ========================
symbol     meaning                                         unit       source
=========  ==============================================  =========  ========================
h          follower lift of the rise                       m          seed 000 (10 mm)
beta       cam angle of the rise                           rad        seed 000 (180 deg)
omega      cam speed                                       rad/s      seed 000 (1 rad/s)
u          normalised cam angle theta/beta in [0, 1]       -
v(u)       normalised law velocity ds/du (unit lift)       -          ``MotionLaw.v``
I_v2       \int_0^1 v(u)^2 du                              -          derived here
v_rms      RMS follower velocity, (h omega/beta) sqrt(I)   m/s        seed 000 eq. for v_rms
S          "effective sliding distance"                    m          seed 000 Table 3
K, L, H    wear coefficient (-), load (N), hardness (Pa)   see        seed 000 assumptions
W          Archard wear volume                             m^3        seed 000 wear list
Cj         peak |d^3 s/du^3| of the law                    -          ``MotionLaw.Cj``
=========  ==============================================  =========  ========================

Why ``v_rms = (h omega / beta) sqrt(I_v2)``: with ``theta = beta u`` the follower velocity is
``v = (h omega / beta) L.v(u)``, and ``(1/beta) int_0^beta v^2 dtheta = (h omega/beta)^2 int_0^1
L.v(u)^2 du``.

Closed forms of ``I_v2`` (derived by hand; each is checked against ``scipy.integrate.quad`` on
``law.v`` in ``tests/test_wear_seed000.py``):

* uniform velocity: v = 1, I = 1.
* SHM: v = (pi/2) sin(pi u), I = pi^2/8.
* cycloidal: v = 1 - cos(2 pi u), I = int (1 - 2 cos + cos^2) = 1 + 1/2 = 3/2.
* 3-4-5 polynomial: v = 30 u^2 (1-u)^2, I = 900 B(5,5) = 900 * 4!4!/9! = 10/7.
* 4-5-6-7 polynomial: v = 140 u^3 (1-u)^3, I = 19600 B(7,7) = 19600 * 6!6!/13! = 4900/3003.
* Bezier (Bernstein) laws of degree n with control ordinates c_i: v = n sum_i (c_{i+1}-c_i)
  B_i^{n-1}(u) and int B_i^m B_j^m du = C(m,i) C(m,j) / ((2m+1) C(2m,i+j)).
* modified trapezoid and modified sine (1/8 sine ramps): piecewise, see
  :func:`_modified_trapezoid_I` and :func:`_modified_sine_I`.

By Cauchy-Schwarz, ``int_0^1 v du = 1`` gives ``int_0^1 v^2 du >= 1`` with equality only for
v = 1: uniform velocity *minimises* v_rms for a given lift and duration. Seed 000's ranking
(uniform velocity wears most) therefore cannot follow from its own formula; it follows from
two arithmetic slips (see ``docs/wear.md``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np

from .. import _validate
from ..kinematics import law as make_law
from .archard import archard_volume, dimensional_coefficient

#: Seed 000's printed Table 3 (v_rms in mm/s, ratio to SHM, S in mm) and wear list (W in mm^3).
PAPER_TABLE3 = {
    "uniform_velocity": {"v_rms_mm_s": 3.183, "ratio": 1.433, "S_mm": 14.33, "W_mm3": 3.58e-8},
    "shm": {"v_rms_mm_s": 2.221, "ratio": 1.000, "S_mm": 10.00, "W_mm3": 2.50e-8},
    "cycloidal": {"v_rms_mm_s": 1.952, "ratio": 0.879, "S_mm": 8.79, "W_mm3": 2.20e-8},
}

PAPER_LAWS = ("uniform_velocity", "shm", "cycloidal")

_PRETTY = {
    "uniform_velocity": "Uniform Velocity", "shm": "SHM", "cycloidal": "Cycloidal",
    "poly345": "3-4-5 polynomial", "poly4567": "4-5-6-7 polynomial",
    "modified_sine": "Modified sine", "modified_trapezoid": "Modified trapezoid",
}


# --------------------------------------------------------------------------- closed forms
def _modified_trapezoid_I() -> float:
    r"""int_0^1 v^2 du for the modified trapezoid (sine ramps on 1/8 of the rise each).

    Acceleration on [0, 1/2] (antisymmetric about 1/2, so v is symmetric and I = 2 int_0^1/2):
    ``C sin(4 pi u)`` on [0, 1/8], ``C`` on [1/8, 3/8], ``C cos(4 pi (u - 3/8))`` on [3/8, 1/2].
    Unit lift gives ``C = 1/(1/8 + 1/(4 pi))`` (= 4.888). With ``v1 = C/(4 pi)``,
    ``v2 = v1 + C/4``:

    * [0, 1/8]: v = v1 (1 - cos 4 pi u), int v^2 = v1^2 (3/16 - 1/(2 pi))
    * [1/8, 3/8]: v = v1 + C t, int v^2 = v1^2/4 + v1 C/16 + C^2/192
    * [3/8, 1/2]: v = v2 + v1 sin 4 pi t, int v^2 = v2^2/8 + v2 C/(8 pi^2) + v1^2/16
    """
    pi = math.pi
    C = 1.0 / (1.0 / 8.0 + 1.0 / (4.0 * pi))
    v1 = C / (4.0 * pi)
    v2 = v1 + C / 4.0
    half = (v1**2 * (3.0 / 16.0 - 1.0 / (2.0 * pi))
            + v1**2 / 4.0 + v1 * C / 16.0 + C**2 / 192.0
            + v2**2 / 8.0 + v2 * C / (8.0 * pi**2) + v1**2 / 16.0)
    return 2.0 * half


def _modified_sine_I() -> float:
    r"""int_0^1 v^2 du for the modified sine (sine ramps on 1/8 of the rise each).

    Acceleration on [0, 1/2]: ``C sin(4 pi u)`` on [0, 1/8], ``C sin(pi/3 + 4 pi u/3)`` on
    [1/8, 1/2]. Unit lift gives ``C = 4 pi^2/(pi + 4)`` (= 5.528); ``v1 = C/(4 pi)``,
    ``B = 3 C/(4 pi)``:

    * [0, 1/8]: v = v1 (1 - cos 4 pi u), int v^2 = v1^2 (3/16 - 1/(2 pi))
    * [1/8, 1/2]: v = v1 - B cos(pi/3 + 4 pi u/3), int v^2 = 3 v1^2/8 + 3 v1 B/(2 pi) + 3 B^2/16
    """
    pi = math.pi
    C = 4.0 * pi**2 / (pi + 4.0)
    v1 = C / (4.0 * pi)
    B = 3.0 * C / (4.0 * pi)
    half = v1**2 * (3.0 / 16.0 - 1.0 / (2.0 * pi)) + 3.0 * v1**2 / 8.0 + 3.0 * v1 * B / (2.0 * pi) \
        + 3.0 * B**2 / 16.0
    return 2.0 * half


def bezier_v2_integral(control_points) -> Fraction:
    r"""int_0^1 v(u)^2 du for a Bezier (Bernstein) law with ordinates ``c_0..c_n``.

    .. math:: v = n\sum_{i=0}^{n-1} (c_{i+1}-c_i) B_i^{n-1}(u), \quad
              \int_0^1 B_i^m B_j^m\,du = \frac{\binom{m}{i}\binom{m}{j}}{(2m+1)\binom{2m}{i+j}}

    Exact rational arithmetic when the ordinates are rational (Farin, *Curves and Surfaces
    for CAGD*, product and integral of Bernstein polynomials).

    Parameters
    ----------
    control_points : sequence of float, length n + 1 >= 2
        Normalised Bezier ordinates ``c_0..c_n`` (unit lift) [-].

    Returns
    -------
    fractions.Fraction
        ``int_0^1 v^2 du`` [-] (exact rational; ``float()`` it for a number).

    Raises
    ------
    InputError
        Fewer than 2 ordinates.

    Examples
    --------
    >>> float(bezier_v2_integral([0, 0, 0, 1, 1, 1]))   # = 3-4-5 polynomial, 10/7
    1.4285714285714286
    """
    c = [Fraction(x).limit_denominator(10**12) for x in control_points]
    n = len(c) - 1
    if n < 1:
        raise _validate.fail("control_points", list(control_points), "", "must hold at least 2 ordinates")
    m = n - 1
    d = [n * (c[i + 1] - c[i]) for i in range(n)]
    total = Fraction(0)
    for i in range(n):
        for j in range(n):
            total += d[i] * d[j] * Fraction(math.comb(m, i) * math.comb(m, j),
                                            (2 * m + 1) * math.comb(2 * m, i + j))
    return total


def polynomial_v2_integral(coefficients) -> Fraction:
    r"""int_0^1 v(u)^2 du for ``s = sum c_k u^k``: ``v = sum k c_k u^(k-1)``, so

    .. math:: \int_0^1 v^2\,du = \sum_{i,j\ge1} \frac{i c_i\, j c_j}{i + j - 1}

    Parameters
    ----------
    coefficients : sequence of float
        Coefficients ``c_0, c_1, ...`` of the normalised lift ``s(u) = sum c_k u^k`` [-].

    Returns
    -------
    fractions.Fraction
        ``int_0^1 v^2 du`` [-] (exact rational).

    Examples
    --------
    >>> round(float(polynomial_v2_integral([0, 0, 0, 10, -15, 6])), 12)   # 10/7
    1.428571428571
    """
    c = [Fraction(x).limit_denominator(10**12) for x in coefficients]
    return sum((i * c[i] * j * c[j] / (i + j - 1) for i in range(1, len(c)) for j in range(1, len(c))),
               Fraction(0))


_CLOSED_I = {
    "uniform_velocity": lambda: 1.0,
    "shm": lambda: math.pi**2 / 8.0,
    "cycloidal": lambda: 1.5,
    "poly345": lambda: 10.0 / 7.0,
    "poly4567": lambda: 4900.0 / 3003.0,
    "modified_trapezoid": _modified_trapezoid_I,
    "modified_sine": _modified_sine_I,
}


def _resolve(law_or_name):
    if isinstance(law_or_name, str):
        return make_law(law_or_name)
    return law_or_name


def _control_points(law):
    for attr in ("control_points",):
        cp = getattr(law, attr, None)
        if cp is not None:
            return list(np.asarray(cp, dtype=float))
    return None


def v2_integral_closed(law) -> float:
    """Closed form of ``int_0^1 v(u)^2 du`` for a law (name or ``MotionLaw``); NaN if unknown.

    Parameters
    ----------
    law : str or MotionLaw
        A law name of :func:`femcam.kinematics.law` or a normalised motion law.

    Returns
    -------
    float
        ``int_0^1 v(u)^2 du`` [-]; NaN if no closed form is known.
    """
    law = _resolve(law)
    name = getattr(law, "name", "")
    if name in _CLOSED_I:
        return float(_CLOSED_I[name]())
    cp = _control_points(law)
    if cp is not None:
        return float(bezier_v2_integral(cp))
    coeffs = getattr(law, "coefficients", None)
    if coeffs is not None:
        return float(polynomial_v2_integral(np.asarray(coeffs, dtype=float)))
    return float("nan")


def v2_integral_quad(law) -> float:
    """``int_0^1 v(u)^2 du`` by adaptive quadrature (``scipy.integrate.quad``) on ``law.v``.

    The law's ``breakpoints`` (and 1/8, 3/8, 1/2, 5/8, 7/8) are passed so that piecewise laws
    (modified sine/trapezoid) are integrated piece by piece.

    Parameters
    ----------
    law : str or MotionLaw
        A law name of :func:`femcam.kinematics.law` or a normalised motion law.

    Returns
    -------
    float
        ``int_0^1 v(u)^2 du`` [-].
    """
    from scipy.integrate import quad  # lazy: scipy.integrate ~0.03 s at import; only this check needs it

    law = _resolve(law)

    def f(u):
        return float(np.asarray(law.v(np.asarray(u, dtype=float)))) ** 2

    pts = sorted({0.125, 0.375, 0.5, 0.625, 0.875}
                 | {float(b) for b in getattr(law, "breakpoints", ()) if 0.0 < float(b) < 1.0})
    val, _err = quad(f, 0.0, 1.0, points=pts, limit=200,
                     epsabs=1e-13, epsrel=1e-12)
    return float(val)


def rms_velocity(law, h, beta, omega, *, method: str = "closed") -> float:
    r"""RMS follower velocity over a rise (m/s).

    .. math:: v_{rms} = \frac{h\omega}{\beta}\sqrt{\int_0^1 v(u)^2\,du}

    ``method`` is ``"closed"`` (hand-derived integral; falls back to quadrature for laws
    without one) or ``"quad"``. References: seed 000, RMS velocity equation.

    Parameters
    ----------
    law : str or MotionLaw
        A law name of :func:`femcam.kinematics.law` or a normalised motion law.
    h : float
        Lift of the rise [m].
    beta : float
        Cam angle of the rise [rad].
    omega : float
        Cam speed [rad/s].
    method : {"closed", "quad"}
        How ``int v^2 du`` is evaluated.

    Returns
    -------
    float
        RMS follower velocity over the rise [m/s].
    """
    h = _validate.positive("h", h, "m")
    beta = _validate.positive("beta", beta, "rad")
    omega = _validate.positive("omega", omega, "rad/s")
    _validate.choice("method", method, ("closed", "quad"))
    I = v2_integral_closed(law) if method == "closed" else float("nan")
    if not math.isfinite(I):
        I = v2_integral_quad(law)
    return h * omega / beta * math.sqrt(I)


def junction_continuity(law) -> str:
    """What happens where a rise of this law meets a dwell (v = a = j = 0 there).

    Returns one of ``"velocity jump: infinite acceleration and jerk"``, ``"acceleration jump:
    infinite jerk"``, ``"finite jerk jump"``, ``"jerk continuous"``, judged from the law's end
    values ``v, a, j`` at u = 0 and 1 (tolerance 1e-9).

    Parameters
    ----------
    law : str or MotionLaw
        A law name of :func:`femcam.kinematics.law` or a normalised motion law.

    Returns
    -------
    str
        The verdict (one of the four strings above).
    """
    law = _resolve(law)
    ends = np.array([0.0, 1.0])

    def jump(f):
        return float(np.max(np.abs(np.asarray(f(ends), dtype=float))))

    tol = 1e-9
    if jump(law.v) > tol:
        return "velocity jump: infinite acceleration and jerk"
    if jump(law.a) > tol:
        return "acceleration jump: infinite jerk"
    if jump(law.j) > tol:
        return "finite jerk jump"
    return "jerk continuous"


#: junction verdicts of :func:`junction_continuity` whose jerk is infinite (a step in v or a)
_INFINITE_JERK = ("velocity jump: infinite acceleration and jerk", "acceleration jump: infinite jerk")


@dataclass(frozen=True, kw_only=True)
class Seed000Inputs:
    """Seed 000's inputs in SI: K = 1e-8, L = 500 N, H = 2000 N/mm^2, h = 10 mm, beta = 180 deg,
    omega = 1 rad/s.

    Parameters
    ----------
    K : float
        Dimensionless Archard coefficient [-].
    L : float
        Normal load [N].
    H : float
        Hardness [Pa].
    h : float
        Lift of the rise [m].
    beta : float
        Cam angle of the rise [rad].
    omega : float
        Cam speed [rad/s].
    """

    K: float = 1e-8
    L: float = 500.0
    H: float = 2000e6
    h: float = 0.010
    beta: float = math.pi
    omega: float = 1.0

    def __post_init__(self):
        object.__setattr__(self, "K", _validate.nonnegative("K", self.K, "(dimensionless)"))
        object.__setattr__(self, "L", _validate.nonnegative("L", self.L, "N"))
        object.__setattr__(self, "H", _validate.positive("H", self.H, "Pa"))
        object.__setattr__(self, "h", _validate.positive("h", self.h, "m"))
        object.__setattr__(self, "beta", _validate.positive("beta", self.beta, "rad"))
        object.__setattr__(self, "omega", _validate.positive("omega", self.omega, "rad/s"))


@dataclass(frozen=True)
class Seed000Row:
    """One law of the Table 3 layout, SI units (v in m/s, S in m, W in m^3, jerk in m/s^3).

    Jerk: ``interior_peak_jerk = Cj h omega^3 / beta^3`` is the largest |jerk| *inside* the rise
    (0 < u < 1). ``peak_jerk`` is the largest |jerk| of the rise *placed between two dwells*: it
    is ``inf`` when the junction has a velocity or an acceleration jump (uniform velocity, SHM:
    the jerk there is a Dirac spike, or worse), else equal to ``interior_peak_jerk`` (a finite
    jerk jump at the junction is bounded by the interior peak). ``junction`` says which case.

    Parameters
    ----------
    law : str
        Law name.
    I_closed : float
        Closed-form ``int_0^1 v^2 du`` [-] (NaN if none).
    I_quad : float
        Same integral by quadrature [-].
    v_rms : float
        RMS follower velocity over the rise [m/s].
    ratio : float
        ``v_rms / v_rms,SHM`` [-].
    S : float
        Seed 000's effective sliding distance ``h ratio`` [m].
    W : float
        Archard wear volume ``K L S / H`` [m^3].
    Cj : float
        Peak ``|d^3s/du^3|`` of the normalised law [-].
    interior_peak_jerk : float
        Largest ``|jerk|`` inside the rise [m/s^3].
    peak_jerk : float
        Largest ``|jerk|`` of the rise between two dwells (``inf`` for a step in v or a) [m/s^3].
    junction : str
        Verdict of :func:`junction_continuity`.
    quad_rel_diff : float
        ``|I_quad - I_closed| / I_closed`` [-] (NaN without a closed form).
    """

    law: str
    I_closed: float
    I_quad: float
    v_rms: float
    ratio: float
    S: float
    W: float
    Cj: float
    interior_peak_jerk: float
    peak_jerk: float
    junction: str
    quad_rel_diff: float


@dataclass(frozen=True)
class Seed000Table:
    """Seed 000's Table 3 and wear list recomputed; ``rows`` in the order asked for.

    Parameters
    ----------
    inputs : Seed000Inputs
        The inputs (SI).
    rows : tuple of Seed000Row
        One row per law.
    paper : dict
        Seed 000's printed values (:data:`PAPER_TABLE3`, in mm, mm/s, mm^3).
    """

    inputs: Seed000Inputs
    rows: tuple
    paper: dict = field(default_factory=lambda: dict(PAPER_TABLE3))

    def row(self, law: str) -> Seed000Row:
        """The row of one law.

        Parameters
        ----------
        law : str
            Law name.

        Returns
        -------
        Seed000Row
            The row of ``law``.

        Raises
        ------
        InputError
            ``law`` not in the table.
        """
        for r in self.rows:
            if r.law == law:
                return r
        raise _validate.fail("law", law, "", f"not in the table ({[r.law for r in self.rows]})")


def seed000_table(laws=PAPER_LAWS, inputs: Seed000Inputs | None = None) -> Seed000Table:
    """Recompute seed 000's Table 3 (v_rms, ratio to SHM, S) and its wear list (W) for ``laws``.

    v_rms uses the closed-form integral (quadrature where none exists); the quadrature value
    and the relative difference are kept as a diagnostic. SHM is always the reference of the
    ratio, as in the paper.

    Parameters
    ----------
    laws : sequence of str or MotionLaw
        The laws, one row each (default the three laws of the paper).
    inputs : Seed000Inputs, optional
        The inputs; default seed 000's.

    Returns
    -------
    Seed000Table
        The rows (SI).
    """
    inp = inputs or Seed000Inputs()
    scale = inp.h * inp.omega / inp.beta
    v_shm = scale * math.sqrt(math.pi**2 / 8.0)
    k = dimensional_coefficient(inp.K, inp.H)
    rows = []
    for name in laws:
        law = _resolve(name)
        I_c = v2_integral_closed(law)
        I_q = v2_integral_quad(law)
        I = I_c if math.isfinite(I_c) else I_q
        v_rms = scale * math.sqrt(I)
        ratio = v_rms / v_shm
        S = inp.h * ratio
        Cj = float(getattr(law, "Cj", float("nan")))
        junction = junction_continuity(law)
        interior = Cj * inp.h * inp.omega**3 / inp.beta**3
        rows.append(Seed000Row(
            law=getattr(law, "name", str(name)), I_closed=I_c, I_quad=I_q, v_rms=v_rms,
            ratio=ratio, S=S, W=archard_volume(k, inp.L, S), Cj=Cj,
            interior_peak_jerk=interior,
            peak_jerk=math.inf if junction in _INFINITE_JERK else interior,
            junction=junction,
            quad_rel_diff=abs(I_q - I_c) / I_c if math.isfinite(I_c) else float("nan"),
        ))
    return Seed000Table(inputs=inp, rows=tuple(rows))


def _pct(new, old):
    return 100.0 * (new - old) / old


def format_table3(table: Seed000Table) -> str:
    """Text in the layout of seed 000's Table 3 and wear list (mm, mm/s, mm^3), then the jerk
    table and a paper-vs-femcam comparison for the laws the paper printed.

    Parameters
    ----------
    table : Seed000Table
        The recomputed table.

    Returns
    -------
    str
        Multi-line text.
    """
    inp = table.inputs
    out = [f"Seed 000 recomputed: K = {inp.K:g}, L = {inp.L:g} N, H = {inp.H / 1e6:g} N/mm^2, "
           f"h = {inp.h * 1e3:g} mm, beta = {math.degrees(inp.beta):g} deg, omega = {inp.omega:g} rad/s",
           "",
           f"{'Motion Type':<22}{'V_rms mm/s':>12}{'Ratio to SHM':>14}{'Sliding distance (S) mm':>25}",
           ]
    for r in table.rows:
        out.append(f"{_PRETTY.get(r.law, r.law):<22}{r.v_rms * 1e3:>12.3f}{r.ratio:>14.3f}"
                   f"{r.S * 1e3:>25.2f}")
    out += ["", "Wear volume calculations (W = K L S / H)"]
    for r in table.rows:
        out.append(f"  {_PRETTY.get(r.law, r.law) + ':':<22} W = ({inp.K:g} x {inp.L:g} x "
                   f"{r.S * 1e3:.2f}) / {inp.H / 1e6:g} = {r.W * 1e9:.3e} mm^3")
    out += ["", "Jerk: 'interior' = max |j| inside the rise (Cj h omega^3/beta^3); 'with dwells' = max |j| "
                "of the rise between two dwells (inf: a step in v or a at the junction)",
            f"{'Motion Type':<22}{'int v^2 du':>12}{'quad rel.diff':>15}{'Cj':>9}"
            f"{'interior peak jerk mm/s^3':>27}{'peak jerk with dwells mm/s^3':>30}  junction with a dwell"]
    for r in table.rows:
        out.append(f"{_PRETTY.get(r.law, r.law):<22}{r.I_closed:>12.6f}{r.quad_rel_diff:>15.1e}"
                   f"{r.Cj:>9.3f}{r.interior_peak_jerk * 1e3:>27.4f}{r.peak_jerk * 1e3:>30.4f}"
                   f"  {r.junction}")
    paper_rows = [r for r in table.rows if r.law in table.paper]
    if paper_rows:
        out += ["", "Paper vs femcam (difference = femcam - paper)",
                f"{'Motion Type':<18}{'quantity':<14}{'paper':>11}{'femcam':>11}{'diff':>11}{'diff %':>9}"]
        for r in paper_rows:
            p = table.paper[r.law]
            for q, pv, fv in (("v_rms mm/s", p["v_rms_mm_s"], r.v_rms * 1e3),
                              ("ratio", p["ratio"], r.ratio),
                              ("S mm", p["S_mm"], r.S * 1e3),
                              ("W mm^3", p["W_mm3"], r.W * 1e9)):
                fmt = ".3e" if q.startswith("W") else ".3f"
                out.append(f"{_PRETTY.get(r.law, r.law):<18}{q:<14}{pv:>11{fmt}}{fv:>11{fmt}}"
                           f"{fv - pv:>11{fmt}}{_pct(fv, pv):>8.1f}%")
    return "\n".join(out)


def table_rows_for_csv(table: Seed000Table):
    """(header, rows) with units in the column names, for ``csv.writer``.

    ``peak_jerk_with_dwells_mm_s3`` is written ``inf`` where a junction step makes it infinite
    (``float("inf")`` reads it back).

    Parameters
    ----------
    table : Seed000Table
        The recomputed table.

    Returns
    -------
    header : list of str
        Column names with units (mm, mm/s, mm^3, mm/s^3).
    rows : list of list
        One row of formatted values per law.
    """
    header = ["law", "int_v2_du", "int_v2_du_quad", "v_rms_mm_s", "ratio_to_shm", "S_mm", "W_mm3",
              "Cj", "interior_peak_jerk_mm_s3", "peak_jerk_with_dwells_mm_s3", "junction_with_dwell",
              "paper_v_rms_mm_s", "paper_S_mm", "paper_W_mm3"]
    rows = []
    for r in table.rows:
        p = table.paper.get(r.law, {})
        rows.append([r.law, f"{r.I_closed:.10g}", f"{r.I_quad:.10g}", f"{r.v_rms * 1e3:.6g}",
                     f"{r.ratio:.6g}", f"{r.S * 1e3:.6g}", f"{r.W * 1e9:.6g}", f"{r.Cj:.6g}",
                     f"{r.interior_peak_jerk * 1e3:.6g}", f"{r.peak_jerk * 1e3:.6g}", r.junction,
                     p.get("v_rms_mm_s", ""), p.get("S_mm", ""), p.get("W_mm3", "")])
    return header, rows
