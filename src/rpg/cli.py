"""The ``rpg`` command line: a thin layer over :mod:`rpg.compiler`.

Exit codes: 0 success; 1 validation failed after repair; 2 bad input or usage;
3 model provider error.
"""

from __future__ import annotations

import json
import os
import shutil
import sys
from contextlib import contextmanager
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.markup import escape as esc

from rpg._version import __version__
from rpg.errors import EXIT_BAD_INPUT, EXIT_INVALID, EXIT_OK, EXIT_SYSTEM

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    help=(
        "rpg: compile natural-language instructions into reproducible MuJoCo block-manipulation tasks.\n\n"
        "Exit codes: 0 success, 1 validation failed after repair, 2 bad input or usage, 3 model provider error."
    ),
)
out = Console()
err = Console(stderr=True)


def _fail(message: str, code: int = EXIT_BAD_INPUT) -> None:
    err.print(f"[bold red]error:[/] {esc(' '.join(str(message).split()))}", highlight=False, soft_wrap=True)
    raise typer.Exit(code)


def _version(value: bool) -> None:
    if value:
        out.print(f"rpg {__version__}")
        raise typer.Exit()


@app.callback()
def main_options(
    version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True, help="Show the version.")] = False,
) -> None:
    """rpg command line."""


@contextmanager
def _reported_errors():
    """Map the API's errors to one line and an exit code: every :class:`rpg.errors.RpgError`
    carries its own (see :mod:`rpg.errors`); any other ``ValueError`` is bad input (2), an
    ``OSError`` (disk full, permission denied) a failure of the machine (4)."""
    from rpg.errors import RpgError

    try:
        yield
    except RpgError as exc:
        _fail(str(exc), exc.exit_code)
    except ValueError as exc:
        _fail(str(exc))
    except OSError as exc:  # disk full, permissions: the machine, not the input
        where = f": {exc.filename}" if exc.filename else ""
        _fail(f"{exc.strerror or exc}{where}", EXIT_SYSTEM)


def default_author(author: str | None) -> str | None:
    """Who is authoring: ``--author``, else ``RPG_AUTHOR``, else git's ``user.name``, else None."""
    if author:
        return author
    if os.environ.get("RPG_AUTHOR"):
        return os.environ["RPG_AUTHOR"]
    import subprocess

    try:
        name = subprocess.run(["git", "config", "user.name"], capture_output=True, text=True, timeout=5).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return None
    return name or None


AUTHOR_HELP = "Who wrote it (recorded in task.yaml provenance); default RPG_AUTHOR, else git's user.name."

BackendOption = Annotated[str, typer.Option("--backend", help="Where the work runs: local (a process pool of --jobs "
                                                               "workers) or ray (Ray tasks; 'pip install rpg[ray]').")]
AddressOption = Annotated[str | None, typer.Option("--address", help="With --backend ray: a running Ray cluster ('auto' "
                                                                     "or HOST:PORT); default a local Ray with --jobs CPUs.")]

GATE_HELP = ("Run an optional gate too: solvable (the oracle must solve 3 of 5 episodes with the floating "
             "gripper; rpg build always runs it).")


def make_llm_client(model: str | None):
    """The model client for ``--model`` (None for the builtin front end); tests replace it
    with a client that holds litellm mock responses."""
    if model in (None, "builtin"):
        return None
    from rpg.schema.llm import LLMClient

    return LLMClient(model)


@app.command("compile")
def compile_cmd(
    instruction: Annotated[str, typer.Argument(help="The task, in plain language.")],
    output: Annotated[Path, typer.Option("-o", "--output", help="Library directory to write the task into.")] = Path("out"),
    seed: Annotated[int, typer.Option("--seed", min=0, help="Seed of the episode shown in the snapshots and checks.")] = 0,
    model: Annotated[str | None, typer.Option("--model", help="'builtin' (default) or a litellm model name.")] = None,
    disable: Annotated[list[str], typer.Option("--disable", help="Switch a gate off (ablation).")] = [],  # noqa: B006
    gate: Annotated[list[str], typer.Option("--gate", help=GATE_HELP)] = [],  # noqa: B006
    family: Annotated[bool, typer.Option("--family", help="Start a task family: the task becomes its v0.")] = False,
    replay: Annotated[Path | None, typer.Option("--replay", help="Recompile offline from an artifact's llm_log.jsonl.")] = None,
    builtin_first: Annotated[bool, typer.Option("--builtin-first", help="With --model: ask the model only for what the builtin parser cannot read.")] = False,
    codegen: Annotated[str, typer.Option("--codegen", help="builtin (the emitter) or llm (the model writes the code; needs --model).")] = "builtin",
    library: Annotated[Path, typer.Option("--library", help="Task library that --codegen llm retrieves reference tasks from.")] = Path("library"),
    as_json: Annotated[bool, typer.Option("--json", help="Print one JSON document.")] = False,
    author: Annotated[str | None, typer.Option("--author", help=AUTHOR_HELP)] = None,
) -> None:
    """Compile INSTRUCTION into a validated task artifact OUTPUT/<slug>/."""
    from rpg.validate.sandbox import prepare

    prepare()  # the validation child starts up while the compiler is imported
    from rpg.compiler import compile_instruction

    _freeze_imports()

    model = model or os.environ.get("RPG_MODEL") or None
    with _reported_errors():
        result = compile_instruction(instruction, output, seed, frozenset(disable), model, replay=replay,
                                     builtin_first=builtin_first, llm=make_llm_client(model), codegen=codegen,
                                     library=library, author=default_author(author), enabled=frozenset(gate))
        if family and result.valid:
            from rpg.steer.family import create_family

            create_family(result.path)
            result.path = result.path / "v0"
    if as_json:
        print(json.dumps(result.to_json(), indent=2))
    else:
        _print_compile(result)
        if family and result.valid:
            out.print(f"family:    {result.path.parent}")
    raise typer.Exit(EXIT_OK if result.valid else EXIT_INVALID)


