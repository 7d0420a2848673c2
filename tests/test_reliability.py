"""Bad input, kill -9 at any moment, concurrent writers, property-based parser robustness."""

import json
import os
import signal
import subprocess
import sys
import time

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rpg.compiler import compile_instruction
from rpg.schema.builtin import ParseError, parse
from rpg.schema.feasibility import InfeasibleTask, check_feasibility
from rpg.steer import Family, create_family

RPG = [sys.executable, "-m", "rpg.cli"]


def rpg(*args, **kw):
    return subprocess.run([*RPG, *args], capture_output=True, text=True, env={**os.environ, "COLUMNS": "200"}, **kw)


def one_clear_line(proc, needle):
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and "Traceback" not in proc.stderr, proc.stderr
    assert needle.lower() in lines[0].lower(), lines[0]


@pytest.mark.parametrize("instruction,needle", [
    ("", "empty"), ("   \n\t", "empty"), ("qwzx plorb vrenk", "could not parse"), ("x" * 2001, "limit"),
    ("Stack the mauve block on the red block", "mauve"), ("Place the letter '?' cube on the table", "could not find a task"),
    ("put red on blue and blue on red", "contradict"), ("Stack 30 red blocks on top of each other", "reach"),
    ("Arrange 27 digit cubes in increasing numerical order from left to right", "workspace"),
    ("Align 12 blocks in a single straight line", "workspace"), ("Make a 9x9 grid of red blocks", "most a task holds"),
])
def test_bad_instructions_exit_2_with_one_line_and_write_nothing(tmp_path, instruction, needle):
    one_clear_line(rpg("compile", instruction, "-o", str(tmp_path / "lib")), needle)
    assert not (tmp_path / "lib").exists() or not any((tmp_path / "lib").iterdir())


@pytest.fixture(scope="module")
def artifact(tmp_path_factory):
    return compile_instruction("Stack the yellow block on top of the red block", tmp_path_factory.mktemp("a")).path


@pytest.mark.parametrize("poses,needle", [
    ({"ghost": {"position": [0.5, 0, 1]}}, "ghost"),
    ({"red": {"position": ["a", 0, 1]}}, "position"),
    ({"red": {"position": [0.5, 0]}}, "3 position"),
    ({"red": {"position": ["NaN", 0, 1]}}, "finite"),
    ([1, 2], "must map"),
])
def test_bad_poses_files(artifact, tmp_path, poses, needle):
    f = tmp_path / "p.json"
    f.write_text(json.dumps(poses))
    one_clear_line(rpg("check", str(artifact), "--poses", str(f)), needle)


def test_malformed_artifacts_and_corrupt_families(artifact, tmp_path):
    import shutil

    bad = tmp_path / "bad"
    shutil.copytree(artifact, bad)
    (bad / "task.yaml").write_text((bad / "task.yaml").read_text()[:120])
    before = {p.name: p.read_bytes() for p in bad.iterdir()}
    one_clear_line(rpg("validate", str(bad)), "malformed")
    one_clear_line(rpg("inspect", str(bad)), "malformed")
    assert {p.name: p.read_bytes() for p in bad.iterdir()} == before
    (bad / "code.py").unlink()
    one_clear_line(rpg("validate", str(bad)), "code.py is missing")
    fam = tmp_path / "fam"
    shutil.copytree(artifact, fam)
    create_family(fam)
    (fam / "family.yaml").write_text("versions: [oops\n")
    for cmd in (["log", str(fam)], ["verify", str(fam)], ["steer", str(fam), "add a green block on top"], ["show", f"{fam}@v0"]):
        one_clear_line(rpg(*cmd), "corrupt")
    assert sorted(p.name for p in fam.iterdir() if not p.name.startswith(".")) == ["family.yaml", "v0"]


@given(st.text(max_size=120))
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_builtin_front_end_never_crashes_on_random_text(text):
    try:
        check_feasibility(parse(text))
    except (ParseError, InfeasibleTask, ValueError):
        pass


WORDS = ["stack", "the", "red", "blue", "green", "block", "on", "top", "of", "a", "tower", "line", "circle", "pyramid",
         "3x3", "letters", "sort", "alphabetically", "left", "right", "behind", "patch", "two", "five", "piles", "by",
         "color", "spell", "word", "'CAT'", "then", "grid", "2x4", "base", "numerically", "yellow", "each", "other"]


@given(st.lists(st.sampled_from(WORDS), min_size=1, max_size=14))
@settings(max_examples=300, deadline=None)
def test_builtin_front_end_reads_or_refuses_domain_word_salad(words):
    try:
        schema = check_feasibility(parse(" ".join(words)))
    except (ParseError, InfeasibleTask, ValueError):
        return
    assert schema.assets and schema.goal_layout


