"""Plots of the analytic chain against cam angle (degrees): SVAJ, pressure angle, radius of
curvature, contact force, and the cam shape. matplotlib is imported inside each function
(Agg backend), so importing this module is cheap and headless.

Every function takes a :class:`femcam.scene.SceneState` (``st``) and a PNG path and returns
the path. Labels carry units: mm, m/s, m/s^2, m/s^3, deg, N. :func:`plot_laws` (the
normalised motion laws, ``docs/img/kinematics_laws.png``) needs no scene.

Each function documents its parameters and return value (numpydoc, with units).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..kinematics import law
from ._mpl import legend_outside, pyplot, save


def _deg(st):
    return np.degrees(np.asarray(st.theta, float))


def _finish(fig, ax, th, ylabel: str, title: str, path):
    """Label the cam-angle axis and ``ylabel``, title, lay out and save; returns the path."""
    ax.set_ylabel(ylabel)
    ax.set_xlabel("cam angle theta (deg)")
    ax.set_title(title)
    _xaxis(ax, th)
    fig.tight_layout()
    return save(fig, path)


def _xaxis(ax, th):
    ax.set_xlim(th.min(), th.max())
    if th.max() - th.min() >= 180:
        ax.set_xticks(np.arange(math.floor(th.min() / 45) * 45, th.max() + 1, 45))
    ax.grid(True, alpha=0.3)


def plot_svaj(st, path, title: str = ""):
    """Four stacked panels: lift s (mm), velocity v (m/s), acceleration a (m/s^2), jerk j (m/s^3).

    Parameters
    ----------
    st : femcam.scene.SceneState
        The analytic chain (SI, rad).
    path : str or os.PathLike
        Output PNG.
    title : str
        Figure title ("": a default).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    th = _deg(st)
    fig, axs = plt.subplots(4, 1, sharex=True, figsize=(7.0, 8.0))
    data = [(np.asarray(st.s) * 1e3, "s (mm)"), (st.v, "v (m/s)"), (st.a, "a (m/s$^2$)"),
            (st.j, "j (m/s$^3$)")]
    for ax, (y, lab), c in zip(axs, data, ("C0", "C1", "C2", "C3"), strict=True):
        ax.plot(th, y, color=c, lw=1.4)
        ax.axhline(0.0, color="k", lw=0.5)
        ax.set_ylabel(lab)
        _xaxis(ax, th)
    axs[-1].set_xlabel("cam angle theta (deg)")
    axs[0].set_title(title or "Follower displacement, velocity, acceleration and jerk")
    fig.tight_layout()
    return save(fig, path)


