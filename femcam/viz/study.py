"""Plots of a design study (draw only: the arrays come from :func:`femcam.study.run_study`):
the Pareto front of peak Hertz pressure against cam size, and the map of the constraint that
binds over two varied keys. matplotlib through :func:`femcam.viz._mpl.pyplot` (lazy).
"""

from __future__ import annotations

import numpy as np

from ._mpl import legend_outside, pyplot, save


def plot_pareto(size, p0, feasible, pareto, path, *, fe=None) -> str:
    """Peak Hertz pressure against cam size: feasible and infeasible variants and the
    non-dominated (Pareto) set.

    Parameters
    ----------
    size : array_like, shape (n,)
        Largest cam radius (m): the distance of the farthest cam surface point from the axis.
    p0 : array_like, shape (n,)
        Worst-angle Hertz peak pressure (Pa).
    feasible, pareto : array_like of bool, shape (n,)
        Flags of the variants.
    path : str or Path
        Output PNG.
    fe : array_like, shape (n,), optional
        FE peak pressure of the FE candidates (Pa; NaN elsewhere).

    Returns
    -------
    str
        ``path``.
    """
    plt = pyplot()
    size, p0 = np.asarray(size, float) * 1e3, np.asarray(p0, float) * 1e-6
    feasible, pareto = np.asarray(feasible, bool), np.asarray(pareto, bool)
    fig, ax = plt.subplots(figsize=(7.0, 4.5))
    ax.scatter(size[~feasible], p0[~feasible], s=12, c="0.7", marker="x", label="infeasible")
    ax.scatter(size[feasible], p0[feasible], s=14, c="tab:blue", label="feasible")
    order = np.argsort(size[pareto])
    ax.plot(size[pareto][order], p0[pareto][order], "-o", c="tab:red", ms=5, mfc="none",
            label="Pareto front (feasible, non-dominated)")
    if fe is not None and np.any(np.isfinite(fe)):
        f = np.isfinite(fe)
        ax.scatter(size[f], np.asarray(fe, float)[f] * 1e-6, marker="*", s=70, c="tab:green", label="FE p0")
    ax.set_xlabel("cam size: largest cam radius (mm)")
    ax.set_ylabel("worst-angle peak pressure p0 (MPa)")
    ax.grid(alpha=0.3)
    legend_outside(ax)
    return str(save(fig, path, tight=True))


def plot_constraint_map(x, y, binding, feasible, path, *, xlabel: str = "x", ylabel: str = "y") -> str:
    """Which constraint binds (has the smallest margin) at each point of two varied keys;
    hollow markers: infeasible (the binding constraint is violated).

    Parameters
    ----------
    x, y : array_like, shape (n,)
        The two varied keys' values (their scene-file units, named in the labels).
    binding : array_like of str, shape (n,)
        Binding constraint per variant ("" for a failed one).
    feasible : array_like of bool, shape (n,)
        Feasible flags.
    path : str or Path
        Output PNG.
    xlabel, ylabel : str
        Axis labels (the scene keys, units in the names).

    Returns
    -------
    str
        ``path``.
    """
    plt = pyplot()
    x, y = np.asarray(x, float), np.asarray(y, float)
    binding, feasible = np.asarray(binding, str), np.asarray(feasible, bool)
    fig, ax = plt.subplots(figsize=(7.0, 4.5))
    names = [b for b in dict.fromkeys(binding.tolist())]
    colours = plt.get_cmap("tab10")
    for k, name in enumerate(names):
        m = binding == name
        c = "0.5" if name == "" else colours(k % 10)
        lab = name or "failed"
        ax.scatter(x[m & feasible], y[m & feasible], s=60, marker="s", color=c, label=f"{lab} (feasible)")
        ax.scatter(x[m & ~feasible], y[m & ~feasible], s=60, marker="s", facecolors="none", edgecolors=c,
                   label=f"{lab} (violated)")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title("binding constraint (smallest margin)")
    legend_outside(ax)
    return str(save(fig, path, tight=True))
