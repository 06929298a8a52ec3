r"""Coatings: a thin elastic layer bonded to one body's surface (DLC, PVD nitrides).

=====================  ============================================  ======  =====================
symbol                 meaning                                       unit    source
=====================  ============================================  ======  =====================
``t``                  coating thickness                             m       scene ``thickness_um``
``E_c, nu_c``          coating Young's modulus, Poisson's ratio      Pa, -   scene ``E_GPa, nu``
``tau_i``              interface shear strength (adhesion)           Pa      scene
``H_c``                coating hardness                              Pa      scene
=====================  ============================================  ======  =====================

The coating is its own material region of the body's FE mesh (``MeshOptions.coat_body``,
``coat_thickness``; a structured band of ``max(coat_layers, ceil(t/h))`` layers, see
:func:`femcam.mesh.build_contact_mesh`), bonded to the substrate (shared nodes, so displacement
and traction are continuous). The contact solve is unchanged; the body's stiffness carries the
coating's Lamé parameters in the band (:func:`femcam.fe.elasticity.assemble_body` reads
``CoatedMaterial.coating``). Reference results for a layer on a half-space: King & O'Sullivan
1987, O'Sullivan & King 1988.
"""

from __future__ import annotations

from dataclasses import dataclass

from .. import _validate
from ..fe import ContactModel, SolverOptions
from ..materials import Material
from ..mesh import MeshOptions


@dataclass(frozen=True, kw_only=True)
class Coating:
    """A coating bonded to one body's surface.

    Parameters
    ----------
    thickness : float
        Coating thickness ``t`` [m], 0 < t <= 1e-3.
    material : femcam.materials.Material
        Coating elastic constants (E [Pa], nu [-]).
    interface_shear_strength : float, optional
        Interface shear strength (adhesion) ``tau_i`` [Pa], > 0; a check that needs it is refused
        without it.
    hardness : float, optional
        Coating hardness ``H_c`` [Pa], > 0; likewise.
    """

    thickness: float
    material: Material
    interface_shear_strength: float | None = None
    hardness: float | None = None

    def __post_init__(self):
        t = _validate.positive("thickness", self.thickness, "m")
        if t > 1e-3:
            raise _validate.fail("thickness", t * 1e6, "um", "must be <= 1000 um (a coating, not a body)")
        if not isinstance(self.material, Material):
            raise _validate.fail("material", self.material, "", "must be a femcam.materials.Material")
        for k in ("interface_shear_strength", "hardness"):
            v = getattr(self, k)
            if v is not None:
                object.__setattr__(self, k, _validate.positive(k, v, "Pa"))

    def require(self, name: str) -> float:
        """A strength that a check needs.

        Parameters
        ----------
        name : {"interface_shear_strength", "hardness"}
            The field.

        Returns
        -------
        float
            Its value [Pa].

        Raises
        ------
        InputError
            It was not given (naming the scene key).
        """
        v = getattr(self, name)
        if v is None:
            key = "interface_shear_strength_MPa" if name.startswith("interface") else "hardness_MPa"
            raise _validate.fail(f"coating.{name}", None, "Pa",
                                 f"is needed for this check (scene key {key})")
        return v


@dataclass(frozen=True, kw_only=True)
class CoatedMaterial(Material):
    """A substrate Material carrying the ``coating`` Material of its surface band.

    Everything that reads ``E, nu`` (Hertz, E*) sees the substrate; the FE assembly gives the
    coating band the coating's constants.

    Parameters
    ----------
    E : float
        Substrate Young's modulus [Pa].
    nu : float
        Substrate Poisson's ratio [-].
    name : str, optional
        Name.
    hardness : float, optional
        Substrate hardness [Pa].
    coating : femcam.materials.Material, optional
        Elastic constants of the coating band.
    """

    coating: Material | None = None


def build_coated_model(*, Rr: float, rho_ref: float, cam: Material, roller: Material,
                       length: float, a_ref: float, coating: Coating, body: str = "roller",
                       mesh: MeshOptions | None = None, solver: SolverOptions | None = None,
                       plane: str = "strain", element: str = "P2") -> ContactModel:
    """A :class:`~femcam.fe.ContactModel` with ``coating`` on ``body``. The coating info is kept
    in ``model.mesh.options`` (``coat_body``, ``coat_thickness``).

    Parameters
    ----------
    Rr : float
        Roller radius [m].
    rho_ref : float
        Cam radius of curvature to mesh [m], signed (``inf`` = flat).
    cam, roller : femcam.materials.Material
        Materials of the two bodies (the substrate for the coated one).
    length : float
        Face width [m].
    a_ref : float
        Reference half-width [m].
    coating : Coating
        The coating.
    body : {"cam", "roller"}, optional
        The coated body.
    mesh : femcam.mesh.MeshOptions, optional
        Mesh options (``coat_body`` and ``coat_thickness`` are overridden).
    solver : femcam.fe.SolverOptions, optional
        Solver options.
    plane : {"strain", "stress"}, optional
        Plane-elasticity assumption.
    element : {"P1", "P2"}, optional
        Triangle element.

    Returns
    -------
    femcam.fe.ContactModel
        The built model, with the coating band meshed on ``body``.
    """
    _validate.choice("body", body, ("cam", "roller"))
    if not isinstance(coating, Coating):
        raise _validate.fail("coating", coating, "", "must be a femcam.layers.Coating")
    mesh = mesh or MeshOptions()
    opts = MeshOptions(**{**{k: getattr(mesh, k) for k in mesh.__dataclass_fields__},
                          "coat_body": body, "coat_thickness": coating.thickness})
    sub = cam if body == "cam" else roller
    coated = CoatedMaterial(E=sub.E, nu=sub.nu, name=f"{sub.name}+coating", hardness=sub.hardness,
                            coating=coating.material)
    mats = {"cam": coated if body == "cam" else cam, "roller": coated if body == "roller" else roller}
    return ContactModel.build(Rr=Rr, rho_ref=rho_ref, cam=mats["cam"], roller=mats["roller"],
                              length=length, a_ref=a_ref, mesh=opts, solver=solver, plane=plane,
                              element=element)
