"""PNG plots of a sweep (matplotlib, Agg; imported lazily).

* ``p0_vs_angle.png``       -- peak pressure against cam angle: Hertz (line) and FE (points);
* ``surface_stress_worst.png`` -- surface sx, sz, txz along x at the worst angle, FE points and
  Hertz lines (as seed 002 Figs. 3-5);
* ``maxima_vs_angle.png``   -- von Mises and tau1 maxima against cam angle (FE points, Hertz lines);
* ``svaj_loads.png``        -- s, v, a, j and phi, rho, Fc against cam angle;
* ``wear_vs_angle.png``     -- Archard wear depth per revolution at the contact point and the
  sliding speed against cam angle (the sweep's ``wear_depth`` and ``v_slip`` columns).

The plots draw what the sweep computed: the table, ``SweepResult.hertz_factors`` (Hertz maxima
in units of p0) and ``SweepResult.surface_profile`` (the worst angle's surface stresses,
:func:`femcam.sweep.profile.worst_surface_profile`); nothing here solves anything.

Units on the axes: degrees, mm, MPa, N, um.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ._mpl import legend_outside, pyplot, save
from .analytic import rho_clip_mm


def _table(result):
    """``(pyplot, table, cam angle in degrees)`` of a sweep result."""
    t = result.table
    return pyplot(), t, np.degrees(t["theta"])


def _save(fig, path) -> str:
    """Lay out, write (90 dpi) and close ``fig``; the path as str."""
    return str(save(fig, path, dpi=90, tight=True))


def plot_p0(result, path) -> str:
    """Peak pressure against cam angle: Hertz (line), FE (points) and FE/Hertz - 1.

    Parameters
    ----------
    result : femcam.sweep.SweepResult
        The sweep (its ``table``, SI).
    path : str or os.PathLike
        Output PNG.

    Returns
    -------
    str
        The path written.
    """
    plt, t, deg = _table(result)
    fe = result.method != "hertz"
    fig, axs = plt.subplots(2 if fe else 1, 1, figsize=(7, 5 if fe else 3.4), sharex=True,
                            squeeze=False, gridspec_kw={"height_ratios": [2.2, 1] if fe else [1]})
    ax = axs[0, 0]
    ax.plot(deg, t["p0_hertz"] / 1e6, "-", color="C0", label="Hertz (Johnson eq. 4.45)")
    if fe:
        ax.plot(deg, t["p0_fe"] / 1e6, ".", color="C3", ms=3, label="FE (peak of the solved pressure)")
        axs[1, 0].plot(deg, 100 * t["err_p0"], "-", color="C3", lw=1)
        axs[1, 0].axhline(0, color="0.5", lw=0.5)
        axs[1, 0].set_ylabel("FE/Hertz - 1 (%)")
        axs[1, 0].grid(alpha=0.3)
    lo = t["status"] == "liftoff"
    if np.any(lo):
        ax.plot(deg[lo], np.zeros(lo.sum()), "x", color="k", ms=3, label="lift-off")
    axs[-1, 0].set_xlabel("cam angle theta (deg)")
    ax.set_ylabel("peak pressure p0 (MPa)")
    legend_outside(ax)
    ax.grid(alpha=0.3)
    ax.set_title("Peak contact pressure over the cam cycle")
    return _save(fig, path)


def plot_maxima(result, path) -> str:
    """Von Mises and tau1 maxima (MPa) against cam angle: FE points, Hertz lines (when
    ``result.hertz_factors`` is set).

    Parameters
    ----------
    result : femcam.sweep.SweepResult
        The sweep (its ``table``, SI). Needs ``hertz_factors`` for the Hertz lines.
    path : str or os.PathLike
        Output PNG.

    Returns
    -------
    str
        The path written.
    """
    plt, t, deg = _table(result)
    fig, ax = plt.subplots(figsize=(7, 3.6))
    k = result.hertz_factors
    if result.method != "hertz":
        ax.plot(deg, t["vm_max"] / 1e6, ".", ms=3, color="C3", label="von Mises max (FE)")
        ax.plot(deg, t["tau1_max"] / 1e6, ".", ms=3, color="C2", label="tau1 max (FE)")
    if k is not None:
        ax.plot(deg, k["von_mises"][0] * t["p0_hertz"] / 1e6, "-", color="C3", lw=1,
                label="von Mises max (Hertz)")
        ax.plot(deg, k["tau1"][0] * t["p0_hertz"] / 1e6, "-", color="C2", lw=1,
                label="tau1 max (Hertz)")
    ax.set_xlabel("cam angle theta (deg)")
    ax.set_ylabel("stress (MPa)")
    legend_outside(ax)
    ax.set_title("Subsurface stress maxima over the cam cycle")
    return _save(fig, path)


def plot_svaj_loads(result, path) -> str:
    """s, v, a, j, phi, rho, Fc and Hertz p0 against cam angle.

    Parameters
    ----------
    result : femcam.sweep.SweepResult
        The sweep (its ``table``, SI).
    path : str or os.PathLike
        Output PNG.

    Returns
    -------
    str
        The path written.
    """
    plt, t, deg = _table(result)
    fig, axs = plt.subplots(4, 2, figsize=(9, 7.5), sharex=True)
    panels = [("s", 1e3, "s (mm)"), ("v", 1, "v (m/s)"), ("a", 1, "a (m/s^2)"),
              ("j", 1, "j (m/s^3)"), ("phi", 180 / np.pi, "phi (deg)"),
              ("rho", 1e3, "rho (mm)"), ("Fc", 1, "Fc (N)"), ("p0_hertz", 1e-6, "p0 Hertz (MPa)")]
    for ax, (name, f, label) in zip(axs.T.ravel(), panels, strict=True):
        y = t[name] * f
        if name == "rho":
            clip = rho_clip_mm(y)  # the one clip rule of every rho plot (femcam.viz.analytic)
            y = np.clip(y, -clip, clip)
            label += f", clipped to +-{clip:.0f}"
        ax.plot(deg, y, "-", lw=1)
        ax.set_ylabel(label, fontsize=8)
        ax.grid(alpha=0.3)
    for ax in axs[-1]:
        ax.set_xlabel("cam angle theta (deg)")
    fig.suptitle("Kinematics (SVAJ), geometry and load over the cam cycle")
    return _save(fig, path)


def plot_wear(result, path) -> str:
    """Archard wear depth per revolution (nm) and sliding speed (m/s) against cam angle.

    Parameters
    ----------
    result : femcam.sweep.SweepResult
        The sweep (its ``table``, SI). Needs the wear columns.
    path : str or os.PathLike
        Output PNG.

    Returns
    -------
    str
        The path written.
    """
    plt, t, deg = _table(result)
    fig, axs = plt.subplots(2, 1, figsize=(7, 4.6), sharex=True)
    src = np.asarray(t["wear_source"]).astype(str)
    known = {"fe": ("C3", "FE pressure"), "hertz": ("C0", "Hertz pressure"),
             "axial_peak": ("C2", "finite-length axial peak pressure")}
    for j, s_ in enumerate(sorted({x for x in src if x}, key=lambda x: (x not in known, x))):
        c, lab = known.get(s_, (f"C{4 + j}", f"{s_.replace('_', ' ')} pressure"))
        m = src == s_
        axs[0].plot(deg[m], t["wear_depth"][m] * 1e9, ".", ms=3, color=c, label=lab)
    k = result.provenance.get("wear", {}).get("k_m3_per_N_m")
    axs[0].set_ylabel("wear depth per rev (nm)")
    axs[0].ticklabel_format(axis="y", style="plain", useOffset=False)  # nm, no 1e-5 multiplier
    axs[0].set_title("Archard wear at the contact point" + (f" (k = {k:.3g} m^3/(N m))" if k else ""))
    legend_outside(axs[0])
    axs[0].grid(alpha=0.3)
    axs[1].plot(deg, t["v_slip"], "-", lw=1, label="sliding speed at the contact")
    axs[1].set_ylabel("sliding speed (m/s)")
    legend_outside(axs[1])
    axs[1].set_xlabel("cam angle theta (deg)")
    axs[1].grid(alpha=0.3)
    return _save(fig, path)


def plot_surface_worst(profile: dict, path) -> str:
    """Surface stresses along x at the worst angle.

    Parameters
    ----------
    profile : dict
        :func:`femcam.sweep.profile.worst_surface_profile` (``SweepResult.surface_profile``).
    path : str or Path
        Output PNG.

    Returns
    -------
    str
        The path written.
    """
    plt = pyplot()
    fig, axs = plt.subplots(1, 3, figsize=(11, 3.4), sharex=True)
    a = profile["a_hertz"]
    for ax, name, label in zip(axs, ("sx", "sz", "txz"),
                               ("sigma_x (MPa)", "sigma_z (MPa)", "tau_xz (MPa)"), strict=True):
        ax.plot(profile["x_hertz"] / a, profile[name + "_hertz"] / 1e6, "-", color="C0",
                label=profile.get("hertz_label", "Hertz, seed 002 eqs. 5-7"))
        if "x_fe" in profile:
            ax.plot(profile["x_fe"] / a, profile[name + "_fe"] / 1e6, ".", color="C3", ms=4,
                    label="FE")
        ax.set_xlabel("x / a_Hertz")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    legend_outside(axs[0])
    fig.suptitle(f"Surface stresses at the worst angle theta = {profile['theta_deg']:.1f} deg "
                 f"(Fc = {profile['Fc']:.0f} N, mu = {profile['mu']:g}"
                 + (f", {profile['traction']})" if "traction" in profile else ")"))
    return _save(fig, path)


def _jump_clusters(deg):
    """Row groups of the flagged angles ``deg`` (deg), one per curvature jump (gaps > 1 deg
    separate them; a jump at 0 deg joins its rows near 360 deg, shifted by -360)."""
    order = np.argsort(deg)
    x = deg[order]
    cuts = np.flatnonzero(np.diff(x) > 1.0) + 1
    groups = [(order[g], x[g]) for g in np.split(np.arange(x.size), cuts)]
    if len(groups) > 1 and groups[0][1][0] < 1.0 and groups[-1][1][-1] > 359.0:
        last = groups.pop()
        groups[0] = (np.concatenate([last[0], groups[0][0]]), np.concatenate([last[1] - 360.0, groups[0][1]]))
    return groups


def plot_junction_p0(result, path, reference=None) -> str:
    """Peak pressure across each curvature jump of a sweep (rows ``curvature_jump``, one panel
    per jump): Hertz (osculating arcs, jumps), the FE with the osculating-arc gap and with the
    exact gap (largest nodal pressure; the arc FE's p0 from ``exact_vs_arc_p0``), optionally a
    reference.

    Parameters
    ----------
    result : femcam.sweep.SweepResult
        The sweep (its ``table``, SI). Rows flagged ``curvature_jump``.
    path : str or os.PathLike
        Output PNG.
    reference : (array_like, array_like), optional
        ``(theta_deg, p0_Pa)``, e.g. an independent half-space solve (deg, Pa).

    Returns
    -------
    str
        The path written.
    """
    plt, t, deg = _table(result)
    j = np.flatnonzero((t["curvature_jump"] == 1) & (t["status"] == "ok"))
    groups = _jump_clusters(deg[j])[:4]
    fig, axs = plt.subplots(1, len(groups), figsize=(3.2 * len(groups) + 1.5, 3.8), squeeze=False)
    for ax, (rows, x) in zip(axs[0], groups, strict=True):
        i = j[rows]
        ex = t["p0_fe"][i]
        ax.plot(x, t["p0_hertz"][i] / 1e6, "-", color="C0", label="Hertz (osculating arcs)")
        ax.plot(x, ex * (1.0 + t["exact_vs_arc_p0"][i]) / 1e6, "s", ms=3, color="C1", label="FE, arc gap")
        ax.plot(x, ex / 1e6, "o-", ms=3, lw=1, color="C3", label="FE, exact gap (sweep)")
        if reference is not None:
            rd = np.asarray(reference[0])
            k = (rd >= x.min() - 1e-9) & (rd <= x.max() + 1e-9)
            ax.plot(rd[k], np.asarray(reference[1])[k] / 1e6, "k+", ms=8,
                    label="half-space reference, exact gap")
        ax.set_xlabel("cam angle theta (deg)")
        ax.grid(alpha=0.3)
    axs[0, 0].set_ylabel("peak pressure (MPa)")
    axs[0, 0].legend(loc="best", fontsize=7)
    fig.suptitle("Peak pressure across the curvature jumps")
    return _save(fig, path)


#: caption of each plot the sweep writes (``plots/<file>``); ``extras_<provider>.png`` get theirs
#: from the provider's name
PLOT_CAPTIONS = {
    "p0_vs_angle.png": "Peak contact pressure p0 over the cam cycle: Hertz and, where it answered, FE.",
    "maxima_vs_angle.png": "Subsurface stress maxima (von Mises, tau1) over the cam cycle.",
    "svaj_loads.png": "Follower motion (s, v, a, j), radius of curvature, contact force and "
                      "pressure angle over the cam cycle.",
    "wear_vs_angle.png": "Archard wear depth per revolution at the contact point, and the sliding speed.",
    "surface_stress_worst.png": "Surface stresses of the cam at the worst angle (largest p0).",
    "p0_curvature_jumps.png": "Peak pressure across the curvature jumps: Hertz, arc-gap FE and "
                              "exact-gap FE.",
}


def plot_caption(name: str) -> str:
    """The caption of a sweep plot, for the reports.

    Parameters
    ----------
    name : str
        The plot's file name in ``DIR/plots`` (``p0_vs_angle.png``, ``extras_<provider>.png``).

    Returns
    -------
    str
        One sentence saying what the plot shows (the file name for an unknown plot).
    """
    if name in PLOT_CAPTIONS:
        return PLOT_CAPTIONS[name]
    if name.startswith("extras_") and name.endswith(".png"):
        return f"The {name[7:-4]} columns over the cam cycle (extra column provider)."
    return name


def plot_sweep(result, out) -> dict[str, str]:
    """All sweep plots into ``out/plots``.

    Parameters
    ----------
    result : femcam.sweep.SweepResult
        With ``hertz_factors`` and ``surface_profile`` for the Hertz lines and the worst-angle
        plot (``sweep(scene, SweepOptions(plots=True), RunOptions(out=...))`` computes them).
    out : str or Path
        Output directory.

    Returns
    -------
    dict[str, str]
        ``{name: path}`` of the PNGs written.
    """
    paths = {}
    for function, args in sweep_plot_calls(result, out):
        paths.update(function(*args))
    return paths


def sweep_plot_calls(result, out) -> list[tuple]:
    """The calls :func:`plot_sweep` makes, one per plot, for a caller that draws them elsewhere
    (:mod:`femcam.viz.process`).

    Parameters
    ----------
    result : femcam.sweep.SweepResult
        As for :func:`plot_sweep`.
    out : str or Path
        Output directory.

    Returns
    -------
    list of (callable, tuple)
        ``(function, args)``; ``function(*args)`` draws one plot and returns ``{name: path}``.
    """
    r = result
    d = Path(out) / "plots"
    calls = [(named_plot, ("plot_p0", plot_p0, r, d / "p0_vs_angle.png")),
             (named_plot, ("plot_maxima", plot_maxima, r, d / "maxima_vs_angle.png")),
             (named_plot, ("plot_svaj", plot_svaj_loads, r, d / "svaj_loads.png"))]
    if np.any(np.isfinite(result.table["wear_depth"])):
        calls.append((named_plot, ("plot_wear", plot_wear, r, d / "wear_vs_angle.png")))
    if "curvature_jump" in result.table and np.any(result.table["curvature_jump"] == 1):
        calls.append((named_plot, ("plot_junction", plot_junction_p0, r, d / "p0_curvature_jumps.png")))
    if result.surface_profile is not None and "x_hertz" in result.surface_profile:
        calls.append((plot_surface_sweep, (result.surface_profile, out)))
    return calls


def named_plot(name: str, function, *args) -> dict[str, str]:
    """``{name: function(*args)}``: one plot of :func:`sweep_plot_calls`.

    Parameters
    ----------
    name : str
        The key of the plot in ``SweepResult.paths`` (``"plot_p0"``).
    function : callable
        A plot function of this module returning the path written.
    *args
        Its arguments.

    Returns
    -------
    dict[str, str]
        ``{name: path}``.
    """
    return {name: function(*args)}


def plot_surface_sweep(profile: dict, out) -> dict[str, str]:
    """The worst-angle surface plot of :func:`plot_sweep` alone (``out/plots``).

    Parameters
    ----------
    profile : dict
        ``SweepResult.surface_profile`` with its Hertz curve (``x_hertz``).
    out : str or Path
        Output directory.

    Returns
    -------
    dict[str, str]
        ``{"plot_surface": path}``.
    """
    return {"plot_surface": plot_surface_worst(profile, Path(out) / "plots" / "surface_stress_worst.png")}
