"""The evaluation page of ``rpg report RUN_DIR``: the success table with Wilson intervals, a
bar chart with error bars (matplotlib PNG), per-episode videos and the failed predicates of
failed episodes.

A run directory may come from someone else, so what it names is checked before anything is
written (:func:`check_run`): its ``run.json``, ``summary.json`` and ``episodes.jsonl`` must
be regular files, and every episode's ``video`` a relative path without ``..`` that reaches a
regular file inside the run directory through no symbolic link (checked component by
component, then the resolved path).  One bad path refuses the whole page (one line, nothing
written); a video that is simply missing is left off the page.
"""

from __future__ import annotations

import json
import os
import shutil
import stat
from pathlib import Path

import jinja2

from rpg.errors import BadInput, PeerError
from rpg.eval.runner import read_episodes
from rpg.eval.stats import task_key

PAGE = jinja2.Template("""<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>rpg eval: {{ cfg.policy }} on {{ cfg.target }}</title>
<style>body{font-family:system-ui,sans-serif;margin:1.5rem;color:#222}table{border-collapse:collapse;margin:.5rem 0}
td,th{border:1px solid #ddd;padding:2px 8px;text-align:left}td.num{text-align:right}img.chart{max-width:100%}
video{width:256px;margin:.2rem}.fail{color:#a00}details{margin:.3rem 0}</style></head>
<body><h1>{{ cfg.policy }} on {{ cfg.target }}</h1>
<p>embodiment {{ cfg.embodiment }}, instruction {{ cfg.instruction }}, seeds {{ cfg.seeds|length }} per task
({{ cfg.seeds[0] }}..{{ cfg.seeds[-1] }}); overall <b id="overall">{{ pct(s.overall.mean) }}</b>
(n {{ s.overall.n }}, 95% {{ pct(s.overall.wilson95[0]) }}..{{ pct(s.overall.wilson95[1]) }}), progress
<b id="progress">{{ pct(s.overall.progress or 0) }}</b> ± {{ pct(s.overall.progress_stderr or 0) }}{% if s.over_tasks %};
mean over {{ s.over_tasks.tasks }} tasks {{ pct(s.over_tasks.mean) }} ± {{ pct(s.over_tasks.stderr) }} (standard error over tasks){% endif %}.
{% if s.errors %}<span class="fail">{{ s.errors|length }} episodes ended with a policy error (counted as failures).</span>{% endif %}</p>
<img class="chart" src="{{ name }}/success.png" alt="success rate per task with 95% Wilson intervals">
{% for title, group in groups %}{% if group %}<h2>per {{ title }}</h2>
<table id="{{ title|replace(' ', '-') }}"><tr><th>{{ title }}</th><th>success</th><th>stderr</th><th>95% Wilson</th><th>progress</th><th>n</th></tr>
{% for k, r in group.items() %}<tr><td>{{ k }}</td><td class="num">{{ pct(r.mean) }}</td><td class="num">{{ pct(r.stderr) }}</td>
<td class="num">{{ pct(r.wilson95[0]) }}..{{ pct(r.wilson95[1]) }}</td><td class="num">{{ pct(r.progress or 0) }} ± {{ pct(r.progress_stderr or 0) }}</td><td class="num">{{ r.n }}</td></tr>
{% endfor %}</table>{% endif %}{% endfor %}
<h2>episodes</h2>
{% for key, eps in episodes %}<details{% if loop.first %} open{% endif %}><summary>{{ key }}: {{ eps|selectattr("success")|list|length }}/{{ eps|length }}</summary>
{% for e in eps %}<div class="episode" data-success="{{ e.success|lower }}">seed {{ e.seed }} ({{ e.instruction_variant }}): {% if e.error %}<span class="fail">policy error: {{ e.error }}</span>{% elif e.success %}success in {{ e.steps }} steps{% else %}<span class="fail">failed after {{ e.steps }} steps (progress {{ pct(e.progress or 0) }}): {{ e.unsatisfied|join("; ") }}</span>{% endif %}
{% if e.video %}<br><video controls muted preload="metadata" src="{{ name }}/{{ e.video }}"></video>{% endif %}</div>
{% endfor %}</details>{% endfor %}
</body></html>
""", autoescape=True)


def _pct(v: float) -> str:
    return f"{100 * v:.1f}%"