def _print_compile(result) -> None:
    status = "[green]valid[/]" if result.valid else "[red]rejected[/]"
    out.print(f"{status} task [bold]{result.schema.name}[/]: {esc(result.schema.goal_summary)}", highlight=False)
    for g in result.gates:
        mark = {"pass": "[green]pass[/]", "fail": "[red]FAIL[/]", "skipped": "[yellow]skip[/]"}[g["status"]]
        out.print(f"  {g['gate']:<11} {mark} {esc(g.get('message', ''))}", highlight=False)
    for r in result.schema.repairs:
        out.print(f"  repair {r.operator}: {esc(r.reason)}", highlight=False)
    for what, why in result.set_aside:  # what the task does not hold, said where the user looks
        out.print(f"set aside: {esc(repr(what))} ({esc(why)})", highlight=False)
    out.print(f"artifact:  {result.path}")
    for k in ("initial", "goal"):
        if (result.path / f"{k}.png").exists():
            out.print(f"snapshot:  {result.path / (k + '.png')}")


@app.command("steer")
def steer_cmd(
    family: Annotated[Path, typer.Argument(help="A task family (or a compiled task, which becomes v0 of one).")],
    edit: Annotated[str, typer.Argument(help="The change, in plain language.")] = "",
    seed: Annotated[int | None, typer.Option("--seed", min=0, help="Seed of the checks (default: the family's).")] = None,
    model: Annotated[str | None, typer.Option("--model", help="'builtin' (default) or a litellm model name.")] = None,
    replay: Annotated[Path | None, typer.Option("--replay", help="Re-apply a recorded model edit (llm_log.jsonl) offline.")] = None,
    disable: Annotated[list[str], typer.Option("--disable", help="Switch a gate off (ablation).")] = [],  # noqa: B006
    gate: Annotated[list[str], typer.Option("--gate", help=GATE_HELP)] = [],  # noqa: B006
    as_json: Annotated[bool, typer.Option("--json", help="Print one JSON document.")] = False,
    author: Annotated[str | None, typer.Option("--author", help=AUTHOR_HELP)] = None,
    dry_run: Annotated[bool, typer.Option("--dry-run", help="Read and classify the edit and check its task; "
                                          "build and record nothing.")] = False,
) -> None:
    """Classify EDIT, pick the version it builds on, recompile and record a new version."""
    from rpg.steer import steer

    model = model or os.environ.get("RPG_MODEL") or None
    with _reported_errors():
        r = steer(family, edit, seed, frozenset(disable), llm=make_llm_client(model) if replay is None else None,
                  replay=replay, author=default_author(author), enabled=frozenset(gate), dry_run=dry_run)
    doc = r.to_json()
    if dry_run:
        from rpg.schema.meaning import meaning

        doc.update(goal=r.schema.goal_summary, meaning=meaning(r.schema))
    if as_json:
        print(json.dumps(doc, indent=2))
    else:
        ref = "none" if r.reference is None else f"v{r.reference}"
        dry = " (dry run: nothing built or recorded)" if dry_run else ""
        out.print(f"intent [bold]{r.intent}[/], reference {ref}{dry}", highlight=False)
        for note in r.notes:
            out.print(f"  {esc(note)}", highlight=False)
        out.print(f"  instruction: {esc(r.instruction)}", highlight=False)
        if dry_run:
            out.print(f"  goal: {esc(r.schema.goal_summary)}", highlight=False)
        if r.compile is not None:
            _print_compile(r.compile)
        if r.valid:
            out.print(f"[green]{'reused' if r.reused else 'recorded'}[/] v{r.version} in {r.family}", highlight=False)
    if dry_run:
        raise typer.Exit(EXIT_OK)
    raise typer.Exit(EXIT_OK if r.valid else EXIT_INVALID)


def _family(path: Path):
    from rpg.steer.family import Family

    fam = Family(path)
    with _reported_errors():
        return fam, fam.load()


@app.command("log")
def log_cmd(
    family: Annotated[Path, typer.Argument(help="A task family.")],
    as_json: Annotated[bool, typer.Option("--json")] = False,
) -> None:
    """Print a family's history as a tree of versions."""
    from rich.tree import Tree

    _, hist = _family(family)
    if as_json:
        print(json.dumps(hist.model_dump(), indent=2))
        return
    children: dict[int | None, list] = {}
    for v in hist.versions:
        children.setdefault(v.parent, []).append(v)

    def label(v) -> str:
        head = " [bold cyan](head)[/]" if v.version_id == hist.head else ""
        return (f"[bold]v{v.version_id}[/] {v.lineage_hash[:10]} [magenta]{v.intent}[/]{head}: {esc(v.description)}\n"
                f"[dim]{esc(v.goal_summary)}[/]")

    tree = Tree(f"[bold]{hist.name}[/] ({len(hist.versions)} versions)")

    def add(node, parent):
        for v in children.get(parent, []):
            add(node.add(label(v)), v.version_id)

    add(tree, None)
    out.print(tree, highlight=False)


@app.command("verify")
def verify_cmd(
    target: Annotated[Path, typer.Argument(help="A task family or a task artifact.")],
    expect: Annotated[str | None, typer.Option("--expect", help="The trusted hash (e.g. the library manifest's) it must have.")] = None,
    as_json: Annotated[bool, typer.Option("--json")] = False,
) -> None:
    """Recompute every hash of a family (every version's files, the history, head and name) or
    of a task artifact; exit 1 if anything was altered or differs from --expect."""
    from rpg.steer.family import verify_target

    with _reported_errors():
        report = verify_target(target, expect)
    if as_json:
        print(json.dumps(report, indent=2))
    else:
        for r in report["versions"]:
            mark = "[green]ok[/]" if r["ok"] else "[red]ALTERED[/]"
            out.print(f"v{r['version']:<3} {mark} {esc('; '.join(r['problems']))}", highlight=False)
        for p in report["problems"]:
            out.print(f"[red]ALTERED[/] {esc(p)}", highlight=False)
        out.print(f"{report['kind']} hash {report['hash']}", highlight=False)
    raise typer.Exit(EXIT_OK if report["ok"] else EXIT_INVALID)


