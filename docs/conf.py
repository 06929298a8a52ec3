"""Sphinx configuration of the femcam documentation site.

Build it (warnings are errors, as in CI) from the repository root::

    python -m pip install -e ".[docs]"
    python -m sphinx -W --keep-going -b html docs docs/_build/html

The pages are the Markdown files of ``docs/`` (read by myst-parser), the API reference is made
by autodoc from the numpydoc docstrings, and the gallery is made by sphinx-gallery from
``examples/*.py``, which it runs during the build.
"""

from __future__ import annotations

import importlib
import inspect
import re
import sys
import types
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(ROOT))  # document this checkout's femcam, not another installed copy

import femcam  # noqa: E402

project = "femcam"
author = "femcam developers"
copyright = "femcam developers"  # noqa: A001  (the name Sphinx reads)
version = release = femcam.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
templates_path = ["_templates"]
exclude_patterns = [
    "_build",
    "sg_execution_times.rst",  # sphinx-gallery's timing page, if an older build left one
]

# --- Markdown pages (myst-parser) ---
# heading anchors for the "[text](page.md#section)" links the pages use between themselves
myst_heading_anchors = 4
# A link from a page to a repository file outside docs/ (CHANGELOG.md, meshes/) has no page on
# the site, so it renders as its text; that the file exists is tested (tests/test_docs_links.py).
nitpick_ignore_regex = [
    ("myst", re.escape(str(ROOT)) + r"/(?!docs/).+"),  # ../CHANGELOG.md, resolved to a doc name
    ("myst", r"\.\./.+"),  # ../meshes/, kept as written
]

# --- API reference (autodoc + numpydoc) ---
autodoc_default_options = {"members": True, "member-order": "bysource"}
autodoc_typehints = "none"  # the numpydoc "Parameters" sections carry types and units
autosummary_generate = True
autosummary_imported_members = False
# numpydoc: no per-method autosummary tables inside each class (autodoc already lists the
# members); parameter types are prose ("float, m"), not cross-reference targets.
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False


#: public packages left out of the API reference, with the reason
NOT_IN_API = {"cli": "the command line: its reference is `femcam --help` and the guide pages"}


def _api_packages() -> list[str]:
    """The packages of the API reference in the order of the data flow: the root package, then
    the layer order written once in docs/architecture.md (tests/test_architecture.py holds every
    package to it), without private modules and ``NOT_IN_API``. A new package appears by itself."""
    text = (DOCS / "architecture.md").read_text(encoding="utf-8")
    units = [u.strip() for u in re.search(r"^\s*layers:\s*(.+)$", text, re.M).group(1).split("->")]
    return ["femcam"] + [f"femcam.{u}" for u in units
                         if not u.startswith("_") and u != "femcam" and u not in NOT_IN_API]


API_PACKAGES = _api_packages()

def _home(obj, default: str) -> str:
    """The API package whose page documents ``obj``: the longest package name its module
    starts with (a name re-exported by several packages is documented once, where it is defined)."""
    mod = obj.__name__ if inspect.ismodule(obj) else getattr(obj, "__module__", None)
    if not isinstance(mod, str) or not mod.startswith("femcam"):
        return default
    found = [p for p in API_PACKAGES if mod == p or mod.startswith(p + ".")]
    return max(found, key=len) if found else default


def _elsewhere() -> dict[str, list[tuple[str, str]]]:
    """For each API package, ``(name, reST link)`` of the names in its ``__all__`` that another
    package's page documents; the page lists them as links instead of a second copy."""
    out = {}
    for pkg in API_PACKAGES:
        mod = importlib.import_module(pkg)
        out[pkg] = []
        for n in getattr(mod, "__all__", ()):
            obj = getattr(mod, n)
            home = _home(obj, pkg)
            if n.startswith("__") or home == pkg:
                continue
            link = f":py:mod:`{home}`" if inspect.ismodule(obj) else f":py:obj:`{home}.{n}`"
            out[pkg].append((n, link))
    return out


autosummary_context = {"elsewhere": _elsewhere(), "api_packages": API_PACKAGES}



def _skip_type_alias(app, what, name, obj, skip, options):
    """Leave type aliases (``femcam.io.Column = tuple[str, str, float]``) out of the API pages:
    numpydoc gives a callable alias a signature, on which Sphinx 9 fails ("error while formatting
    signature", Sphinx issue 14576); the module docstrings describe them in words."""
    return True if isinstance(obj, types.GenericAlias) else None


def setup(app):
    """Connect the hooks above."""
    app.connect("autodoc-skip-member", _skip_type_alias)


# --- Gallery (sphinx-gallery) ---
# Every examples/*.py is a narrated script, executed during the build; its figures are
# rendered into docs/gallery/ (generated, git-ignored). A failing example fails the build.
sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": str(DOCS / "gallery"),
    "filename_pattern": r"\.py$",
    "ignore_pattern": r"__init__\.py",
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "show_memory": False,
    "write_computation_times": False,  # the build log prints them; no extra page in the index glob
}
# sphinx-gallery needs the gallery's header (examples/GALLERY_HEADER.rst, written with the
# scripts); a checkout without it gets a one-line gallery page, so the index's toctree stays whole.
if not (ROOT / "examples" / "GALLERY_HEADER.rst").is_file():
    extensions.remove("sphinx_gallery.gen_gallery")
    (DOCS / "gallery").mkdir(exist_ok=True)
    (DOCS / "gallery" / "index.rst").write_text("Gallery\n=======\n\nNo example scripts here.\n")

# --- HTML ---
html_theme = "furo"
html_title = f"femcam {release}"
html_static_path: list[str] = []
html_show_sourcelink = False
