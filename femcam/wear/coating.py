r"""Archard wear of a coated body: the coating's wear coefficient while the coating lasts.

=============  =================================================  ===========  ==========================
symbol         meaning                                            unit         source
=============  =================================================  ===========  ==========================
``t``          coating thickness                                  m            ``[materials.<body>.coating]
                                                                               thickness_um``
``k_c``        coating's dimensional wear coefficient             m^3/(N m)    ``wear_k_mm3_per_N_m``, or
                                                                               ``wear_K / hardness_MPa``
``k_s``        substrate's (the scene's ``[wear]``) coefficient   m^3/(N m)    :func:`wear_coefficient_info`
``d_c``        depth per revolution of a surface point while      m            the wear map with ``k_c``
               the coating lasts
``N``          cam revolutions                                    -
``N_t``        revolutions to wear through the coating            -            ``t / max d_c``
=============  =================================================  ===========  ==========================

Archard's law (Archard 1953) is linear in ``k``, so a point's depth rate is ``d_c`` in the
coating and ``d_s = d_c k_s / k_c`` in the substrate under it. With the same contact every
revolution the depth after ``N`` revolutions is piecewise linear:

.. math::

    h(N) = \begin{cases} N d_c & N d_c \le t \\ t + (N - t/d_c)\, d_s & N d_c > t \end{cases}

(the contact pressure is the uncoated one: a worn-through spot does not change the load, and
the coating's effect on the pressure is left to :mod:`femcam.layers`). The coating is worn
through first where ``d_c`` is largest, after ``N_t = t / max d_c`` revolutions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..scene.layers import BodyLayers
from ..scene.wear import WearSettings
from .options import wear_coefficient_info


@dataclass(frozen=True, kw_only=True)
class CoatingWear:
    """The wear data of a coated body.

    Parameters
    ----------
    body : ``"cam"`` or ``"roller"``
    thickness : float
        Coating thickness ``t`` (m).
    k_coating : float
        Coating wear coefficient ``k_c`` (m^3/(N m)).
    k_substrate : float
        The substrate's (scene ``[wear]``) coefficient ``k_s`` (m^3/(N m)).
    source : str
        Where ``k_c`` came from (scene keys).
    """

    body: str
    thickness: float
    k_coating: float
    k_substrate: float
    source: str = ""

    def __post_init__(self):
        _validate.choice("body", self.body, ("cam", "roller"))
        _validate.positive("thickness", self.thickness, "m")
        _validate.positive("k_coating", self.k_coating, "m^3/(N m)")
        _validate.positive("k_substrate", self.k_substrate, "m^3/(N m)")

    @property
    def ratio(self) -> float:
        """``k_c / k_s`` (-)."""
        return self.k_coating / self.k_substrate

    def depth_after(self, d_substrate, cycles: float) -> np.ndarray:
        """Depth after ``cycles`` revolutions of points whose depth per revolution is
        ``d_substrate`` (m) with the substrate's ``k`` (the uncoated wear map), see the module
        formula.

        Parameters
        ----------
        d_substrate : float or array_like, shape (n,)
            Depth per revolution with the substrate's ``k`` [m/revolution].
        cycles : float
            Cam revolutions ``N`` [-].

        Returns
        -------
        ndarray, shape of ``d_substrate``
            Worn depth after ``cycles`` revolutions [m].

        Examples
        --------
        >>> cw = CoatingWear(body="cam", thickness=2e-6, k_coating=1e-17, k_substrate=1e-16)
        >>> [round(float(h) * 1e6, 6) for h in cw.depth_after([1e-12, 1e-11], 5e6)]
        [0.5, 32.0]
        """
        d_s = np.asarray(d_substrate, dtype=float)
        return layered_depth(d_s * self.ratio, d_s, self.thickness, cycles)

    def revolutions_through(self, d_substrate) -> float:
        """``N_t = t / max d_c`` (revolutions; inf if nothing wears). ``d_substrate`` (m per
        revolution) as in :meth:`depth_after`.

        Parameters
        ----------
        d_substrate : float or array_like, shape (n,)
            Depth per revolution with the substrate's ``k`` [m/revolution].

        Returns
        -------
        float
            Revolutions ``N_t`` to wear through the coating [-]; ``inf`` if nothing wears.

        Examples
        --------
        >>> CoatingWear(body="cam", thickness=2e-6, k_coating=1e-17, k_substrate=1e-16
        ...             ).revolutions_through([1e-12, 1e-11])
        2000000.0
        """
        d = np.asarray(d_substrate, dtype=float)
        d_max = float(np.nanmax(d)) * self.ratio if d.size else 0.0
        return self.thickness / d_max if d_max > 0 else math.inf


def layered_depth(d_coating, d_substrate, thickness: float, cycles: float) -> np.ndarray:
    r"""Depth (m) after ``cycles`` revolutions through a coating of ``thickness`` (m) worn at
    ``d_coating`` (m/revolution) on a substrate worn at ``d_substrate`` (m/revolution).

    .. math:: h = \min(N d_c, t) + \max(N - t/d_c, 0)\, d_s

    Parameters
    ----------
    d_coating : float or array_like, shape (n,)
        Depth per revolution in the coating [m/revolution].
    d_substrate : float or array_like, shape (n,)
        Depth per revolution in the substrate [m/revolution].
    thickness : float
        Coating thickness ``t`` [m].
    cycles : float
        Cam revolutions ``N`` [-].

    Returns
    -------
    ndarray, broadcast shape of ``d_coating`` and ``d_substrate``
        Worn depth [m].

    Examples
    --------
    >>> layered_depth([1e-12, 1e-11], [1e-11, 1e-10], 2e-6, 1e6).round(12).tolist()
    [1e-06, 8.2e-05]
    """
    d_c = np.asarray(d_coating, dtype=float)
    d_s = np.asarray(d_substrate, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        n_through = np.where(d_c > 0, thickness / np.where(d_c > 0, d_c, 1.0), np.inf)
    return np.minimum(cycles * d_c, thickness) + np.maximum(cycles - n_through, 0.0) * d_s


def coating_wear(layers, wear: WearSettings, hardness: float | None) -> CoatingWear | None:
    """The :class:`CoatingWear` of the first coated body in ``layers``, or None (no coating, or
    a coating without ``wear_k_mm3_per_N_m`` / ``wear_K``). The substrate's ``k`` is the scene's
    ``[wear]`` coefficient (:func:`femcam.wear.options.wear_coefficient_info` of ``wear`` and
    the cam ``hardness``).

    Parameters
    ----------
    layers : tuple of femcam.scene.layers.BodyLayers
        The coated and case-hardened bodies (``Scene.layers``).
    wear : femcam.scene.wear.WearSettings
        The ``[wear]`` settings in SI (``Scene.wear``).
    hardness : float or None
        Cam hardness [Pa] (``Scene.cam.hardness``); None: not given.

    Returns
    -------
    CoatingWear or None
        The first coated body's wear data (SI), or None.

    Raises
    ------
    InputError
        ``layers`` not a tuple of BodyLayers, ``wear`` not a WearSettings, a hardness that is not
        > 0.
    """
    wear = _validate.instance("wear", wear, WearSettings, "a femcam.scene.wear.WearSettings")
    hardness = _validate.optional(_validate.positive, "hardness", hardness, "Pa")
    if not isinstance(layers, tuple) or not all(isinstance(b, BodyLayers) for b in layers):
        raise _validate.fail("layers", type(layers).__name__, "", "must be a tuple of "
                             "femcam.scene.layers.BodyLayers (Scene.layers)")
    for body, c in ((b.body, b.coating) for b in layers if b.coating is not None):
        if c.wear_k is None and c.wear_K is None:
            continue
        if c.wear_k is not None:  # SI: m^3/(N m), Pa, m
            k, src = c.wear_k, (f"[materials.{body}.coating] wear_k_mm3_per_N_m = "
                                f"{c.wear_k * 1e9:g}")
        else:
            k = c.wear_K / c.hardness
            src = (f"[materials.{body}.coating] wear_K = {c.wear_K:g} / hardness_MPa = "
                   f"{c.hardness / 1e6:g}")
        return CoatingWear(body=body, thickness=c.thickness, k_coating=k,
                           k_substrate=wear_coefficient_info(wear, hardness)[0], source=src)
    return None
