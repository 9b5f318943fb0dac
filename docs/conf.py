"""Sphinx configuration of the API reference and the user guide (``make docs``, ``tools/docs.py``).

tools/docs.py copies docs/ into build/docs/src (autosummary writes its stub pages next to the source,
and the tree stays clean), puts MathJax from its official release (tools/mathjax.py) into _static/,
and runs sphinx-build with -W. WMR_REPOSITORY names the repository (README.md, examples/).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import wmr

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))

project = "wmr"
author = "the wmr-kinematics contributors"
copyright = f"2026, {author}"
release = version = wmr.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "numpydoc",
    "wmr_markdown",
    "wmr_aliases",
]

#: the repository whose README.md and examples/ the guide uses
wmr_repository = os.environ.get("WMR_REPOSITORY", str(HERE.parent))

templates_path = ["_templates"]
exclude_patterns = ["_build", "_ext"]
root_doc = "index"
nitpicky = True  # every cross-reference must resolve, except to
nitpick_ignore_regex = [
    ("py:.*", r"(?!wmr\.)[A-Za-z_]\w*\..+"),  # other libraries (their inventories would come from the
    # network), the standard library, the repository's edition
    ("py:mod", r"edition"),
    ("py:.*", r"(.*\.)?_[A-Za-z].*"),  # private names (a base class in a signature)
]
default_role = "obj"

# the API reference: a page per module, class and function (templates in _templates/autosummary)
autosummary_generate = True
autosummary_ignore_module_all = True  # each object on one page, in the module that defines it
# (what wmr re-exports: the table of api.rst, `.. exports::`)
autosummary_imported_members = False
autodoc_default_options = {"member-order": "bysource"}
autodoc_typehints = "none"  # the numpydoc sections say the types
numpydoc_show_class_members = False  # the class template lists members itself
numpydoc_class_members_toctree = False
numpydoc_attributes_as_param_list = False

# math from the official MathJax release, served from _static/ (no CDN): tools/docs.py puts it there
mathjax_path = "mathjax/tex-svg-full.js"
mathjax3_config = {"tex": {"tags": "none"}, "svg": {"fontCache": "global"}}

html_theme = "alabaster"
html_static_path = ["_static"]
html_title = f"wmr {release}"
html_theme_options = {
    "description": "Kinematics of wheeled mobile robots",
    "fixed_sidebar": True,
    "page_width": "1100px",
    "sidebar_width": "240px",
    "show_relbars": True,
}
html_sidebars = {"**": ["about.html", "navigation.html", "searchbox.html"]}
html_last_updated_fmt = None
html_copy_source = False