def plot_pressure_angle(st, path, title: str = "", limit_deg: float = 30.0):
    """Pressure angle phi (deg) with the +-limit lines (30 deg by default).

    Parameters
    ----------
    st : femcam.scene.SceneState
        The analytic chain (SI, rad).
    path : str or os.PathLike
        Output PNG.
    title : str
        Figure title ("": a default naming the maximum).
    limit_deg : float
        Pressure-angle limit drawn as +- lines (deg).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    th = _deg(st)
    fig, ax = plt.subplots(figsize=(7.0, 3.4))
    ax.plot(th, np.degrees(st.phi), lw=1.4)
    for sgn in (1, -1):
        ax.axhline(sgn * limit_deg, color="r", ls="--", lw=0.8)
    ax.text(th.min(), limit_deg, f" limit {limit_deg:g} deg", color="r", va="bottom", fontsize=8)
    pm = float(np.max(np.abs(np.degrees(st.phi)))) if np.size(st.phi) else 0.0
    return _finish(fig, ax, th, "pressure angle phi (deg)",
                   title or f"Pressure angle (max |phi| = {pm:.2f} deg)", path)


#: rho plots clip |rho| at this multiple of the median convex |rho| (every rho plot: this
#: module's and the sweep's svaj_loads.png, through :func:`rho_clip_mm`)
RHO_CLIP_FACTOR = 4.0


def rho_clip_mm(rho_mm) -> float:
    """The clip value (mm) of every rho plot: :data:`RHO_CLIP_FACTOR` x the median convex
    radius (100 mm when no part is convex). Near an inflection |rho| grows without bound.

    Parameters
    ----------
    rho_mm : array_like
        Radius of curvature (mm, signed; inf where flat).

    Returns
    -------
    float
        The clip value (mm).
    """
    rho_mm = np.asarray(rho_mm, float)
    pos = rho_mm[np.isfinite(rho_mm) & (rho_mm > 0)]
    return RHO_CLIP_FACTOR * float(np.median(pos)) if pos.size else 100.0


def plot_rho(st, path, title: str = "", Rr: float = 0.0, clip_mm: float | None = None):
    """Cam-surface radius of curvature rho (mm); concave parts are negative. Values beyond
    ``clip_mm`` (default :func:`rho_clip_mm`) are clipped; the legend states the value.

    Parameters
    ----------
    st : femcam.scene.SceneState
        The analytic chain (SI, rad).
    path : str or os.PathLike
        Output PNG.
    title : str
        Figure title ("": a default naming the maximum).
    Rr : float
        Roller radius drawn as a line (m; 0: none).
    clip_mm : float, optional
        Clip value (mm; default :func:`rho_clip_mm`).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    th = _deg(st)
    rho = np.asarray(st.rho, float) * 1e3
    fin = np.isfinite(rho)
    if clip_mm is None:
        clip_mm = rho_clip_mm(rho)
    shown = np.clip(np.where(fin, rho, np.sign(rho) * np.inf), -clip_mm, clip_mm)
    fig, ax = plt.subplots(figsize=(8.4, 3.4))
    ax.plot(th, shown, lw=1.4, label="rho (cam surface)")
    if np.any(np.abs(rho) > clip_mm):
        ax.axhline(clip_mm, color="0.6", lw=0.6, ls=":",
                   label=f"|rho| > {clip_mm:.3g} mm clipped\n(nearly flat; {RHO_CLIP_FACTOR:g} x median rho)")
        ax.axhline(-clip_mm, color="0.6", lw=0.6, ls=":")
    if Rr > 0:
        ax.axhline(Rr * 1e3, color="C3", ls="--", lw=0.8, label=f"roller radius {Rr * 1e3:g} mm")
    ax.axhline(0.0, color="k", lw=0.5)
    fmin = float(np.min(np.abs(rho[fin]))) if fin.any() else math.inf
    ax.set_ylabel("radius of curvature rho (mm)")
    ax.set_xlabel("cam angle theta (deg)")
    ax.set_title(title or f"Cam radius of curvature at the contact (min |rho| = {fmin:.2f} mm)")
    legend_outside(ax)
    _xaxis(ax, th)
    fig.tight_layout()
    return save(fig, path)


def plot_contact_force(st, path, title: str = ""):
    """Contact force Fc (N, seed 002 eq. 11) with lift-off (Fc <= 0) shaded.

    Parameters
    ----------
    st : femcam.scene.SceneState
        The analytic chain (SI, rad).
    path : str or os.PathLike
        Output PNG.
    title : str
        Figure title ("": a default naming the maximum).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    th = _deg(st)
    fig, ax = plt.subplots(figsize=(7.0, 3.4))
    ax.plot(th, st.Fc, lw=1.4, color="C2")
    ax.axhline(0.0, color="k", lw=0.5)
    lift = np.asarray(st.liftoff, bool)
    if lift.any():
        ax.fill_between(th, 0, 1, where=lift, transform=ax.get_xaxis_transform(), color="r",
                        alpha=0.15, label="lift-off (Fc <= 0)")
        legend_outside(ax)
    return _finish(fig, ax, th, "contact force Fc (N)",
                   title or f"Contact force (max {np.max(st.Fc):.1f} N, min {np.min(st.Fc):.1f} N)",
                   path)


def plot_cam(st, path, title: str = ""):
    """Cam shape (cam frame, mm) with the pitch curve, base circle and undercut points.

    Parameters
    ----------
    st : femcam.scene.SceneState
        The analytic chain (SI, rad).
    path : str or os.PathLike
        Output PNG.
    title : str
        Figure title ("": names the follower kind).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    p = st.profile
    fig, ax = plt.subplots(figsize=(6.6, 5.0))
    ax.plot(np.r_[p.x, p.x[:1]] * 1e3, np.r_[p.y, p.y[:1]] * 1e3, lw=1.6, label="cam surface")
    if p.follower.translating_roller:
        ax.plot(p.pitch_x * 1e3, p.pitch_y * 1e3, "--", lw=0.8, label="pitch curve")
    t = np.linspace(0, 2 * np.pi, 361)
    Rb = p.follower.Rb * 1e3
    ax.plot(Rb * np.cos(t), Rb * np.sin(t), ":", color="0.5", lw=0.8, label="base circle")
    if p.undercut.any():
        ax.plot(p.x[p.undercut] * 1e3, p.y[p.undercut] * 1e3, "r.", ms=3, label="undercut")
    ax.plot(0, 0, "k+")
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title(title or f"Cam profile ({p.follower.kind})")
    legend_outside(ax)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    return save(fig, path)


