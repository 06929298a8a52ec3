"""Plots of follower-train dynamics: the contact force against cam angle (rigid eq. 11 vs the
elastic trains) and the rpm sweep (peak and least contact force vs speed, jump speed).
They draw what :mod:`femcam.dynamics` computed and never call the solver. matplotlib is
imported inside each function (Agg backend) so that importing this module stays cheap.
"""

from __future__ import annotations

import math

import numpy as np

from ._mpl import pyplot, save


def plot_force(results: dict, path, title: str = ""):
    """Axial contact force (N) vs cam angle (deg): ``results`` maps a label to a
    :class:`~femcam.dynamics.DynamicsResult`; the rigid eq. 11 force of the first result is
    drawn as the reference (dotted: a result's own eq. 11 when its total mass differs);
    free-flight angles are shaded. The lower panel is the displacement error of the last mass
    about its cycle mean (the mean is the static compression of the train).

    Parameters
    ----------
    results : dict of str to femcam.dynamics.DynamicsResult
        Label -> response (forces in N, displacements in m).
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
    fig, (ax, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8.0, 6.5),
                                  gridspec_kw={"height_ratios": [3, 2]})
    first = next(iter(results.values()))
    th = np.degrees(first.theta)
    ax.plot(th, first.Fc_rigid_axial, "k--", lw=1.2, label="rigid (eq. 11)")
    for i, (lab, r) in enumerate(results.items()):
        t = np.degrees(r.theta)
        ax.plot(t, r.Fc_axial, color=f"C{i}", lw=1.1, label=lab)
        if i and r.Fc_rigid_axial.shape == first.Fc_rigid_axial.shape and not np.allclose(
                r.Fc_rigid_axial, first.Fc_rigid_axial):  # another total mass: its own eq. 11
            ax.plot(t, r.Fc_rigid_axial, color=f"C{i}", ls=":", lw=1.0, label=f"{lab}: eq. 11")
        de = r.e[:, -1] - np.mean(r.e[:, -1])
        ax2.plot(t, de * 1e6, color=f"C{i}", lw=1.1, label=lab)
        if r.any_liftoff:
            ax.fill_between(t, 0, 1, where=~r.contact, color=f"C{i}", alpha=0.15,
                            transform=ax.get_xaxis_transform(), label=f"{lab}: free flight")
    ax.set_ylabel("axial contact force Fc (N)")
    ax2.set_ylabel("x - s - mean, last mass (um)")
    ax2.set_xlabel("cam angle theta (deg)")
    for a in (ax, ax2):
        a.grid(True, alpha=0.3)
        a.set_xlim(0, 360)
        a.set_xticks(np.arange(0, 361, 45))
    ax.legend(fontsize=8, loc="best")
    ax.set_title(title or f"Contact force at {first.rpm:g} rpm: rigid vs elastic follower train")
    fig.tight_layout()
    return save(fig, path)


def plot_rpm_sweep(sweep, path, jump=None, title: str = ""):
    """Peak and least axial contact force (N) vs cam speed (rpm) of an
    :class:`~femcam.dynamics.RpmSweep`, with the rigid eq. 11 values dashed and, given a
    :class:`~femcam.dynamics.JumpResult`, the jump speed; speeds without a one-periodic
    answer are marked with x.

    Parameters
    ----------
    sweep : femcam.dynamics.RpmSweep
        The sweep (speeds in rpm, forces in N).
    path : str or os.PathLike
        Output PNG.
    jump : femcam.dynamics.JumpResult, optional
        Jump speed to mark (rpm).
    title : str
        Figure title ("": a default).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8.0, 4.8))
    rpm = sweep.rpm
    ok = sweep.converged
    ax.plot(rpm[ok], sweep.Fc_max[ok], "C3.-", ms=3, lw=1.1, label="peak Fc (train)")
    ax.plot(rpm[ok], sweep.Fc_min[ok], "C0.-", ms=3, lw=1.1, label="least Fc (train)")
    ax.plot(rpm, sweep.Fc_rigid_max, "C3--", lw=0.9, label="peak Fc (rigid eq. 11)")
    ax.plot(rpm, sweep.Fc_rigid_min, "C0--", lw=0.9, label="least Fc (rigid eq. 11)")
    bad = ~ok & np.isfinite(sweep.Fc_max)
    if np.any(bad):
        ax.plot(rpm[bad], sweep.Fc_max[bad], "kx", ms=5,
                label="no stable one-periodic motion (peak of the last cycle)")
    ax.axhline(0.0, color="k", lw=0.6)
    if jump is not None and math.isfinite(jump.rpm_jump):
        ax.axvline(jump.rpm_jump, color="C2", lw=1.2, label=f"jump speed {jump.rpm_jump:.0f} rpm")
    if jump is not None and math.isfinite(jump.rpm_rigid):
        ax.axvline(jump.rpm_rigid, color="C2", ls=":", lw=1.2,
                   label=f"rigid lift-off {jump.rpm_rigid:.0f} rpm")
    ax.set_xlabel("cam speed (rpm)")
    ax.set_ylabel("axial contact force Fc (N)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    ax.set_title(title or "Contact force vs speed: peak, least, jump")
    fig.tight_layout()
    return save(fig, path)
