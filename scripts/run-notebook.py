#!/usr/bin/env python3
"""Execute notebooks top to bottom (nbclient, the python3 kernel) as a user would: each in an empty
temporary working directory, which must stay empty (a notebook writes nothing where it runs), and
fail on the first cell that raises or on a notebook that draws no figure. The executed notebooks
go to OUT_DIR (for a look afterwards). make test runs every examples/*.ipynb this way.
Usage: run-notebook.py OUT_DIR NOTEBOOK [NOTEBOOK ...]"""
import os
import sys
import tempfile

import nbformat
from nbclient import NotebookClient

if len(sys.argv) < 3:
    sys.exit("usage: run-notebook.py OUT_DIR NOTEBOOK [NOTEBOOK ...]")
out_dir = sys.argv[1]
os.makedirs(out_dir, exist_ok=True)
for path in sys.argv[2:]:
    nb = nbformat.read(path, as_version=4)
    with tempfile.TemporaryDirectory() as cwd:
        NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": cwd}}).execute()
        left = sorted(os.listdir(cwd))
        if left:
            sys.exit(f"run-notebook: {path} wrote into its working directory: {left}")
    nbformat.write(nb, os.path.join(out_dir, os.path.basename(path)))
    images = sum("image/png" in o.get("data", {}) for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", []))
    if images == 0:
        sys.exit(f"run-notebook: {path} drew no figure")
    print(f"run-notebook: {path} executed from an empty directory, {len(nb.cells)} cells, {images} figure(s), nothing written")
