"""Test set-up: headless rendering, offline litellm, and the Chromium the page tests load sites in."""

import os
import shutil

import pytest

os.environ.setdefault("MUJOCO_GL", "egl")
os.environ.setdefault("LITELLM_LOCAL_MODEL_COST_MAP", "True")
# Tasks are built without initial.png and goal.png unless a test asks for them (`snapshots_on`, or RPG_SNAPSHOTS=1 set
# by the test): each is a fifth of a second of software rendering, a third of a build's time, and most tests look at no
# picture.  test_compile checks that the task is the same either way.
os.environ.setdefault("RPG_SNAPSHOTS", "0")


CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync"]


@pytest.fixture(scope="session")
def chromium():
    """Debian's chromium, which `make install` installs where it can; the page tests skip without it."""
    exe = shutil.which("chromium")
    if exe is None:
        pytest.skip("chromium is not installed: install Debian's 'chromium' package "
                    "(`make install` does, as root with apt-get; or sudo apt-get install chromium)")
    return exe


@pytest.fixture
def snapshots_on(monkeypatch):
    """Builds in this test render initial.png and goal.png (the suite's default leaves them out)."""
    monkeypatch.setenv("RPG_SNAPSHOTS", "1")
