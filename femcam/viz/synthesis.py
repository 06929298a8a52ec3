"""Plots of the seed-003 synthesis: cam curve, error/pressure angle, parameter studies.

matplotlib is imported inside each function (Agg, headless). Lengths are plotted in mm and
angles in degrees, with the unit in every label.

Each function documents its parameters and return value (numpydoc, with units).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ._mpl import pyplot, save


def plot_curve(result, path, *, direct_r=None) -> Path:
    """Cam curve (FE nodes and interpolated curve), base circle, optional direct profile.

    Parameters
    ----------
    result : femcam.synthesis.SynthesisResult
        The FE curve (m, rad).
    path : str or os.PathLike
        Output PNG.
    direct_r : array_like, optional
        Direct-profile radius at ``result.theta`` (m).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(4.6, 4.6), dpi=90)
    t = np.linspace(0, 2 * np.pi, 400)
    Rb = result.Rb * 1e3
    ax.plot(Rb * np.cos(t), Rb * np.sin(t), "k:", lw=0.8, label="base circle")
    ax.plot(np.append(result.x, result.x[0]) * 1e3, np.append(result.y, result.y[0]) * 1e3, "C0-",
            lw=1.2, label="FE cam curve")
    ax.plot(result.nodes[:, 0] * 1e3, result.nodes[:, 1] * 1e3, "C0.", ms=2)
    if direct_r is not None:
        ax.plot(direct_r * np.cos(result.theta) * 1e3, direct_r * np.sin(result.theta) * 1e3, "C1--",
                lw=0.8, label="direct r = Rb + s")
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title(f"knife-edge cam, Rb = {Rb:g} mm, {result.options.n_elements} elements")
    ax.legend(fontsize=7, loc="lower left")
    return save(fig, path, dpi=90, tight=True)  # the figure's own 90 dpi


def plot_error_phi(result, path) -> Path:
    """Transfer-function error and pressure angle (FE vs exact) against cam angle.

    Parameters
    ----------
    result : femcam.synthesis.SynthesisResult
        The FE curve (error in m, angles in rad).
    path : str or os.PathLike
        Output PNG.

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(6.0, 4.6), dpi=90, sharex=True)
    th = np.degrees(result.theta)
    a1.plot(th, result.error * 1e3, "C0-", lw=0.8)
    a1.set_ylabel("y - y_o (mm)")
    a1.set_title(f"max |error| = {result.max_error * 1e3:.3e} mm")
    a2.plot(th, np.degrees(result.phi), "C0-", lw=1.2, label="FE curve")
    a2.plot(th, np.degrees(result.phi_exact), "C1--", lw=0.8, label="exact atan(s'/(Rb+s))")
    a2.axhline(30, color="k", lw=0.5, ls=":")
    a2.axhline(-30, color="k", lw=0.5, ls=":")
    a2.set_ylabel("pressure angle phi (deg)")
    a2.set_xlabel("cam angle theta (deg)")
    a2.legend(fontsize=7)
    return save(fig, path, dpi=90, tight=True)  # the figure's own 90 dpi


def plot_study(rows, path, *, x: str = "k") -> Path:
    """Error and phi_max against k or k/mu (seed 003 Figs. 6-9), log x axis.

    Parameters
    ----------
    rows : sequence of femcam.synthesis.StudyRow
        The study (errors in m, angles in rad).
    path : str or os.PathLike
        Output PNG.
    x : str
        ``"k"``: k on the log x axis; anything else: k/mu (-).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    ok = [r for r in rows if r.converged]
    xs = np.array([r.k if x == "k" else r.k_over_mu for r in ok])
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.5, 3.0), dpi=90)
    a1.loglog(xs, [r.max_error * 1e3 for r in ok], "o-", ms=3)
    a1.set_xlabel("k (-)" if x == "k" else "k/mu (-)")
    a1.set_ylabel("max |y - y_o| (mm)")
    a2.semilogx(xs, [math.degrees(r.phi_max) for r in ok], "o-", ms=3)
    a2.set_xlabel("k (-)" if x == "k" else "k/mu (-)")
    a2.set_ylabel("max pressure angle (deg)")
    return save(fig, path, dpi=90, tight=True)  # the figure's own 90 dpi
