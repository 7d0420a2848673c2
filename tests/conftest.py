"""Test set-up: headless rendering, offline litellm, and the Chromium the page tests load sites in."""

import os
import shutil

import pytest

os.environ.setdefault("MUJOCO_GL", "egl")
os.environ.setdefault("LITELLM_LOCAL_MODEL_COST_MAP", "True")


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
