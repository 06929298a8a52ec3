"""The optimisation problem in scaled variables: values, finite-difference Jacobians, SLSQP runs.

Design variables are scaled to ``z in [0, 1]`` by their bounds; the objective is divided by its
value at the first start, so SLSQP sees numbers of order one. A maximum over angles is the
*epigraph* form: minimise ``t`` subject to ``t >= q(theta_i)/q_ref`` at every sample angle
(one linear-in-``t`` constraint per angle) -- exact for the discrete grid, no smoothing
parameter, and SLSQP's multipliers pick the active angles. The grid is then refined by
exchange (:mod:`femcam.optimise.solve`). Gradients are central finite differences in ``z``
(step ``FD_STEP``) of the analytic chain, which is smooth in the design at a fixed normalised
angle.
"""

from __future__ import annotations

import numpy as np

from .chain import angle_grid, evaluate

#: central-difference step in the scaled variables z (truncation ~1e-12, round-off ~1e-10)
FD_STEP = 1e-6
#: a margin >= -FEAS_TOL counts as satisfied (dimensionless; phi over its limit by <= 5e-7 phi_max)
FEAS_TOL = 1e-6


class Problem:
    """Scaled objective and constraint margins of one design problem (cached per ``z``).

    Parameters
    ----------
    design : femcam.optimise.design.Design
        Variables and the base scene.
    objective : str
        Objective name (:data:`femcam.optimise.chain.OBJECTIVES`).
    limits : dict
        ``{constraint name: limit (SI)}``.
    n_motion : int
        Samples per rise/fall segment.
    """

    def __init__(self, design, objective: str, limits: dict, n_motion: int):
        self.design, self.objective, self.limits, self.n_motion = design, objective, dict(limits), n_motion
        self.lo, self.hi = design.bounds()
        self.extra_u: list = []
        self.ref = 1.0
        self.nfev = 0
        self._cache: dict = {}

    # ---- values -------------------------------------------------------------------------
    def x_of(self, z) -> np.ndarray:
        """Design vector of a scaled point.

        Parameters
        ----------
        z : array_like, shape (n,)
            Scaled design in [0, 1].

        Returns
        -------
        ndarray, shape (n,)
            Design vector (SI).
        """
        return self.lo + np.asarray(z, float) * (self.hi - self.lo)

    def z_of(self, x) -> np.ndarray:
        """Scaled point of a design vector.

        Parameters
        ----------
        x : array_like, shape (..., n)
            Design vector(s) (SI).

        Returns
        -------
        ndarray, shape (..., n)
            Scaled design in [0, 1].
        """
        return (np.asarray(x, float) - self.lo) / (self.hi - self.lo)

    def raw(self, z, *, dense: int | None = None) -> dict:
        """:func:`~femcam.optimise.chain.evaluate` of the variant at ``z`` on the current grid
        (or on ``dense`` samples per rise/fall), plus ``"theta"`` and ``"seg_u"``.

        Parameters
        ----------
        z : array_like, shape (n,)
            Scaled design.
        dense : int, optional
            Samples per rise/fall of a fine grid (no exchange points).

        Returns
        -------
        dict
            Per-angle arrays (SI and dimensionless margins) and the variant ``"scene"``.
        """
        scene = self.design.apply(self.x_of(z))
        n = dense or self.n_motion
        theta, seg_u = angle_grid(scene.program, n, () if dense else self.extra_u)
        lim = self.limits.get
        r = evaluate(scene, theta, self.objective, phi_max=lim("phi_max"), rho_min=lim("rho_min"),
                     liftoff_omega=lim("liftoff_omega"), safety_min=lim("safety_min"),
                     lambda_min=lim("lambda_min"))
        r["theta"], r["seg_u"], r["scene"] = theta, seg_u, scene
        self.nfev += 1
        return r

    def vector(self, z) -> tuple[np.ndarray, np.ndarray]:
        """Scaled objective samples and constraint margins (cached per ``z``).

        Parameters
        ----------
        z : array_like, shape (n,)
            Scaled design.

        Returns
        -------
        q : ndarray, shape (m,)
            Objective per grid angle / ``ref``.
        margins : ndarray, shape (k m,)
            Constraint margins, constraint by constraint (dimensionless).
        """
        key = np.asarray(z, float).tobytes()
        if key not in self._cache:
            r = self.raw(z)
            q = np.ravel(r["objective"])
            m = [np.ravel(r[c]) for c in self.limits]
            self.sizes = [x.size for x in m]
            self._cache = {key: (q / self.ref, np.concatenate(m) if m else np.zeros(0))} | (
                {k: v for k, v in list(self._cache.items())[-64:]})
        return self._cache[key]

    def jacobian(self, z) -> tuple[np.ndarray, np.ndarray]:
        """Central differences of :meth:`vector` in ``z`` (one-sided at a bound).

        Parameters
        ----------
        z : array_like, shape (n,)
            Scaled design.

        Returns
        -------
        dq, dm : ndarray, shapes (m, n) and (k m, n)
            Jacobians of the two arrays of :meth:`vector`.
        """
        z = np.asarray(z, float)
        cols_q, cols_m = [], []
        for i in range(z.size):
            up, dn = z.copy(), z.copy()
            hp = FD_STEP if z[i] + FD_STEP <= 1.0 else 0.0
            hm = FD_STEP if z[i] - FD_STEP >= 0.0 else 0.0
            up[i] += hp
            dn[i] -= hm
            qu, mu = self.vector(up)
            qd, md = self.vector(dn)
            cols_q.append((qu - qd) / (hp + hm))
            cols_m.append((mu - md) / (hp + hm))
        return np.array(cols_q).T, np.array(cols_m).T

    # ---- SLSQP --------------------------------------------------------------------------
    def run(self, z0, *, maxiter: int = 200, ftol: float = 1e-12, only: str | None = None):
        """One SLSQP run from ``z0``.

        ``only=name``: the feasibility problem of one constraint alone (maximise its smallest
        margin, the objective ignored).

        Parameters
        ----------
        z0 : array_like, shape (n,)
            Scaled start.
        maxiter : int
            SLSQP iterations.
        ftol : float
            SLSQP's tolerance on the (scaled) objective.
        only : str, optional
            A constraint name: its feasibility problem alone.

        Returns
        -------
        scipy.optimize.OptimizeResult
            With ``z`` (scaled design) and ``t`` (epigraph value) added.
        """
        from scipy.optimize import minimize  # lazy: scipy.optimize, ~0.15 s to import

        n = len(self.lo)
        names = list(self.limits)
        epi = True
        q0, m0 = self.vector(z0)

        def split(y):
            return (y[:n], y[n]) if epi else (y, 0.0)

        def sel(m):
            if only is None:
                return m
            k = names.index(only)
            start = sum(self.sizes[:k])
            return m[start:start + self.sizes[k]]

        if only is not None:  # maximise s subject to margin_i >= s
            fun = (lambda y: -y[n], lambda y: np.r_[np.zeros(n), -1.0])
            cons = {"type": "ineq", "fun": lambda y: sel(self.vector(y[:n])[1]) - y[n],
                    "jac": lambda y: np.c_[sel(self.jacobian(y[:n])[1]), -np.ones(sel(m0).size)]}
            y0 = np.r_[z0, float(np.min(sel(m0)))]
        elif epi:
            fun = (lambda y: y[n], lambda y: np.r_[np.zeros(n), 1.0])

            def cf(y):
                q, m = self.vector(y[:n])
                return np.r_[y[n] - q, m]

            def cj(y):
                jq, jm = self.jacobian(y[:n])
                return np.r_[np.c_[-jq, np.ones(q0.size)], np.c_[jm, np.zeros(m0.size)]]

            cons = {"type": "ineq", "fun": cf, "jac": cj}
            y0 = np.r_[z0, float(np.max(q0))]
        else:
            fun = (lambda y: float(self.vector(y)[0][0]), lambda y: self.jacobian(y)[0][0])
            cons = {"type": "ineq", "fun": lambda y: self.vector(y)[1], "jac": lambda y: self.jacobian(y)[1]}
            y0 = np.asarray(z0, float)
        bounds = [(0.0, 1.0)] * n + ([(None, None)] if epi else [])
        res = minimize(fun[0], y0, jac=fun[1], method="SLSQP", bounds=bounds,
                       constraints=[cons] if (names or epi) else [],
                       options={"maxiter": maxiter, "ftol": ftol})
        z, t = split(np.asarray(res.x, float))
        res.z, res.t = np.clip(z, 0.0, 1.0), t
        return res
