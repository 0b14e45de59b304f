# Sphinx configuration of the Python API reference (make docs; ctest docs.sphinx builds it with
# warnings as errors). The module is imported from PYTHONPATH (the build tree's python/).
project = "cagd"
author = "the cagd-repro contributors"
extensions = ["sphinx.ext.autodoc", "sphinx.ext.doctest"]
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": True, "imported-members": True}
html_theme = "alabaster"
exclude_patterns = []
