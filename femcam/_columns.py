"""One declaration of a table column: :class:`Column` (SI name, CSV name, factor, description).

Every package that adds columns to a table (the sweep, the assessment, the half-space, the
ring and cam-disk bodies, the layers) declares them as a tuple of :class:`Column`; the writers
(:func:`femcam.io.write_csv`), :class:`femcam.sweep.SweepResult` and the worst-angle summary
read ``.si``, ``.csv`` and ``.factor``. stdlib only, so every layer may import it.

Unit grammar of CSV names (docs/architecture.md, "Column names"): the unit is the name's
suffix after the quantity, ``<quantity>_<unit>`` (``p0_MPa``, ``theta_deg``); a quotient is
written with ``_per_`` (``u_cam_m_per_s``, ``w_max_N_per_mm``, ``k_wear_mm3_per_N_m``); a
product joins its factors with ``_`` (``eta0_mPa_s``); a dimensionless column has no unit
(``lambda``, ``sf_yield``). The sweep's first kinematic columns (``v_m_s``, ``a_m_s2``,
``j_m_s3``, ``v_slip_m_s``, ``V_cam_m_s``) predate the rule and keep their public names.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["UNITS", "Column"]

#: unit suffixes of CSV names, longest first (the first one a name ends with is its unit)
UNITS = ("mm3_per_N_m", "per_rev_nm", "m_per_rev", "N_per_mm", "m_per_s2", "m_per_s", "mPa_s",
         "m_s2", "m_s3", "m_s", "cycles", "MPa", "deg", "pct", "mm", "um", "nm", "ms", "N", "K", "C")


@dataclass(frozen=True, slots=True)
class Column:
    """One numeric column of a table: its SI name, its CSV name and the factor between them.

    Parameters
    ----------
    si : str
        Name in the table (values in SI units: m, Pa, rad, N, s, fractions).
    csv : str
        Name in the CSV file, unit in the name (:data:`UNITS`, module docstring).
    factor : float
        Factor from SI to the CSV unit: ``csv value = SI value * factor``.
    description : str
        One line on what the column holds ("" where none is written down).

    Examples
    --------
    >>> c = Column("p0_fe", "p0_fe_MPa", 1e-6)
    >>> c.unit, Column("u", "u_cam_m_per_s", 1.0).unit, Column("lam", "lambda", 1.0).unit
    ('MPa', 'm_per_s', '')
    """

    si: str
    csv: str
    factor: float
    description: str = ""

    @property
    def unit(self) -> str:
        """The CSV name's unit suffix (:data:`UNITS`), "" for a dimensionless column.

        Returns
        -------
        str
            E.g. ``"MPa"`` for ``p0_MPa``, ``"m_per_s"`` for ``u_cam_m_per_s``.
        """
        return next((u for u in UNITS if self.csv.endswith("_" + u)), "")
