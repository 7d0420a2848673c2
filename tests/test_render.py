"""Snapshots are drawn by rpg's own process from the task's data: the sandboxed child that
runs task code has no simulator and no renderer."""

import io
import subprocess
import sys

import numpy as np
import pytest
from PIL import Image

from rpg.compiler import compile_instruction


@pytest.fixture(scope="module")
def letters(tmp_path_factory):
    return compile_instruction("Spell CAB with letter blocks in a row", tmp_path_factory.mktemp("cab")).path


def _png(path) -> np.ndarray:
    if not path.is_file():
        pytest.skip("no headless OpenGL on this machine")
    return np.asarray(Image.open(io.BytesIO(path.read_bytes())).convert("RGB")).astype(int)


def test_rpg_render_redraws_the_compiled_snapshots(letters, tmp_path):
    before = {k: _png(letters / f"{k}.png") for k in ("initial", "goal")}
    for k in before:
        (letters / f"{k}.png").unlink()
    proc = subprocess.run([sys.executable, "-m", "rpg.cli", "render", str(letters)], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    for key, a in before.items():
        b = _png(letters / f"{key}.png")
        assert a.shape == b.shape == (480, 640, 3)
        assert a.std() > 5, "blank image"
        assert np.abs(a - b).mean() < 0.05, key
    assert np.abs(before["initial"] - before["goal"]).mean() > 0.5  # two different states


def test_the_child_that_runs_task_code_imports_no_simulator(letters):
    """The sandboxed child answers with data only: it must not even import MuJoCo or an
    OpenGL binding (what it cannot load it cannot misuse)."""
    code = ("import sys, json; from rpg.validate import child; from rpg.artifact import task_sources;"
            f"out = child.handle({{'op': 'data', 'sources': task_sources({str(letters)!r}), 'seeds': [0]}});"
            "assert json.loads(out)['ok'], out;"
            "bad = sorted(m for m in sys.modules if m.split('.')[0] in ('mujoco', 'OpenGL', 'PIL', 'gymnasium'));"
            "print(bad)")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"