@app.command("show")
def show_cmd(
    target: Annotated[str, typer.Argument(help="FAMILY@v3, FAMILY@<hash prefix> or FAMILY (the head).")],
    as_json: Annotated[bool, typer.Option("--json")] = False,
) -> None:
    """Resolve and print one version of a family."""
    path, _, ref = target.rpartition("@") if "@" in target else (target, "", "")
    fam, _ = _family(Path(path))
    with _reported_errors():
        v = fam.resolve(ref or None)
    doc = {**v.model_dump(), "path": str(fam.version_dir(v.version_id))}
    if as_json:
        print(json.dumps(doc, indent=2))
        return
    for k, val in doc.items():
        out.print(f"{k:<18} {esc(str(val))}", highlight=False)


@app.command("build")
def build_cmd(
    manifest: Annotated[Path, typer.Argument(help="A library manifest (library/manifest.yaml).")],
    jobs: Annotated[int, typer.Option("--jobs", "-j", min=1, help="Parallel workers.")] = 1,
    backend: BackendOption = "local",
    address: AddressOption = None,
    check: Annotated[bool, typer.Option("--check", help="Regenerate in a temporary directory; exit 1 if any hash differs.")] = False,
    report: Annotated[Path | None, typer.Option("--json", help="Write a JSON report here.")] = None,
    force: Annotated[bool, typer.Option("--force", help="Rewrite entries whose hash did not change too (e.g. to refresh snapshots).")] = False,
) -> None:
    """Compile and steer every manifest entry in parallel (or check that they regenerate unchanged).

    Entries the library already holds with the same hash keep their files, unless --force.
    """
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
    from rich.table import Table

    from rpg.library import build_library, load_manifest

    if jobs < 1:
        _fail("--jobs must be at least 1")
    with _reported_errors():
        total = len(load_manifest(manifest).entries)
        with Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                      console=err, transient=True) as bar:
            task = bar.add_task("check" if check else "build", total=total)
            reports, seconds = build_library(manifest, jobs, backend, check, address, force=force,
                                             progress=lambda r: bar.update(task, advance=1, description=r["name"]))
    changed = [r for r in reports if r["changed"]]
    failed = [r for r in reports if r["status"] != "valid"]
    table = Table(title=f"{'check' if check else 'build'} {manifest}")
    cols = ("entries", "valid", "repaired", "rejected", "changed", *(() if check else ("written",)), "time")
    for col in cols:
        table.add_column(col)
    table.add_row(str(len(reports)), str(sum(r["status"] == "valid" for r in reports)),
                  str(sum(bool(r.get("repairs")) for r in reports)), str(len(failed)), str(len(changed)),
                  *(() if check else (str(sum(r.get("written", False) for r in reports)),)), f"{seconds:.1f} s")
    out.print(table)
    for r in failed:
        out.print(f"[red]{r['status']}[/] {r['name']}: {esc(r.get('error') or '; '.join(r.get('problems') or []) or 'validation failed')}")
    for r in reports:
        for gate_name, why in sorted((r.get("waived") or {}).items()):
            out.print(f"[yellow]waived[/] {r['name']}: gate {gate_name} ({esc(why)})", highlight=False)
    if check:
        for r in changed:
            why = "; ".join(r.get("problems") or []) if r.get("content_hash") == r["expected"] else ""
            out.print(f"[red]changed[/] {r['name']}: expected {r['expected']}, got {r.get('content_hash')}"
                      + (f" ({esc(why)})" if why else ""), highlight=False)
    if report is not None:
        report.write_text(json.dumps({"manifest": str(manifest), "check": check, "seconds": seconds, "entries": reports}, indent=2))
    raise typer.Exit(EXIT_INVALID if failed or (check and changed) else EXIT_OK)


@app.command("report")
def report_cmd(
    library: Annotated[Path, typer.Argument(help="A library directory (tasks and families), or an rpg eval run directory.")],
    output: Annotated[Path, typer.Option("-o", "--output", help="Site directory to write.")] = Path("site"),
    diversity: Annotated[str | None, typer.Option("--diversity", help="Add a diversity page grouped by author, family or tag:KEY.")] = None,
    runs: Annotated[list[Path] | None, typer.Option("--eval", help="An rpg eval run directory: its page, and its success rate on each task's card (repeatable).")] = None,
) -> None:
    """Write a static HTML gallery: one card per task and family version; for an `rpg eval` run
    directory, its evaluation page (table, chart with error bars, videos, failed predicates)."""
    from rpg.eval.report import is_run_dir, write_eval_report
    from rpg.library.report import write_report

    with _reported_errors():
        if is_run_dir(library):
            page = write_eval_report(library, output)
        else:
            page = write_report(library, output, diversity=diversity, runs=runs or [])
    out.print(f"wrote {page}")


WristSupersampleOption = Annotated[str, typer.Option(
    "--wrist-supersample", metavar="1|2",
    help="Draw the wrist camera at this many times the image size per side and average each block "
         "back (1: off, the default; 2: anti-aliased wrist shadows, in a renderer of its own: the other "
         "cameras' images are unchanged; on a software renderer about half the steps/s with cameras, "
         "see the README).")]


def _integer_or_text(value: str) -> int | str:
    """An option's decimal integer as an int; anything else as given, for the API to refuse in
    one line (a typed option would be refused by the parser in a box of several lines)."""
    text = value.strip()
    return int(text) if text.isdecimal() and text.isascii() else value


def _parse_seeds(episodes: int | None, seeds: str | None) -> tuple[int, ...]:
    if episodes is not None and seeds is not None:
        _fail("give --episodes N or --seeds LIST, not both")
    if seeds is None:
        return tuple(range(episodes if episodes is not None else 20))
    out = []
    for part in seeds.split(","):
        lo, dash, hi = part.strip().partition("-")
        if not (lo.isdigit() and (not dash or hi.isdigit())):
            _fail(f"--seeds takes non-negative integers and ranges like 0-9,20, not {seeds!r}")
        out += list(range(int(lo), int(hi) + 1)) if dash else [int(lo)]
    if not out or len(set(out)) != len(out):
        _fail(f"--seeds must list distinct seeds, got {seeds!r}")
    return tuple(out)


