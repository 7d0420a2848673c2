"""The attack review's file, name, integrity, YAML, concurrency and argument findings, each
replayed against the real CLI: symlinked outputs and inputs, traversal names, alias bombs,
forged histories, edits to the committed library, concurrent first steers, kill -9 of a
build, and a sweep of bad arguments over every subcommand (one line, exit 2, nothing
written, never a traceback)."""

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import yaml

from rpg.compiler import compile_instruction
from rpg.steer.family import Family, verify_target

ROOT = Path(__file__).resolve().parents[1]
RPG = [sys.executable, "-m", "rpg.cli"]
LIB = ROOT / "library"


def rpg(*args, cwd=None, timeout=300):
    return subprocess.run([*RPG, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=timeout,
                          env={**os.environ, "COLUMNS": "200"})


def one_line_error(r, code=2):
    assert r.returncode == code, (r.returncode, r.stdout, r.stderr)
    assert "Traceback" not in r.stdout + r.stderr, r.stderr
    assert r.stderr.strip().startswith("error:"), r.stderr


@pytest.fixture(scope="module")
def artifact(tmp_path_factory):
    with pytest.MonkeyPatch.context() as mp:  # with its pictures: the attacks below go through them
        mp.setenv("RPG_SNAPSHOTS", "1")
        return compile_instruction("Stack the red block on top of the blue block.", tmp_path_factory.mktemp("a")).path


@pytest.fixture()
def task(artifact, tmp_path):
    d = tmp_path / "task"
    shutil.copytree(artifact, d)
    return d


# -- symlinks ------------------------------------------------------------------------------
def test_validate_never_writes_through_a_symlinked_log(task, tmp_path):
    rc = tmp_path / "bashrc"
    rc.write_text("# my shell rc\n")
    (task / "validation.log").unlink()
    (task / "validation.log").symlink_to(rc)
    r = rpg("validate", task)
    assert r.returncode == 0, r.stderr
    assert rc.read_text() == "# my shell rc\n"
    assert not (task / "validation.log").is_symlink() and "result: VALID" in (task / "validation.log").read_text()


def test_render_never_writes_through_symlinked_snapshots(task, tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("keep")
    (task / "initial.png").unlink()
    (task / "initial.png").symlink_to(victim)
    r = rpg("render", task)
    assert r.returncode == 0, r.stderr
    assert victim.read_text() == "keep" and not (task / "initial.png").is_symlink()


@pytest.mark.parametrize("fname", ["code.py", "goal_state_code.py", "task.yaml"])
def test_symlinked_artifact_inputs_are_refused(task, tmp_path, fname):
    real = tmp_path / f"real-{fname}"
    shutil.move(task / fname, real)
    (task / fname).symlink_to(real)
    r = rpg("validate", task)
    one_line_error(r)
    assert "symbolic link" in r.stderr


def test_report_never_copies_what_a_link_points_at(task, tmp_path):
    lib = tmp_path / "lib"
    lib.mkdir()
    shutil.move(task, lib / "t")
    (lib / "t" / "initial.png").unlink()
    (lib / "t" / "initial.png").symlink_to("/etc/passwd")
    r = rpg("report", lib, "-o", tmp_path / "site")
    assert r.returncode == 0, r.stderr
    published = b"".join(p.read_bytes() for p in (tmp_path / "site").rglob("*") if p.is_file())
    assert b"root:x:0:0" not in published


# -- names that become paths ----------------------------------------------------------------
@pytest.mark.parametrize("name", ["../../escaped", "/tmp/rpg-abs-escape", "a/b", ".."])
def test_traversal_names_in_sessions_are_refused(tmp_path, name):
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "s.yaml").write_text(yaml.safe_dump({"name": name, "steps": [{"instruction": "Stack two blocks."}]}))
    (tmp_path / "lib" / "manifest.yaml").write_text("entries:\n- name: fam\n  session: s.yaml\n")
    before = sorted(p.name for p in tmp_path.iterdir())
    r = rpg("session", "run", tmp_path / "lib" / "s.yaml", "-o", tmp_path / "out")
    one_line_error(r)
    assert "not a valid name" in r.stderr
    r = rpg("build", tmp_path / "lib" / "manifest.yaml", "--check")  # the entry's own name wins
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    assert not Path("/tmp/rpg-abs-escape").exists()
    assert "Traceback" not in r.stderr


# -- YAML alias bombs -----------------------------------------------------------------------
BOMB = "a: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
    f"{c}: &{c} [*{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}]\n" for p, c in zip("abcdefgh", "bcdefghi", strict=True))