@pytest.mark.slow
@pytest.mark.parametrize("delay", [0.3, 0.8, 1.3, 1.8])
def test_kill_9_during_steer_leaves_the_family_valid(artifact, tmp_path, delay):
    import shutil

    fam = tmp_path / "fam"
    shutil.copytree(artifact, fam)
    create_family(fam)
    proc = subprocess.Popen([*RPG, "steer", str(fam), "Add a green block on top"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    time.sleep(delay)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    assert rpg("verify", str(fam)).returncode == 0
    hist = Family(fam).load()
    assert len(hist.versions) in (1, 2)
    r = rpg("steer", str(fam), "Add a blue block on top")
    assert r.returncode == 0, r.stderr
    assert rpg("verify", str(fam)).returncode == 0


@pytest.mark.slow
@pytest.mark.parametrize("delay", [0.3, 0.9, 1.5])
def test_kill_9_during_compile_leaves_no_half_written_task(tmp_path, delay):
    lib = tmp_path / "lib"
    proc = subprocess.Popen([*RPG, "compile", "Make a 3x3 square of red blocks", "-o", str(lib)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    time.sleep(delay)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    for d in (lib.iterdir() if lib.exists() else []):
        if not d.name.startswith("."):
            assert rpg("validate", str(d)).returncode == 0


@pytest.mark.slow
def test_concurrent_steers_are_serialized_and_lose_no_version(artifact, tmp_path):
    import shutil

    fam = tmp_path / "fam"
    shutil.copytree(artifact, fam)
    create_family(fam)
    procs = [subprocess.Popen([*RPG, "steer", str(fam), edit], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
             for edit in ("Add a green block on top", "Add a blue block on top")]
    assert all(p.wait() == 0 for p in procs), [p.stderr.read() for p in procs]
    hist = Family(fam).load()
    assert len(hist.versions) == 3
    assert {v.description for v in hist.versions[1:]} == {"Add a green block on top", "Add a blue block on top"}
    assert rpg("verify", str(fam)).returncode == 0


@pytest.mark.slow
def test_concurrent_compiles_into_one_library(tmp_path):
    lib = tmp_path / "lib"
    texts = ["Stack the red block on top of the yellow block", "Stack the red block on top of the yellow block",
             "Place the red block behind the yellow block"]
    procs = [subprocess.Popen([*RPG, "compile", t, "-o", str(lib)], stdout=subprocess.PIPE, stderr=subprocess.PIPE) for t in texts]
    assert all(p.wait() == 0 for p in procs), [p.stderr.read() for p in procs]
    tasks = sorted(d.name for d in lib.iterdir() if not d.name.startswith("."))
    assert len(tasks) == 2
    for d in tasks:
        assert rpg("validate", str(lib / d)).returncode == 0


@pytest.mark.slow
@pytest.mark.parametrize("delay", [1.0, 2.5])
def test_kill_9_during_a_batch_build_leaves_entries_whole(tmp_path, delay):
    manifest = tmp_path / "manifest.yaml"
    manifest.write_text("entries:\n"
                        "- {name: a, instruction: Stack two blocks on top of each other.}\n"
                        "- {name: b, instruction: Place the red block behind the yellow block}\n"
                        "- {name: c, instruction: Make a 3x3 square of red blocks}\n")
    before = manifest.read_text()
    proc = subprocess.Popen([*RPG, "build", str(manifest), "--jobs", "2"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    time.sleep(delay)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    if manifest.read_text() != before:  # rewritten only when the batch is done: then complete
        from rpg.library import load_manifest

        assert all(e.content_hash for e in load_manifest(manifest).entries)
    for d in tmp_path.iterdir():
        if d.is_dir() and not d.name.startswith("."):
            assert rpg("validate", str(d)).returncode == 0


def test_every_error_class_of_the_package_is_an_rpg_error_with_its_exit_code():
    """The CLI maps errors to exit codes through ``RpgError.exit_code`` alone, so every
    public error class the package defines must derive from it (rpg.errors)."""
    import importlib
    import inspect
    import pkgutil

    import rpg
    from rpg.errors import EXIT_BAD_INPUT, EXIT_INVALID, EXIT_PROVIDER, RpgError
    from rpg.schema.llm import ModelOutputError, ProviderError

    found = {}
    for mod in pkgutil.walk_packages(rpg.__path__, "rpg."):
        if mod.name.startswith(("rpg.validate.child", "rpg.library.ray")):
            continue
        module = importlib.import_module(mod.name)
        for name, cls in inspect.getmembers(module, inspect.isclass):
            if (cls.__module__ == mod.name and issubclass(cls, Exception) and not issubclass(cls, Warning)
                    and not name.startswith("_")
                    and name not in ("GateFailure", "SandboxViolation", "RestrictedAccess", "LoadError")):  # internal to the gates
                found[name] = cls
    assert {"ParseError", "SteerError", "ArtifactError", "UnaccountedMention", "ManifestError"} <= set(found)
    assert [n for n, c in found.items() if not issubclass(c, RpgError)] == []
    assert ParseError.exit_code == EXIT_BAD_INPUT and ProviderError.exit_code == EXIT_PROVIDER
    assert ModelOutputError.exit_code == EXIT_INVALID