@app.command("eval", context_settings={"allow_interspersed_args": True})
def eval_cmd(
    target: Annotated[str, typer.Argument(help="A task, family (all versions), FAMILY@vN, manifest or KEY=VALUE filter; "
                                               "or 'compare' followed by two run directories.")],
    runs: Annotated[list[Path] | None, typer.Argument(help="With 'compare': RUN_A RUN_B.")] = None,
    policy: Annotated[str, typer.Option("--policy", help="oracle, random, noop, module:Class, file.py:Class or ws://host:port.")] = "oracle",
    episodes: Annotated[int | None, typer.Option("--episodes", "-n", min=1, help="Seeds 0..N-1 per task (default 20).")] = None,
    seeds: Annotated[str | None, typer.Option("--seeds", help="Seeds, e.g. 0-9,42.")] = None,
    embodiment: Annotated[str, typer.Option("--embodiment", help="panda or floating_gripper.")] = "panda",
    instruction: Annotated[str, typer.Option("--instruction", help="original (as written), canonical (G stated "
                                                                  "exactly), paraphrase:K or all.")] = "original",
    allow_unstated: Annotated[bool, typer.Option("--allow-unstated", help="Score tasks whose sent instruction does not "
                                                 "state every constraint G checks (recorded in summary.json).")] = False,
    jobs: Annotated[int, typer.Option("--jobs", "-j", min=1, help="Episodes run at once (processes, or a local Ray's CPUs).")] = 1,
    backend: BackendOption = "local",
    address: AddressOption = None,
    video: Annotated[bool, typer.Option("--video", help="Write an agentview MP4 per episode.")] = False,
    replan: Annotated[int | None, typer.Option("--replan", min=1, help="Actions of a chunk executed before asking again.")] = None,
    cameras: Annotated[str | None, typer.Option("--cameras", help="Comma-separated camera observations (default: none for built-ins, agentview,wrist otherwise).")] = None,
    image_size: Annotated[int, typer.Option("--image-size", min=16, max=2048, help="Square camera observations, pixels.")] = 224,
    library: Annotated[Path, typer.Option("--library", help="Manifest a KEY=VALUE filter selects from.")] = Path("library/manifest.yaml"),
    output: Annotated[Path | None, typer.Option("-o", "--output", help="Run directory (created; resumed if it holds the same run).")] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print the summary (or comparison) as JSON.")] = False,
    control_mode: Annotated[str, typer.Option("--control-mode", help="ee_delta, ee_abs or joint_pos (Panda).")] = "ee_delta",
    inference_timeout: Annotated[float, typer.Option("--inference-timeout", help="Seconds one policy call may take.")] = 30.0,
    episode_timeout: Annotated[float, typer.Option("--episode-timeout", help="Seconds one episode may take.")] = 600.0,
    fail_fast: Annotated[bool, typer.Option("--fail-fast", help="Stop at the first episode whose policy fails.")] = False,
    allow_mismatch: Annotated[bool, typer.Option("--allow-mismatch", help="compare: compare runs whose settings or "
                                                 "task contents differ (the output says so).")] = False,
    visual: Annotated[str, typer.Option("--visual", help="The robot's meshes in the images: decimated (default) or "
                                                         "stock (the Menagerie's); recorded in run.json and each "
                                                         "episode's record.")] = "decimated",
    wrist_supersample: WristSupersampleOption = "1",
) -> None:
    """Run a policy on tasks: success and progress per task, family version, steering intent and
    split, with standard errors and Wilson 95% intervals.  An episode whose policy fails or times
    out is kept with its error and counts as a failure.  `rpg eval compare RUN_A RUN_B` tests
    differences (McNemar paired, Fisher unpaired, Holm-corrected)."""
    from rpg.eval import EvalConfig, run_eval

    if target == "compare":
        _eval_compare(runs or [], as_json, allow_mismatch)
        return
    if runs:
        _fail(f"unexpected argument {runs[0]}; rpg eval takes one TARGET (or: rpg eval compare RUN_A RUN_B)")
    if output is None:
        _fail("give -o RUN_DIR for the run's episodes.jsonl and summary.json")
    cams = None if cameras is None else tuple(c for c in cameras.split(",") if c)
    config = EvalConfig(target=target, policy=policy, seeds=_parse_seeds(episodes, seeds), embodiment=embodiment,
                        instruction=instruction, cameras=cams, image_size=(image_size, image_size), replan=replan,
                        video=video, library=str(library), control_mode=control_mode,
                        inference_timeout=inference_timeout, episode_timeout=episode_timeout,
                        allow_unstated=allow_unstated, visual=visual,
                        wrist_supersample=_integer_or_text(wrist_supersample))
    from rich.progress import Progress

    with _reported_errors(), Progress(console=err, transient=True) as bar:
        tick = bar.add_task("episodes", total=None)
        summary = run_eval(config, output, jobs=jobs, progress=lambda rec: bar.advance(tick), fail_fast=fail_fast,
                           backend=backend, address=address)
    if as_json:
        print(json.dumps(summary, indent=2, sort_keys=True))
        return
    from rich.table import Table

    table = Table(title=f"{esc(policy)} on {esc(target)} ({embodiment})")
    for col in ("task", "success", "stderr", "95% Wilson", "progress", "n", "errors", "latency p50/p95"):
        table.add_column(col, justify="left" if col == "task" else "right")
    for name, r in summary["tasks"].items():
        t = summary["timing"].get(name, {})
        lat = ("-" if t.get("latency_median_s") is None else
               f"{1000 * t['latency_median_s']:.0f}/{1000 * t['latency_p95_s']:.0f} ms")
        table.add_row(esc(name), f"{100 * r['mean']:.1f}%", f"{100 * r['stderr']:.1f}",
                      f"{100 * r['wilson95'][0]:.0f}-{100 * r['wilson95'][1]:.0f}%",
                      f"{100 * r['progress']:.0f}% ± {100 * r['progress_stderr']:.0f}", str(r["n"]), str(r["errors"]), lat)
    o, ot = summary["overall"], summary["over_tasks"]
    table.add_row("[bold]overall[/]", f"{100 * o['mean']:.1f}%", f"{100 * o['stderr']:.1f}",
                  f"{100 * o['wilson95'][0]:.0f}-{100 * o['wilson95'][1]:.0f}%",
                  f"{100 * o['progress']:.0f}% ± {100 * o['progress_stderr']:.0f}", str(o["n"]), str(o["errors"]), "")
    out.print(table)
    out.print(f"mean over {ot['tasks']} tasks: success {100 * ot['mean']:.1f}% ± {100 * ot['stderr']:.1f}, "
              f"progress {100 * ot['progress']:.1f}% ± {100 * ot['progress_stderr']:.1f} (standard error over tasks)",
              highlight=False)
    for e in summary["errors"][:10]:
        out.print(f"error: {esc(e['task'])} seed {e['seed']} ({e['instruction_variant']}): {esc(e['error'])}",
                  highlight=False)
    if len(summary["errors"]) > 10:
        out.print(f"... and {len(summary['errors']) - 10} more episodes with errors (summary.json)", highlight=False)
    for group in ("intents", "splits"):
        parts = [f"{k} {100 * r['mean']:.0f}% (n {r['n']})" for k, r in summary[group].items() if k != "none"]
        if parts:
            out.print(f"per {group[:-1]}: " + ", ".join(parts), highlight=False)
    out.print(f"run: {output}")