def test_alias_bomb_in_task_yaml_is_refused_at_once(task):
    (task / "task.yaml").write_text(BOMB + (task / "task.yaml").read_text())
    t0 = time.monotonic()
    r = rpg("validate", task)
    one_line_error(r)
    assert "aliases are not allowed" in r.stderr and time.monotonic() - t0 < 20


def test_alias_bomb_in_family_yaml_is_refused_at_once(task):
    from rpg.steer.steering import steer

    steer(task, "make the top block green")
    (task / "family.yaml").write_text(BOMB + (task / "family.yaml").read_text())
    for cmd in (["verify", task], ["show", task], ["log", task]):
        one_line_error(rpg(*cmd))


# -- integrity ------------------------------------------------------------------------------
def test_verify_expect_catches_a_recomputed_forgery(task):
    from rpg.steer.steering import steer

    steer(task, "make the top block green")
    steer(task, "add a yellow block on top")
    trusted = Family(task).load().digest()
    assert rpg("verify", task, "--expect", trusted).returncode == 0
    hist = Family(task).load()
    hist.versions.pop()  # drop the newest version: every remaining hash still checks out
    hist.head = len(hist.versions) - 1
    Family(task).save(hist)
    shutil.rmtree(task / "v2")
    assert rpg("verify", task).returncode == 0, "self-consistent without a trusted hash"
    r = rpg("verify", task, "--expect", trusted)
    assert r.returncode == 1 and "differs from the expected" in r.stdout
    hist.head = 0  # a moved head is caught too
    Family(task).save(hist)
    assert verify_target(task, Family(task).load().digest())["ok"]
    assert not verify_target(task, trusted)["ok"]


def test_verify_covers_every_file_of_a_version(task, snapshots_on):
    from rpg.steer.steering import steer

    steer(task, "make the top block green")
    assert rpg("verify", task).returncode == 0
    (task / "v1" / "goal.png").write_bytes(b"\x89PNG forged")
    r = rpg("verify", task)
    assert r.returncode == 1 and "goal.png" in r.stdout
    (task / "v1" / "goal.png").unlink()
    (task / "v0" / "validation.log").write_text("result: VALID\n")
    r = rpg("verify", task, "--json")
    report = json.loads(r.stdout)
    assert r.returncode == 1 and not report["versions"][0]["ok"] and not report["versions"][1]["ok"]


def test_verify_reports_invalid_utf8_instead_of_crashing(task):
    from rpg.steer.steering import steer

    steer(task, "make the top block green")
    (task / "v1" / "code.py").write_bytes(b"\xff\xfe not utf-8")
    r = rpg("verify", task)
    assert r.returncode == 1 and "not UTF-8" in r.stdout and "Traceback" not in r.stderr


def test_code_hash_is_over_the_code_bytes(task):
    from rpg.steer.family import code_hash
    from rpg.steer.steering import steer

    steer(task, "make the top block green")
    v1 = Family(task).load().versions[1]
    code = (task / "v1" / "code.py").read_text()
    assert v1.code_hash == code_hash({"code.py": code, "goal_state_code.py": (task / "v1" / "goal_state_code.py").read_text()})
    assert v1.task_hash and v1.task_hash != v1.code_hash


def test_build_check_catches_an_edit_to_the_committed_library(tmp_path):
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "manifest.yaml").write_text("entries:\n- name: stack_blocks\n  instruction: Stack two blocks on top of each other.\n")
    assert rpg("build", lib / "manifest.yaml").returncode == 0
    assert rpg("build", lib / "manifest.yaml", "--check").returncode == 0
    code = lib / "stack_blocks" / "code.py"
    code.write_text(code.read_text() + "\n# an innocent-looking edit\n")
    r = rpg("build", lib / "manifest.yaml", "--check")
    assert r.returncode == 1 and "committed library" in r.stdout


# -- concurrency and crashes ----------------------------------------------------------------
# one process imports rpg, then forks the two steers of each trial at once: a fresh interpreter
# per steer spent as long importing as steering
_FORKED_STEERS = """\
import os, sys, traceback
from rpg.steer.steering import steer
edits, dirs = sys.argv[1:3], sys.argv[3:]
for d in dirs:
    pids = []
    for e in edits:
        pid = os.fork()
        if pid == 0:
            code = 0
            try:
                print(d, steer(d, e).version, flush=True)
            except BaseException:
                traceback.print_exc()
                code = 1
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(code)
        pids.append(pid)
    codes = [os.waitstatus_to_exitcode(os.waitpid(p, 0)[1]) for p in pids]
    if any(codes):
        sys.exit(f"{d}: the steers exited with {codes}")
"""


