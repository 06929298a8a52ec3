"""How large a contact mesh will be, before gmsh is asked: the element count from the mesh
options alone, and the cap above which a mesh is refused (with the estimate, the cap and the
option to change) instead of running for many minutes and tens of GB.

Symbols (lengths in units of the reference half-width ``a_ref``):

=========  =====================================================  ======
symbol     meaning                                                unit
=========  =====================================================  ======
``n``      ``a_over_h``, elements per half-width in the fine zone  -
``xf``     ``fine_half_width``, half-length of the fine zone       a_ref
``d``      ``fine_depth``, depth kept at size ``h``                a_ref
``g``      ``growth``, size slope beyond the fine band             -
``c``      area of a triangle of edge ``s`` over ``s**2``          -
=========  =====================================================  ======

One body: the fine band (a ``2 xf`` by ``d`` rectangle with quarter discs at its ends) at size
``h = 1/n``, then the graded zone where the size grows as ``h + g t`` with the distance ``t``
beyond the band (a strip of length ``2 xf`` plus a half annulus), up to the largest size. The
element count is the area over ``c s**2`` integrated over both zones:

.. math::

    N \\approx \\frac{(2 x_f d + \\pi d^2 / 2)\\, n^2}{c}
          + \\frac{2 x_f}{c\\, g} (n - n_c)
          + \\frac{\\pi}{c\\, g^2}\\Big(\\ln\\frac{n}{n_c} + \\frac{n_c}{n} - 1\\Big)
          + \\frac{\\pi d}{c\\, g} (n - n_c)

with ``n_c = 1 / s_max`` the half-width over the largest size. The fine band dominates
(``~ 16.5 n**2`` for both bodies with the default options); against gmsh's own meshes of
both bodies (``tests/test_mesh_estimate.py``: ``n`` = 5 to 40, three radius pairs) the real
count is 1.05-1.3 times the estimate, the larger ratio on the coarsest meshes (gmsh's
Frontal-Delaunay triangles are a little smaller than equilateral ones of edge ``s``).
"""

from __future__ import annotations

import math

from .. import _validate
from .options import MeshOptions

#: area of a triangle of edge s, over s**2 (equilateral)
C_TRIANGLE = math.sqrt(3.0) / 4.0

#: most triangles of the two bodies of one contact mesh (cam + roller). The FE sweep held
#: ~1.9 GB for a 33,000-element mesh (a_over_h = 40, seed 002, 4 angles: models of several
#: families, P2 assembly and factorisations) and ~0.6 GB at 4,000 (a_over_h = 10): about
#: 45 kB per element above the 0.5 GB base, so this cap keeps one sweep process near 4-5 GB
#: (a_over_h up to ~65 with the default mesh options).
MAX_CONTACT_ELEMENTS = 80_000

#: memory of the FE sweep per contact-mesh element (bytes), measured as said above
BYTES_PER_ELEMENT = 45e3


def estimate_body_elements(options: MeshOptions, L_over_a: float) -> float:
    """Estimated triangles of one body's contact mesh (see the module docstring).

    Parameters
    ----------
    options : MeshOptions
        The mesh options (``a_over_h``, ``fine_half_width``, ``fine_depth``, ``growth``,
        ``max_size_fraction``).
    L_over_a : float
        Body size over the reference half-width (-, > 0).

    Returns
    -------
    float
        The estimate (-).

    Examples
    --------
    >>> round(estimate_body_elements(MeshOptions(a_over_h=10), 100.0))
    1658
    """
    L_over_a = _validate.positive("L_over_a", L_over_a, "")
    n, xf, d, g = options.a_over_h, options.fine_half_width, options.fine_depth, options.growth
    c = C_TRIANGLE
    nc = min(n, 1.0 / (options.max_size_fraction * L_over_a))  # half-widths per largest size
    fine = (2.0 * xf * d + 0.5 * math.pi * d * d) * n * n / c
    graded = (2.0 * xf + math.pi * d) / (c * g) * (n - nc) \
        + math.pi / (c * g * g) * (math.log(n / nc) + nc / n - 1.0)
    return fine + graded


def estimate_contact_elements(options: MeshOptions, L_over_a: float = 200.0) -> float:
    """Estimated triangles of a contact mesh (cam and roller), from the options alone.

    Parameters
    ----------
    options : MeshOptions
        The mesh options.
    L_over_a : float, optional
        Body size over the reference half-width (-); the default 200 (a 10 mm roller, a
        0.05 mm half-width) is on the large side of cam contacts, and the count depends on it
        only through a logarithm.

    Returns
    -------
    float
        Both bodies (-).

    Examples
    --------
    >>> round(estimate_contact_elements(MeshOptions(a_over_h=40)))
    31538
    """
    return 2.0 * estimate_body_elements(options, L_over_a)


def check_contact_elements(options: MeshOptions, name: str = "a_over_h",
                           L_over_a: float = 200.0) -> float:
    """Refuse a contact mesh whose estimated size exceeds :data:`MAX_CONTACT_ELEMENTS`.

    Parameters
    ----------
    options : MeshOptions
        The mesh options.
    name : str, optional
        The parameter named in the refusal (``a_over_h``, ``[fe] a_over_h``, ``--a-over-h``).
    L_over_a : float, optional
        Body size over the reference half-width (-).

    Returns
    -------
    float
        The estimate (-), when accepted.

    Raises
    ------
    InputError
        Naming ``name``, its value, the estimate, the memory it would need, the cap and the
        largest accepted value.
    """
    n = estimate_contact_elements(options, L_over_a)
    if n <= MAX_CONTACT_ELEMENTS:
        return n
    lo, hi = 2.0, options.a_over_h   # the largest accepted a_over_h, by bisection
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        m = MeshOptions(**{**_fields(options), "a_over_h": mid})
        lo, hi = (mid, hi) if estimate_contact_elements(m, L_over_a) <= MAX_CONTACT_ELEMENTS else (lo, mid)
    gb = (n * BYTES_PER_ELEMENT + 0.5e9) / 1e9
    raise _validate.fail(name, options.a_over_h, "(elements per contact half-width, a/h)",
                         f"the contact mesh would have ~{n:.3g} elements (~{gb:.3g} GB for an FE "
                         f"sweep), above the cap of {MAX_CONTACT_ELEMENTS:,} elements "
                         f"(femcam.mesh.estimate.MAX_CONTACT_ELEMENTS); use {name} <= "
                         f"{math.floor(lo)}")


def _fields(options: MeshOptions) -> dict:
    return {k: getattr(options, k) for k in options.__dataclass_fields__}