def _eval_compare(runs: list[Path], as_json: bool, allow_mismatch: bool = False) -> None:
    from rpg.eval.runner import read_episodes
    from rpg.eval.stats import SIGNIFICANCE, compare_runs, mismatches

    if len(runs) != 2:
        _fail("rpg eval compare takes two run directories: RUN_A RUN_B")
    docs, episodes = [], []
    for r in runs:
        try:
            docs.append(json.loads((r / "summary.json").read_text()))
        except (OSError, ValueError):
            _fail(f"{r} holds no readable summary.json (an rpg eval run directory)")
        if "task_hashes" not in docs[-1]:
            _fail(f"{r}'s summary.json was written by an older rpg (no task hashes); run rpg eval on it again to "
                  "update it")
        episodes.append(read_episodes(r / "episodes.jsonl") if (r / "episodes.jsonl").is_file() else [])
    differ = mismatches(*docs)
    if differ and not allow_mismatch:
        _fail(f"the runs differ in {'; '.join(differ)}: their numbers are not comparable (--allow-mismatch compares "
              "them anyway)")
    result = compare_runs(docs[0], docs[1], episodes[0], episodes[1])
    result["mismatch_overridden"] = differ
    seeds = [d["config"].get("seeds") for d in docs]
    result["same_seeds"] = seeds[0] == seeds[1]
    if as_json:
        print(json.dumps(result, indent=2))
        return
    from rich.table import Table

    table = Table(title=f"{esc(str(runs[0]))} (A) vs {esc(str(runs[1]))} (B)")
    for col in ("task", "A", "B", "B - A", "progress B - A", "test", "p", "p (Holm)", ""):
        table.add_column(col, justify="left" if col == "task" else "right")

    def cell(r: dict | None) -> str:
        return "-" if r is None else f"{r['successes']}/{r['n']} ({100 * r['mean']:.0f}%)"

    for row in result["rows"]:
        table.add_row(esc(row["task"]), cell(row["a"]), cell(row["b"]),
                      "-" if row["diff"] is None else f"{100 * row['diff']:+.0f} pts",
                      "-" if row["progress_diff"] is None else f"{100 * row['progress_diff']:+.0f} pts",
                      {"mcnemar_exact": "McNemar (paired)", "fisher_exact": "Fisher"}.get(row["test"], "-"),
                      "-" if row["p_value"] is None else f"{row['p_value']:.3g}",
                      "-" if row["p_holm"] is None else f"{row['p_holm']:.3g}",
                      "[bold]real[/]" if row["significant"] else "")
    ov = result["overall"]
    if ov["a"] and ov["b"]:
        table.add_row("[bold]mean over tasks[/]", f"{100 * ov['a']['mean']:.1f}% ± {100 * ov['a']['stderr']:.1f}",
                      f"{100 * ov['b']['mean']:.1f}% ± {100 * ov['b']['stderr']:.1f}", f"{100 * ov['diff']:+.1f} pts",
                      f"{100 * (ov['b']['progress'] - ov['a']['progress']):+.1f} pts", "", "", "", "")
    out.print(table)
    rows = result["rows"]
    out.print(f"{sum(r['significant'] for r in rows)} of {len(rows)} differences are real at Holm-adjusted p < "
              f"{SIGNIFICANCE} ({result['paired_tasks']} tasks paired by seed: McNemar's exact test; "
              f"{result['unpaired_tasks']} unpaired: Fisher's exact test)", highlight=False)
    if not result["same_seeds"]:
        out.print("the runs used different seeds: their tasks are compared unpaired", highlight=False)
    if differ:
        out.print(f"[bold]compared although the runs differ (--allow-mismatch)[/]: {esc('; '.join(differ))}")


session_app = typer.Typer(help="Scripted steering sessions.", no_args_is_help=True)
app.add_typer(session_app, name="session")


@session_app.command("run")
def session_run_cmd(
    session: Annotated[Path, typer.Argument(help="Session YAML: name, steps (instruction, then edits).")],
    output: Annotated[Path, typer.Option("-o", "--output", help="Directory to write the family into.")] = Path("out"),
    seed: Annotated[int, typer.Option("--seed", min=0)] = 0,
    as_json: Annotated[bool, typer.Option("--json")] = False,
) -> None:
    """Run an instruction and its edits; exit 1 if any step fails or misses its expectations."""
    from rpg.steer.session import run_session

    with _reported_errors():
        fam, steps = run_session(session, output, seed)
    ok = all(s.ok for s in steps)
    if as_json:
        print(json.dumps({"family": str(fam), "ok": ok, "steps": [s.to_json() for s in steps]}, indent=2))
    else:
        from rich.table import Table

        table = Table(title=f"session {session.stem} -> {fam}")
        for col in ("step", "text", "intent", "reference", "version", "result"):
            table.add_column(col)
        for s in steps:
            table.add_row(str(s.index), esc(s.text), s.intent, s.reference or "-", s.version or "-",
                          "[green]ok[/]" if s.ok else "[red]" + esc("; ".join(s.problems)) + "[/]")
        out.print(table)
    raise typer.Exit(EXIT_OK if ok else EXIT_INVALID)


