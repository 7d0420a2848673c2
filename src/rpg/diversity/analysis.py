"""``rpg diversity``: collect a library's tasks, measure their diversity, write the results.

Outputs in ``out_dir``: ``summary.json`` (every number), ``pooled.png`` (diversity vs number
of contributors with its 95% band), ``cumulative.png`` (per contributor), ``tsne.png`` (a
t-SNE map of the task embeddings coloured by contributor).
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rpg.artifact import load_artifact
from rpg.diversity.embeddings import embed
from rpg.diversity.measures import (
    cumulative_diversity,
    mean_pairwise_distance,
    pooled_diversity,
    structural_diversity,
    suggestions,
)
from rpg.errors import BadInput
from rpg.schema.model import TaskSchema

UNKNOWN_AUTHOR = "unknown"


@dataclass
class TaskRecord:
    """One task of the library: where it is, its schema, who wrote it."""

    path: Path
    name: str
    schema: TaskSchema
    author: str

    def group(self, by: str) -> str:
        """The contributor group under ``by``: ``author``, ``family`` or ``tag:KEY``."""
        if by == "author":
            return self.author
        if by == "family":
            return self.name.split("@")[0]
        if by.startswith("tag:"):
            value = self.schema.tags().get(by[4:])
            if value is None:
                raise BadInput(f"no tag {by[4:]!r}; tags are {', '.join(sorted(self.schema.tags()))}")
            return ",".join(map(str, value)) if isinstance(value, list) else str(value)
        raise BadInput(f"--by must be author, family or tag:KEY, not {by!r}")


def _record(path: Path, name: str, author: str | None) -> TaskRecord:
    schema, doc = load_artifact(path)
    who = author or (doc.get("provenance") or {}).get("author") or UNKNOWN_AUTHOR
    return TaskRecord(path, name, schema, str(who))


def collect(target: str | Path) -> list[TaskRecord]:
    """Every task of a library directory (directories by name) or manifest (its order), a
    family's versions in order (:func:`rpg.library.report.library_entries`), with its author
    (the manifest entry's ``author``, else the task's provenance, else ``unknown``).

    Raises:
        BadInput: the target is neither, or holds no task.
    """
    from rpg.library.report import library_entries

    target = Path(target)
    if target.is_file():
        from rpg.library.build import load_manifest

        authors = {e.name: e.author for e in load_manifest(target).entries}
        base = target.parent
        missing = sorted(n for n in authors if not (base / n).is_dir())
        if missing:
            raise BadInput(f"{base / missing[0]} is listed in {target} but not built; run 'rpg build {target}'")
        order = {n: i for i, n in enumerate(authors)}  # manifest order; a family's versions stay in order
        entries = sorted((e for e in library_entries(base) if e[0] in order), key=lambda e: order[e[0]])
    elif target.is_dir():
        authors, entries = {}, library_entries(target)
    else:
        raise BadInput(f"{target} is neither a library directory nor a manifest")
    out = [_record(d, name if v is None else f"{name}@v{v['version_id']}", authors.get(name)) for name, d, v in entries]
    if not out:
        raise BadInput(f"{target} holds no task")
    return out


def analyze(target: str | Path, by: str = "author", embedding: str = "wordllama", out_dir: str | Path | None = None,
            seed: int = 0, orderings: int | None = None) -> dict:
    """Measure a library's diversity and (with ``out_dir``) write summary.json and the plots.

    Args:
        target: a library directory or manifest.
        by: contributor groups: ``author``, ``family`` or ``tag:KEY``.
        embedding: ``wordllama``, ``tfidf`` or ``st:PATH``.
        seed: seed of the contributor orderings and the t-SNE map.
        orderings: random orderings for the pooled curve (default
            :data:`rpg.diversity.measures.POOL_ORDERINGS`).

    Returns:
        The summary: tasks, groups, embedding, mean pairwise distance overall and per
        group, the pooled and cumulative curves, structural diversity and suggestions.
    """
    from rpg.diversity.measures import POOL_ORDERINGS

    if out_dir is not None and Path(out_dir).exists() and not Path(out_dir).is_dir():
        raise BadInput(f"{out_dir} is a file; -o needs a directory for summary.json and the plots")
    records = collect(target)
    groups = [r.group(by) for r in records]
    x = embed([r.schema.instruction for r in records], embedding)
    rng = np.random.default_rng(seed)
    structural = structural_diversity([r.schema for r in records])
    names = sorted(set(groups))
    summary = {
        "target": str(target), "by": by, "embedding": embedding, "seed": seed, "tasks": len(records),
        "groups": {g: groups.count(g) for g in names},
        "mean_pairwise_distance": _num(mean_pairwise_distance(x)),
        "per_group": {g: _num(mean_pairwise_distance(x, np.array([i for i, h in enumerate(groups) if h == g])))
                      for g in names},
        "pooled": [{k: _num(v) for k, v in row.items()}
                   for row in pooled_diversity(x, groups, rng, orderings or POOL_ORDERINGS)],
        "cumulative": {g: [_num(v) for v in vals] for g, vals in cumulative_diversity(x, groups).items()},
        "structural": structural,
        "suggest": suggestions(structural),
        "task_groups": [{"task": r.name, "group": g} for r, g in zip(records, groups, strict=True)],
    }
    if out_dir is not None:
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        summary["plots"] = _plots(summary, x, groups, out, seed)
        tmp = out / ".summary.json.tmp"  # written last and renamed: a summary.json is never half-written
        tmp.write_text(json.dumps(summary, indent=2, sort_keys=True) + "\n")
        os.replace(tmp, out / "summary.json")
    return summary


def _num(v):
    if isinstance(v, float):
        return None if np.isnan(v) else round(v, 6)
    return v


def _plots(summary: dict, x: np.ndarray, groups: list[str], out: Path, seed: int) -> dict[str, str]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    files = {}
    pooled = [r for r in summary["pooled"] if r["mean"] is not None]
    fig, ax = plt.subplots(figsize=(5, 3.5), dpi=120)
    ks = [r["contributors"] for r in pooled]
    ax.plot(ks, [r["mean"] for r in pooled], marker="o", color="C0")
    ax.fill_between(ks, [r["lo"] for r in pooled], [r["hi"] for r in pooled], alpha=0.25, color="C0", label="95% interval")
    ax.set_xlabel(f"contributors pooled ({summary['by']})")
    ax.set_ylabel("mean pairwise cosine distance")
    ax.set_title(f"diversity vs contributors ({summary['embedding']})")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "pooled.png")
    plt.close(fig)
    files["pooled"] = "pooled.png"

    fig, ax = plt.subplots(figsize=(5, 3.5), dpi=120)
    for g, vals in summary["cumulative"].items():
        if vals:
            ax.plot(range(2, len(vals) + 2), [v if v is not None else np.nan for v in vals], label=g)
    ax.set_xlabel("tasks by this contributor")
    ax.set_ylabel("mean pairwise cosine distance")
    ax.set_title("cumulative diversity per contributor")
    if len(summary["cumulative"]) <= 12:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "cumulative.png")
    plt.close(fig)
    files["cumulative"] = "cumulative.png"

    if len(x) >= 5:
        from sklearn.manifold import TSNE

        xy = TSNE(n_components=2, perplexity=min(30.0, (len(x) - 1) / 3), random_state=seed, init="pca",
                  metric="cosine").fit_transform(x)
        fig, ax = plt.subplots(figsize=(5, 4.5), dpi=120)
        for i, g in enumerate(sorted(set(groups))):
            pts = xy[[j for j, h in enumerate(groups) if h == g]]
            ax.scatter(pts[:, 0], pts[:, 1], s=18, label=g, color=f"C{i % 10}")
        ax.set_title(f"t-SNE of task embeddings by {summary['by']}")
        ax.set_xticks([])
        ax.set_yticks([])
        if len(set(groups)) <= 12:
            ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / "tsne.png")
        plt.close(fig)
        files["tsne"] = "tsne.png"
    return files
