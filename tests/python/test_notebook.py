"""examples/saltus-notebook.ipynb runs end to end (nbclient), so it cannot rot: on an IPython
kernel of this interpreter (Debian's /usr/bin/python3) that finds the module through
PYTHONPATH, every cell without an error, every figure drawn."""

import json
import os
import sys

import nbformat
from nbclient import NotebookClient

from conftest import EXAMPLES


def test_the_notebook_runs_and_draws_its_figures(tmp_path, monkeypatch):
    # A kernel of this very interpreter, whatever kernels the machine has under the name
    # "python3" (a pyenv one would have neither numpy nor the module).
    kernels = tmp_path / "jupyter" / "kernels" / "saltus-test-python"
    kernels.mkdir(parents=True)
    (kernels / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "saltus test", "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "jupyter"))
    monkeypatch.setenv("SALTUS_FIGURES_DIR", str(tmp_path))
    monkeypatch.setenv("MPLBACKEND", "agg")
    notebook = nbformat.read(EXAMPLES / "saltus-notebook.ipynb", as_version=4)
    client = NotebookClient(notebook, kernel_name="saltus-test-python", timeout=300,
                            resources={"metadata": {"path": str(EXAMPLES)}})
    client.execute()  # raises CellExecutionError on the first cell that fails
    text = "".join(o.get("text", "") for c in notebook.cells if c.cell_type == "code"
                   for o in c.get("outputs", []))
    assert "average root force sqrt(J/6)" in text
    assert "refused:" in text and "keyframes" in text
    assert "take-off" in text  # M7's twist comes from its take-off
    for name in ("python-m1-root-force.png", "python-three-athletes.png", "python-m7-twist.png"):
        png = tmp_path / name
        assert png.is_file() and png.stat().st_size > 10_000, name
    assert os.environ["PYTHONPATH"]  # how the kernel found the module