def _chart(summary: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    tasks = summary["tasks"]
    names = list(tasks)
    means = [tasks[n]["mean"] * 100 for n in names]
    lo = [max(0.0, (tasks[n]["mean"] - tasks[n]["wilson95"][0]) * 100) for n in names]
    hi = [max(0.0, (tasks[n]["wilson95"][1] - tasks[n]["mean"]) * 100) for n in names]
    fig, ax = plt.subplots(figsize=(max(4.0, 0.35 * len(names) + 2), 4.0), dpi=100)
    ax.bar(range(len(names)), means, yerr=[lo, hi], capsize=3, color="#4c72b0")
    ax.set_xticks(range(len(names)), names, rotation=70, ha="right", fontsize=7)
    ax.set_ylabel("success (%), 95% Wilson interval")
    ax.set_ylim(0, 105)
    ax.set_title(f"{summary['config']['policy']}: success per task")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def task_rates(run_dir: str | Path) -> dict[str, tuple[int, int]]:
    """Successes and episodes of a run per task content hash: ``{hash: (k, n)}``."""
    out: dict[str, tuple[int, int]] = {}
    for e in read_episodes(Path(run_dir) / "episodes.jsonl"):
        k, n = out.get(e["task_hash"], (0, 0))
        out[e["task_hash"]] = (k + bool(e["success"]), n + 1)
    return out


def is_run_dir(path: Path) -> bool:
    """``path`` holds an ``rpg eval`` run (``run.json`` and ``summary.json``)."""
    return (Path(path) / "run.json").is_file() and (Path(path) / "summary.json").is_file()


RUN_FILES = ("run.json", "summary.json", "episodes.jsonl")
"""The files of a finished run a page is made from."""


def _run_video(run_dir: Path, video: object) -> Path | None:
    """The file an episode's ``video`` names inside ``run_dir``, None if it does not exist.

    Raises:
        PeerError: not a relative path of plain names, a symbolic link at any component, not
            a regular file, or a resolved path outside ``run_dir``.
    """
    if not isinstance(video, str) or not video or "\0" in video:
        raise PeerError(f"{run_dir}: an episode's video {str(video)[:80]!r} is not a path")
    rel = Path(video)
    if rel.is_absolute() or ".." in rel.parts or rel.as_posix() != video:
        raise PeerError(f"{run_dir}: the video path {video[:200]!r} is not a plain path inside the run directory")
    here = run_dir
    for part in rel.parts:
        here = here / part
        try:
            st = os.lstat(here)
        except (FileNotFoundError, NotADirectoryError):
            return None
        if stat.S_ISLNK(st.st_mode):
            raise PeerError(f"{here} is a symbolic link; rpg report copies only a run directory's own files")
    if not stat.S_ISREG(st.st_mode):
        raise PeerError(f"{here} is not a regular file")
    if not here.resolve().is_relative_to(run_dir.resolve()):
        raise PeerError(f"{here} resolves outside the run directory {run_dir}")
    return here


def check_run(run_dir: str | Path) -> tuple[dict, list[dict], dict[str, Path]]:
    """Read a finished run and check every file its page would copy, writing nothing.

    Returns:
        (summary, episodes, {video path as recorded: the file to copy}); an episode whose
        video is missing has it set to None.

    Raises:
        BadInput: ``run_dir`` holds no finished run.
        PeerError: a run file that is a symbolic link or not a regular file, or a video path
            :func:`_run_video` refuses.
    """
    run_dir = Path(run_dir)
    if not is_run_dir(run_dir):
        raise BadInput(f"{run_dir} holds no rpg eval run (run.json and summary.json)")
    for name in RUN_FILES:
        f = run_dir / name
        if f.is_symlink() or (f.exists() and not f.is_file()):
            raise PeerError(f"{f} is a symbolic link or not a regular file; rpg report reads a run's own files only")
    summary = json.loads((run_dir / "summary.json").read_text())
    episodes = read_episodes(run_dir / "episodes.jsonl")
    copies: dict[str, Path] = {}
    for e in episodes:
        video = e.get("video")
        if video is None:
            continue
        src = _run_video(run_dir, video)
        if src is None:
            e["video"] = None
        else:
            copies[video] = src
    return summary, episodes, copies


def write_eval_report(run_dir: str | Path, site: str | Path, name: str = "eval") -> Path:
    """Write ``site/<name>.html`` (with ``site/<name>/``: the chart and videos) for a run;
    return the page's path.  Every video is checked (:func:`check_run`) before anything is
    written.

    Raises:
        BadInput: ``run_dir`` holds no finished run, or ``site`` is a file.
        PeerError: a run file or video path :func:`check_run` refuses (nothing is written).
    """
    run_dir, site = Path(run_dir), Path(site)
    summary, episodes, copies = check_run(run_dir)
    if site.exists() and not site.is_dir():
        raise BadInput(f"{site} is a file; -o needs a directory for the site")
    assets = site / name
    assets.mkdir(parents=True, exist_ok=True)
    _chart(summary, assets / "success.png")
    for video, src in copies.items():
        dst = assets / video
        dst.parent.mkdir(parents=True, exist_ok=True)
        with open(src, "rb", opener=lambda p, f: os.open(p, f | os.O_NOFOLLOW)) as fin, open(dst, "wb") as fout:
            shutil.copyfileobj(fin, fout)
    by_task: dict[str, list[dict]] = {}
    for e in sorted(episodes, key=lambda e: (task_key(e), e["instruction_variant"], e["seed"])):
        by_task.setdefault(task_key(e), []).append(e)
    groups = [("task", summary["tasks"]), ("family", summary["families"]), ("intent", summary["intents"]),
              ("split", summary["splits"]), ("instruction", summary["instructions"])]
    page = site / f"{name}.html"
    page.write_text(PAGE.render(cfg=summary["config"], s=summary, groups=groups, episodes=list(by_task.items()),
                                pct=_pct, name=name))
    return page