@app.command("validate")
def validate_cmd(
    directory: Annotated[Path, typer.Argument(help="A task artifact directory.")],
    disable: Annotated[list[str], typer.Option("--disable", help="Switch a gate off.")] = [],  # noqa: B006
    gate: Annotated[list[str], typer.Option("--gate", help=GATE_HELP)] = [],  # noqa: B006
    as_json: Annotated[bool, typer.Option("--json")] = False,
) -> None:
    """Re-run every gate on an artifact (e.g. after a hand edit)."""
    from rpg.compiler import revalidate

    with _reported_errors():
        result = revalidate(directory, frozenset(disable), frozenset(gate))
    if as_json:
        print(json.dumps(result.to_json(), indent=2))
    else:
        for line in result.log:
            out.print(esc(line), highlight=False)
    raise typer.Exit(EXIT_OK if result.valid else EXIT_INVALID)


def _artifact_task(directory: Path):
    """The task of an artifact directory, rebuilt from its code's data (the text gate, then
    the sandbox; nothing of the task runs here)."""
    from rpg.artifact import load_artifact, task_sources
    from rpg.domain.task import Task
    from rpg.env.loading import task_data

    with _reported_errors():
        load_artifact(directory)
        return Task(task_data(task_sources(directory), where=str(directory)))


def _inspect_block(task, *, state: str = "initial", seed: int = 0, settle: int = 0, poses: dict | None = None) -> dict:
    from rpg.validate.verdicts import result_block

    with _reported_errors():
        if poses is not None:
            task.scene.load_json(json.dumps({"objects": poses}))
            task.scene.reset_time()
        elif state == "goal":
            task.set_goal_state()
        else:
            task.reset(seed)
        task.step(settle)
        return result_block(task)


def _print_block(block: dict, as_json: bool) -> None:
    if as_json:
        print(json.dumps(block, indent=2))
        return
    out.print(f"success: {block['success']}")
    for o in block["objects"]:
        pos = ", ".join(f"{v:.3f}" for v in o["position"])
        out.print(f"  {o['name']:<16} {o['kind']:<14} ({pos})", highlight=False)
    for p in block["predicates"]:
        mark = "[green]ok[/]" if p["satisfied"] else "[red]no[/]"
        out.print(f"  {mark} {esc(p['reason'])}", highlight=False)


@app.command("inspect")
def inspect_cmd(
    directory: Annotated[Path, typer.Argument(help="A task artifact directory.")],
    state: Annotated[str, typer.Option("--state", help="initial or goal")] = "initial",
    seed: Annotated[int, typer.Option("--seed", min=0)] = 0,
    settle: Annotated[int, typer.Option("--settle", min=0, help="Zero-action steps before reading the state.")] = 50,
    as_json: Annotated[bool, typer.Option("--json")] = False,
) -> None:
    """Print objects, success and predicates of the initial or goal state."""
    if state not in ("initial", "goal"):
        _fail("--state must be 'initial' or 'goal'")
    _print_block(_inspect_block(_artifact_task(directory), state=state, seed=seed, settle=settle), as_json)


@app.command("check")
def check_cmd(
    directory: Annotated[Path, typer.Argument(help="A task artifact directory.")],
    poses: Annotated[Path, typer.Option("--poses", help="JSON: object name -> {position, quaternion}.")],
    settle: Annotated[int, typer.Option("--settle", min=0)] = 0,
    as_json: Annotated[bool, typer.Option("--json")] = False,
) -> None:
    """Evaluate the success predicate on given poses."""
    from rpg.artifact import ArtifactError, read_text

    try:
        doc = json.loads(read_text(poses, 16 * 1024**2))
    except (ArtifactError, ValueError, RecursionError) as exc:
        _fail(f"cannot read poses from {poses}: {str(exc).splitlines()[0][:200] if str(exc) else type(exc).__name__}")
    objects = doc.get("objects", doc) if isinstance(doc, dict) else None
    if not isinstance(objects, dict):
        _fail(f"{poses} must map object names to {{'position': [x, y, z], 'quaternion': [w, x, y, z]}}")
    _print_block(_inspect_block(_artifact_task(directory), poses=objects, settle=settle), as_json)


@app.command("render")
def render_cmd(
    directory: Annotated[Path, typer.Argument(help="A task artifact directory (or FAMILY@vN with --embodiment).")],
    seed: Annotated[int, typer.Option("--seed", min=0)] = 0,
    embodiment: Annotated[str | None, typer.Option(
        "--embodiment", help="Show a robot (panda or floating_gripper): writes initial_<embodiment>.png and "
                             "goal_<embodiment>.png from the agentview camera.")] = None,
    output: Annotated[Path | None, typer.Option("-o", "--output", help="Directory for the robot snapshots "
                                                                       "(default: the task directory).")] = None,
) -> None:
    """Re-render initial.png and goal.png (or, with --embodiment, snapshots with the robot)."""
    if embodiment is not None:
        from rpg.env.loading import resolve_target
        from rpg.env.rollout import robot_snapshots

        with _reported_errors():
            out_dir = output or resolve_target(directory)
            if out_dir.exists() and not out_dir.is_dir():
                _fail(f"{out_dir} is not a directory")
            created = not out_dir.exists()
            out_dir.mkdir(parents=True, exist_ok=True)
            try:
                paths = robot_snapshots(directory, embodiment, seed, out_dir)
            except BaseException:
                if created:
                    shutil.rmtree(out_dir, ignore_errors=True)  # nothing half-written
                raise
            _record_written(out_dir, paths.values())
        for k, v in paths.items():
            out.print(f"{k}: {v}")
        return
    if output is not None:
        _fail("-o is for robot snapshots; give --embodiment too")
    from rpg.validate.verdicts import write_snapshots

    written = write_snapshots(_artifact_task(directory), seed, directory)
    with _reported_errors():
        _record_written(directory, written.values())
    for k, v in written.items():
        out.print(f"{k}: {v or 'skipped (no headless OpenGL)'}")