@pytest.mark.slow
def test_concurrent_first_steers_lose_no_edit(artifact, tmp_path):
    """Two processes steer the same plain artifact at once (its first steer makes it a
    family): both edits end up as versions, in 8 trials.  Each trial's two are forked from one
    process that imported rpg once (no state of a steer: it has run none)."""
    edits = ["make the top block green", "make the bottom block yellow"]
    dirs = [tmp_path / f"t{trial}" for trial in range(8)]
    for d in dirs:
        shutil.copytree(artifact, d)
    r = subprocess.run([sys.executable, "-c", _FORKED_STEERS, *edits, *map(str, dirs)], capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    assert sorted(r.stdout.splitlines()) == sorted(f"{d} {v}" for d in dirs for v in (1, 2)), r.stdout + r.stderr
    for trial, d in enumerate(dirs):
        hist = Family(d).load()
        assert sorted(v.description for v in hist.versions[1:]) == sorted(edits), (trial, r.stdout, r.stderr)
        assert all(v["ok"] for v in Family(d).verify())


def test_a_steer_waits_while_another_first_steer_moves_the_artifact(artifact, tmp_path):
    """The moment of the race above, made to last: while one steer holds the family lock and
    has moved the plain artifact out of its path (turning it into v0), a second steer waits
    for the lock and then steers the family; it does not fail on the half-moved artifact."""
    from filelock import FileLock

    from rpg.steer.family import create_family

    d = tmp_path / "t"
    shutil.copytree(artifact, d)
    script = ("import sys\nfrom rpg.steer.steering import steer\nprint('ready', flush=True)\n"
              "r = steer(sys.argv[1], sys.argv[2])\nprint(r.version)\n")
    with FileLock(str(d.parent / f".{d.name}.family.lock")):
        aside = tmp_path / "aside"
        d.rename(aside)
        proc = subprocess.Popen([sys.executable, "-c", script, str(d), "make the top block green"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert proc.stdout.readline().strip() == "ready"
        time.sleep(1.5)
        assert proc.poll() is None, proc.stderr.read()  # waiting for the lock, not failed
        aside.rename(d)
        create_family(d)
    out, err = proc.communicate(timeout=300)
    assert proc.returncode == 0, err
    assert [v.description for v in Family(d).load().versions[1:]] == ["make the top block green"]


def _descendants(pid: int) -> set[int]:
    kids: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                ppid = int(open(f"/proc/{entry}/stat").read().rsplit(")", 1)[1].split()[1])
            except (OSError, ValueError, IndexError):
                continue
            kids.setdefault(ppid, []).append(int(entry))
    out, todo = set(), [pid]
    while todo:
        for k in kids.get(todo.pop(), []):
            out.add(k)
            todo.append(k)
    return out


def _alive(pid: int) -> bool:
    try:
        stat = open(f"/proc/{pid}/stat").read()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


@pytest.mark.slow
def test_kill_9_of_build_leaves_no_process(tmp_path):
    lib = tmp_path / "lib"
    lib.mkdir()
    entries = "".join(f"- name: t{i}\n  instruction: Stack {n} blocks.\n" for i, n in enumerate(["two", "three", "four", "five"]))
    (lib / "manifest.yaml").write_text("entries:\n" + entries)
    build = subprocess.Popen([*RPG, "build", str(lib / "manifest.yaml"), "--jobs", "2"], stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 60
    family: set[int] = set()
    while time.monotonic() < deadline and len(family) < 4:  # workers, template, its sandbox
        family |= _descendants(build.pid)
        time.sleep(0.2)
    assert len(family) >= 3, "the build should have started its workers and fork-server template"
    build.send_signal(signal.SIGKILL)
    build.wait()
    family |= _descendants(build.pid)
    time.sleep(5)
    left = sorted(p for p in family if _alive(p))
    assert not left, f"processes left 5 s after kill -9 of rpg build: {left}"


def test_stale_build_directories_are_removed_at_start(tmp_path):
    from rpg.library.build import remove_stale_temporaries

    old = tmp_path / ".rpg-build-dead"
    new = tmp_path / ".tmp-live-x"
    for d in (old, new):
        d.mkdir()
    os.utime(old, (time.time() - 7 * 3600,) * 2)
    assert remove_stale_temporaries(tmp_path) == [".rpg-build-dead"]
    assert new.exists() and not old.exists()


# -- every subcommand, bad arguments --------------------------------------------------------
@pytest.fixture(scope="module")
def junk(tmp_path_factory):
    d = tmp_path_factory.mktemp("junk")
    (d / "afile").write_text("hi\n")
    (d / "binary").write_bytes(bytes(range(256)) * 2)
    (d / "deep.json").write_text("[" * 100000 + "]" * 100000)
    (d / "listinstr.yaml").write_text("name: s\nsteps:\n  - instruction: [a, b]\n")
    (d / "noname.yaml").write_text("steps: 3\n")
    return d


SWEEP = [
    ("compile", "stack two blocks", "-o", "{junk}/afile"),
    ("compile", "", "-o", "{out}"),
    ("compile", "stack two blocks", "--seed", "-3", "-o", "{out}"),
    ("compile", "stack two blocks", "--disable", "bogus", "-o", "{out}"),
    ("compile", "\udcff\udcfe", "-o", "{out}"),
    ("compile", "--replay", "{junk}/deep.json", "-o", "{out}"),
    ("compile", "--replay", "{junk}/binary", "-o", "{out}"),
    ("steer", "{junk}/binary", "make it red"),
    ("steer", "{junk}/nonexistent", "make it red"),
    ("steer", "{task}", ""),
    ("log", "{junk}/binary"),
    ("show", "{task}@v99"),
    ("show", "{junk}/afile@v1"),
    ("verify", "{junk}/binary"),
    ("build", "{junk}/binary"),
    ("build", "{junk}/afile"),
    ("build", "{junk}/deep.json"),
    ("build", "{lib}/manifest.yaml", "--jobs", "0"),
    ("report", "{junk}/binary", "-o", "{out}"),
    ("report", "{lib}", "-o", "{junk}/afile"),
    ("session", "run", "{junk}/listinstr.yaml", "-o", "{out}"),
    ("session", "run", "{junk}/noname.yaml", "-o", "{out}"),
    ("session", "run", "{junk}/binary", "-o", "{out}"),
    ("validate", "{task}", "--disable", "bogus"),
    ("validate", "{junk}"),
    ("inspect", "{task}", "--settle", "-1"),
    ("inspect", "{task}", "--state", "bogus"),
    ("check", "{task}", "--poses", "{junk}/deep.json"),
    ("check", "{task}", "--poses", "{junk}/binary"),
    ("check", "{task}", "--poses", "{junk}/afile"),
    ("render", "{junk}/afile"),
    ("render", "{task}", "--seed", "-1"),
    ("diversity", "{junk}/binary"),
    ("diversity", "{lib}", "--by", "bogus"),
    ("schema", "-o", "{junk}"),
]


@pytest.mark.parametrize("args", SWEEP, ids=[" ".join(a)[:60] for a in SWEEP])
def test_bad_arguments_exit_2_with_one_line_and_write_nothing(args, junk, artifact, tmp_path):
    task = tmp_path / "task"
    shutil.copytree(artifact, task)
    lib = ROOT / "library"
    before = {p: p.stat().st_mtime_ns for p in [*junk.iterdir(), *task.iterdir()]}
    out = tmp_path / "out"
    argv = [a.format(junk=junk, task=task, lib=lib, out=out) for a in args]
    r = subprocess.run([*RPG, *argv], capture_output=True, timeout=300, env={**os.environ, "COLUMNS": "200"},
                       cwd=tmp_path)
    stderr = r.stderr.decode("utf-8", "replace")
    assert r.returncode == 2, (argv, r.returncode, stderr[-2000:])
    assert "Traceback" not in stderr and stderr.strip().startswith(("error:", "Usage:")), stderr[-2000:]
    assert not out.exists(), "nothing may be written on bad input"
    assert {p: p.stat().st_mtime_ns for p in [*junk.iterdir(), *task.iterdir()]} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["task"]


def test_disk_full_exits_4_with_one_line(tmp_path, snapshots_on):  # (without its pictures a task fits in 24 KB)
    """A compile onto a full file system (a 24 KB tmpfs in a private mount namespace) ends
    with one line and exit 4, and no half-written artifact."""
    probe = subprocess.run(["unshare", "--mount", "true"], capture_output=True)
    if probe.returncode != 0:
        pytest.skip("needs mount namespaces (unshare --mount) to make a small file system")
    mnt = tmp_path / "small"
    mnt.mkdir()
    cmd = (f"mount -t tmpfs -o size=24k tmpfs {mnt} && {sys.executable} -m rpg.cli compile 'stack two blocks' "
           f"-o {mnt}/out; rc=$?; find {mnt} -type f; exit $rc")
    r = subprocess.run(["unshare", "--mount", "sh", "-c", cmd], capture_output=True, text=True, timeout=300)
    assert r.returncode == 4, (r.stdout, r.stderr)
    assert r.stderr.strip().splitlines() == ["error: No space left on device"], r.stderr
    assert r.stdout.strip() == "", f"files left on the full disk: {r.stdout}"