def plot_all(st, outdir, prefix: str = "", *, Rr: float = 0.0, limit_deg: float = 30.0,
             title: str = "") -> list[Path]:
    """All analytic plots into ``outdir`` as ``[<prefix>_]{svaj,phi,rho,fc,cam}.png``.

    Parameters
    ----------
    st : femcam.scene.SceneState
        The analytic chain (SI, rad).
    outdir : str or os.PathLike
        Output directory (must exist).
    prefix : str
        File-name prefix (``<prefix>_svaj.png``; "": none).
    Rr : float
        Roller radius drawn on the rho plot (m; 0: none).
    limit_deg : float
        Pressure-angle limit (deg).
    title : str
        Prefix of the SVAJ title ("": defaults).

    Returns
    -------
    list of pathlib.Path
        The five PNGs.
    """
    outdir = Path(outdir)
    name = (lambda k: outdir / (f"{prefix}_{k}.png" if prefix else f"{k}.png"))  # noqa: E731
    pre = f"{title}: " if title else ""
    return [
        plot_svaj(st, name("svaj"), title=f"{pre}s, v, a, j" if title else ""),
        plot_pressure_angle(st, name("phi"), limit_deg=limit_deg),
        plot_rho(st, name("rho"), Rr=Rr),
        plot_contact_force(st, name("fc")),
        plot_cam(st, name("cam")),
    ]


#: the laws drawn by :func:`plot_laws` (the figure docs/img/kinematics_laws.png)
LAWS_FIGURE = ("shm", "cycloidal", "poly345", "poly4567", "modified_sine", "modified_trapezoid",
               "bezier9")


def plot_laws(path, names=LAWS_FIGURE, n: int = 401, title: str = ""):
    """Normalised motion laws (unit lift) against u = theta/beta: four panels s, v = ds/du,
    a = d2s/du2 and j = d3s/du3 (dimensionless), one curve per law in ``names``.

    This draws ``docs/img/kinematics_laws.png``::

        python -c "from femcam.viz.analytic import plot_laws; plot_laws('docs/img/kinematics_laws.png')"

    Parameters
    ----------
    path : str or os.PathLike
        Output PNG.
    names : sequence of str
        Motion-law names (:data:`femcam.kinematics.LAW_NAMES`).
    n : int
        Points per curve over u in [0, 1].
    title : str
        Figure title ("": a default).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    u = np.linspace(0.0, 1.0, n)
    fig, axs = plt.subplots(2, 2, sharex=True, figsize=(8.0, 4.2))
    panels = [("s", "s (lift / h)"), ("v", "v = ds/du"), ("a", "a = d\u00b2s/du\u00b2"),
              ("j", "j = d\u00b3s/du\u00b3")]
    for name in names:
        L = law(name)
        for ax, (k, _) in zip(axs.flat, panels, strict=True):
            ax.plot(u, getattr(L, k)(u), lw=1.0, label=name)
    for ax, (_, lab) in zip(axs.flat, panels, strict=True):
        ax.set_ylabel(lab)
        ax.grid(True, alpha=0.3)
    for ax in axs[-1]:
        ax.set_xlabel("u = \u03b8/\u03b2 (-)")
    fig.legend(*axs[0, 0].get_legend_handles_labels(), loc="center right", fontsize=7, frameon=False)
    fig.suptitle(title or "femcam normalised motion laws (unit lift)", fontsize=10)
    fig.tight_layout(rect=(0.0, 0.0, 0.78, 1.0))  # the legend, beside the panels, in the rest
    return save(fig, path)