def _record_written(directory: Path, paths) -> None:
    """Record files rpg just wrote into a task artifact in its task.yaml file manifest."""
    from rpg.artifact import TASK_FILE, record_files

    names = [Path(p).name for p in paths if p and Path(p).parent == Path(directory)]
    if names and (Path(directory) / TASK_FILE).is_file():
        record_files(directory, names)


@app.command("play")
def play_cmd(
    task: Annotated[str, typer.Argument(help="A task directory, family directory or FAMILY@vN.")],
    embodiment: Annotated[str, typer.Option("--embodiment", help="panda or floating_gripper.")] = "panda",
    policy: Annotated[str, typer.Option("--policy", help="oracle, random, noop, module:Class, file.py:Class or "
                                                          "ws://host:port (as rpg eval).")] = "random",
    seed: Annotated[int, typer.Option("--seed", min=0, help="Episode seed (rho_0's sample).")] = 0,
    video: Annotated[Path | None, typer.Option("--video", help="Write an MP4 (agentview | wrist).")] = None,
    steps: Annotated[int | None, typer.Option("--steps", min=1, help="Episode length (default: the task's limit).")] = None,
    as_json: Annotated[bool, typer.Option("--json")] = False,
) -> None:
    """Run one episode of a policy in the task's environment (ee_delta control, 20 Hz)."""
    from rpg.env.rollout import play

    if video is not None and (video.is_dir() or not video.parent.is_dir()):
        _fail(f"--video {video}: give a file name in an existing directory")
    from rpg.env.rollout import BUILTIN_POLICIES

    with _reported_errors():
        chosen = policy
        if policy not in BUILTIN_POLICIES:
            from rpg.eval.policies import load_policy

            chosen = load_policy(policy)
        try:
            summary = play(task, embodiment=embodiment, policy=chosen, seed=seed, video=video, max_steps=steps)
        finally:
            if callable(getattr(chosen, "close", None)):
                chosen.close()
    if as_json:
        print(json.dumps(summary.to_json(), indent=2))
    else:
        mark = "[green]success[/]" if summary.success else "[red]no success[/]"
        out.print(f"{esc(summary.task)} {summary.embodiment} {summary.policy} seed {summary.seed}: {mark} "
                  f"after {summary.steps} steps", highlight=False)
        if summary.video:
            out.print(f"video: {esc(summary.video)} ({summary.frames} frames)", highlight=False)


@app.command("demos")
def demos_cmd(
    target: Annotated[str | None, typer.Argument(help="A task, family, FAMILY@vN or library manifest.")] = None,
    out_dir: Annotated[Path | None, typer.Option("--out", "-o", help="Dataset directory (created; resumed if it exists).")] = None,
    episodes: Annotated[int, typer.Option("--episodes", "-n", min=1, help="Successful episodes per task.")] = 10,
    embodiment: Annotated[str, typer.Option("--embodiment", help="panda or floating_gripper (rpg eval's default "
                                                                 "is the Panda too).")] = "panda",
    fmt: Annotated[str, typer.Option("--format", help="lerobot (LeRobot v3.0: parquet + MP4, episodes concatenated), "
                                                      "lerobot-v2.1 (a file per episode) or hdf5 (robomimic).")] = "lerobot",
    jobs: Annotated[int, typer.Option("--jobs", "-j", min=1, help="Episodes run at once (processes, or a local Ray's CPUs).")] = 1,
    backend: BackendOption = "local",
    address: AddressOption = None,
    cameras: Annotated[str, typer.Option("--cameras", help="Comma-separated cameras recorded as videos ('' for none).")] = "agentview,wrist",
    image_size: Annotated[int, typer.Option("--image-size", min=16, max=2048, help="Square video size, pixels.")] = 256,
    instruction: Annotated[str, typer.Option("--instruction", help="original (as written), canonical (G stated "
                                                                  "exactly) or paraphrase:K.")] = "original",
    gop: Annotated[int, typer.Option("--gop", min=1, help="Most frames between keyframes of the MP4s (LeRobot's "
                                                          "default 2: reading frame t decodes at most 2 frames).")] = 2,
    columns: Annotated[str, typer.Option("--columns", help="Optional LeRobot columns, comma-separated ('' for none): "
                                                           "joint_pos, object_poses, next (next.reward, "
                                                           "next.success, next.done).")] = "joint_pos,object_poses,next",
    keep_failed: Annotated[bool, typer.Option("--keep-failed", help="Keep failed episodes too, marked success "
                                                                    "false (they do not count toward -n).")] = False,
    visual: Annotated[str, typer.Option("--visual", help="The robot's meshes in the images: decimated (default) or "
                                                         "stock (the Menagerie's); recorded in robomimic's env_kwargs "
                                                         "or LeRobot's meta/info.json (rpg_visual).")] = "decimated",
    wrist_supersample: WristSupersampleOption = "1",
    replay: Annotated[Path | None, typer.Option("--replay", help="Replay a dataset and check every episode.")] = None,
    library: Annotated[Path, typer.Option("--library", help="With --replay: the library whose tasks are found by "
                                                            "content hash (a directory or its manifest).")] = Path("library"),
) -> None:
    """Record oracle demonstrations (successful episodes; failed ones too with --keep-failed) as a
    dataset, or replay one."""
    from rpg.demos import collect_demos, replay_dataset

    if replay is not None:
        with _reported_errors():
            results = replay_dataset(replay, library=library, progress=lambda r: out.print(
                f"episode {r.episode_index}: {'ok' if r.ok else 'MISMATCH'} (success {r.success}, "
                f"pose error {r.max_pose_error:.2e})", highlight=False))
        bad = [r for r in results if not r.ok]
        out.print(f"replayed {len(results)} episodes, {len(bad)} mismatched", highlight=False)
        raise typer.Exit(EXIT_INVALID if bad or not results else EXIT_OK)
    if target is None or out_dir is None:
        _fail("give a TARGET and --out DIR (or --replay DATASET)")
    cams = tuple(c for c in cameras.split(",") if c)
    from rich.progress import Progress

    with _reported_errors(), Progress(console=err, transient=True) as bar:
        tick = bar.add_task("episodes", total=None)

        def progress(ep, index):
            bar.advance(tick)
            mark = f"failed ({ep.failure or 'goal not reached'})" if not ep.success else ""
            mark = f"kept as {index}{' ' + mark if mark else ''}" if index is not None else mark
            err.print(f"{esc(ep.task_name)} seed {ep.seed}: {ep.length} steps, {mark}", highlight=False)

        summary = collect_demos(target, out_dir, episodes=episodes, embodiment=embodiment, fmt=fmt, jobs=jobs,
                                cameras=cams, image_size=(image_size, image_size), instruction=instruction,
                                progress=progress, gop=gop, columns=tuple(c for c in columns.split(",") if c),
                                keep_failed=keep_failed, backend=backend, address=address, visual=visual,
                                wrist_supersample=_integer_or_text(wrist_supersample))
    short = {t: v for t, v in summary["per_task"].items() if v["success"] < episodes}
    out.print(f"{out_dir}: {summary['episodes']} episodes ({summary['attempts']} run now)", highlight=False)
    for t, v in short.items():
        out.print(f"[yellow]{esc(t)}: only {v['success']} successful of {v['attempts']} attempts[/]", highlight=False)
    raise typer.Exit(EXIT_INVALID if short else EXIT_OK)


