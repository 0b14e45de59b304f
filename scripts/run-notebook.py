#!/usr/bin/env python3
"""Execute a notebook top to bottom (nbclient, the python3 kernel) and fail on the first cell
that raises. Writes the executed notebook and what it saves into OUT_DIR. make test runs
examples/curvature_combs.ipynb this way. Usage: run-notebook.py NOTEBOOK OUT_DIR"""
import os
import sys

import nbformat
from nbclient import NotebookClient

if len(sys.argv) != 3:
    sys.exit("usage: run-notebook.py NOTEBOOK OUT_DIR")
path, out_dir = sys.argv[1], sys.argv[2]
os.makedirs(out_dir, exist_ok=True)
os.environ["CAGD_NOTEBOOK_OUT"] = os.path.abspath(out_dir)
nb = nbformat.read(path, as_version=4)
NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": out_dir}}).execute()
nbformat.write(nb, os.path.join(out_dir, os.path.basename(path)))
saved = os.path.join(out_dir, "curvature_combs.png")
if os.path.basename(path) == "curvature_combs.ipynb" and not os.path.getsize(saved):
    sys.exit(f"run-notebook: {saved} is empty")
print(f"run-notebook: {path} executed, {len(nb.cells)} cells")