@app.command("diversity")
def diversity_cmd(
    library: Annotated[Path, typer.Argument(help="A library directory or manifest.")],
    by: Annotated[str, typer.Option("--by", help="Contributor groups: author, family or tag:KEY (e.g. tag:complexity).")] = "author",
    embedding: Annotated[str, typer.Option("--embedding", help="wordllama (offline, default), tfidf, or st:PATH (a local sentence-transformers model).")] = "wordllama",
    output: Annotated[Path | None, typer.Option("-o", "--output", help="Directory for summary.json and the plots.")] = None,
    suggest: Annotated[bool, typer.Option("--suggest", help="List what the library covers least.")] = False,
    seed: Annotated[int, typer.Option("--seed", min=0, help="Seed of the contributor orderings and the t-SNE map.")] = 0,
    as_json: Annotated[bool, typer.Option("--json", help="Print the summary as JSON.")] = False,
) -> None:
    """How much of the task space a library covers, by contributor (offline)."""
    from rich.table import Table

    from rpg.diversity import analyze

    with _reported_errors():
        s = analyze(library, by=by, embedding=embedding, out_dir=output, seed=seed)
    if as_json:
        print(json.dumps(s, indent=2, sort_keys=True))
        return
    table = Table(title=f"diversity of {library} by {by} ({embedding}): {s['tasks']} tasks, "
                        f"mean pairwise cosine distance {s['mean_pairwise_distance']}")
    for col in ("group", "tasks", "diversity"):
        table.add_column(col)
    for g, n in s["groups"].items():
        d = s["per_group"][g]
        table.add_row(esc(g), str(n), "-" if d is None else f"{d:.3f}")
    out.print(table)
    pooled = s["pooled"]
    out.print(f"pooled: 1 {by} {pooled[0]['mean']} -> {pooled[-1]['contributors']} {pooled[-1]['mean']} "
              f"(95% interval {pooled[-1]['lo']}..{pooled[-1]['hi']})", highlight=False)
    st = s["structural"]
    for key in ("goal_kinds", "predicate_types", "asset_classes"):
        out.print(f"{key.replace('_', ' ')}: entropy {st[key]['entropy_bits']:.2f} bits, "
                  f"coverage {st[key]['coverage'] * 100:.0f}%", highlight=False)
    if suggest:
        for key, values in s["suggest"].items():
            out.print(f"least covered {key.replace('_', ' ')}: {', '.join(values)}", highlight=False)
    if output is not None:
        out.print(f"wrote {output / 'summary.json'} and {', '.join(s['plots'].values())}")


@app.command("doctor")
def doctor_cmd(
    as_json: bool = typer.Option(False, "--json", help="Print the layers as JSON."),
) -> None:
    """Show which sandbox layers protect this machine from task code (exit 0 when all are active, 1 otherwise)."""
    from rpg.validate.isolation import layers

    found = layers()
    if as_json:
        typer.echo(json.dumps([{"layer": x.name, "active": x.active, "detail": x.detail} for x in found], indent=2))
    else:
        for x in found:
            typer.echo(f"{'active ' if x.active else 'MISSING'}  {x.name:<21} {x.detail}")
    if not all(x.active for x in found):
        raise typer.Exit(EXIT_INVALID)


@app.command("schema")
def schema_cmd(
    output: Annotated[Path, typer.Option("-o", "--output")] = Path("schemas/task.schema.json"),
) -> None:
    """Write the TaskSchema JSON Schema."""
    from rpg.artifact import write_file
    from rpg.schema.model import export_json_schema

    if output.is_dir():
        _fail(f"{output} is a directory; give the JSON Schema's file name, e.g. {output / 'task.schema.json'}")
    with _reported_errors():
        output.parent.mkdir(parents=True, exist_ok=True)
        write_file(output, export_json_schema())
    out.print(f"wrote {output}")


def _freeze_imports() -> None:
    """Move what the imports allocated (modules, classes, tables: live until exit) out of the
    garbage collector's reach, so a one-shot command's collections walk only its own work."""
    import gc

    gc.freeze()


def main() -> None:
    try:
        app()
    except KeyboardInterrupt:
        sys.exit(130)
    finally:
        # Exiting: the interpreter's last collection would walk every object of the imported
        # libraries (~80 ms of a one-shot command's ~0.9 s). Files are written and synced
        # explicitly; atexit handlers (temporary directories, a spare sandbox child) still run.
        _freeze_imports()


if __name__ == "__main__":
    main()
