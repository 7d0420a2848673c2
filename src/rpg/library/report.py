"""``rpg report``: a static HTML gallery of a task library.

One card per task artifact and per family version (like the paper's task figures): the
instruction, the initial and goal snapshots, the gate results, the repairs applied, and
for family versions the intent, reference, parent and lineage hash.  Snapshots are copied
next to the page, so the site directory is self-contained.
"""

from __future__ import annotations

import json
from pathlib import Path

import jinja2

from rpg import yamlio
from rpg.artifact import ArtifactError, load_artifact, read_bytes, write_file

PAGE = jinja2.Template("""<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>{{ title }}</title>
<style>
body{font-family:system-ui,sans-serif;margin:1.5rem;background:#fafafa;color:#222}
.grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(420px,1fr));gap:1rem}
.card{background:#fff;border:1px solid #ddd;border-radius:8px;padding:.8rem}
.card h2{font-size:1rem;margin:.2rem 0}.shots{display:flex;gap:.4rem}.shots figure{margin:0;flex:1}
.shots img{width:100%;border-radius:4px}figcaption{font-size:.75rem;color:#666;text-align:center}
.instr{font-style:italic}.gates{display:flex;flex-wrap:wrap;gap:2px}.gates span{font-size:.7rem;padding:1px 4px;border-radius:3px;margin-right:2px}
.pass{background:#d4f4d4}.fail{background:#f8d0d0}.skipped{background:#eee}.meta{font-size:.75rem;color:#555}
h1 small{font-weight:normal;color:#666;font-size:.9rem}
</style></head>
<body><h1>{{ title }} <small>{{ cards|length }} cards</small></h1>
{% if diversity %}<p><a id="diversity-link" href="diversity.html">Task diversity by {{ diversity }}</a></p>{% endif %}
{% for r in runs %}<p class="run"><a id="{{ r.page }}-link" href="{{ r.page }}.html">Evaluation: {{ r.label }}</a> ({{ r.episodes }} episodes per task)</p>{% endfor %}
<div class="grid">
{% for c in cards %}<section class="card" id="{{ c.id }}" data-kind="{{ c.kind }}">
<h2>{{ c.title }}</h2>
<p class="instr">{{ c.instruction }}</p>
<div class="shots">{% for key in ("initial", "goal") %}{% if c.images[key] %}
<figure><img src="{{ c.images[key] }}" alt="{{ key }} state of {{ c.title }}"><figcaption>{{ key }} state</figcaption></figure>
{% endif %}{% endfor %}</div>
<p class="gates">{% for g, st in c.gates.items() %}<span class="{{ st }}">{{ g }}</span>{% endfor %}</p>
<p class="meta">{{ c.summary }}</p>
<p class="meta oracle">{% if c.oracle %}oracle (solvable gate): {{ c.oracle.successes }}/{{ c.oracle.episodes }} episodes with the {{ c.oracle.embodiment|replace("_", " ") }}{% elif c.waived %}solvable gate waived: {{ c.waived }}{% else %}solvable gate not run{% endif %}</p>
{% for r in c.evals %}<p class="meta eval" data-run="{{ r.page }}">{{ r.label }}: {{ r.k }}/{{ r.n }} episodes ({{ "%.0f"|format(100 * r.mean) }}%, 95% Wilson {{ "%.0f"|format(100 * r.lo) }}..{{ "%.0f"|format(100 * r.hi) }}%)</p>{% endfor %}
{% if c.repairs %}<p class="meta">repairs: {{ c.repairs|join(", ") }}</p>{% endif %}
{% if c.lineage %}<p class="meta">{{ c.lineage }}</p>{% endif %}
</section>
{% endfor %}</div>
<script>
window.addEventListener("load", function () {
  var imgs = Array.from(document.images);
  document.body.dataset.imagesLoaded = imgs.filter(function (i) { return i.complete && i.naturalWidth > 0; }).length;
  document.body.dataset.images = imgs.length;
});
</script>
</body></html>
""", autoescape=True)


DIVERSITY_PAGE = jinja2.Template("""<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>{{ title }}: diversity</title>
<style>body{font-family:system-ui,sans-serif;margin:1.5rem;color:#222}table{border-collapse:collapse}
td,th{border:1px solid #ddd;padding:2px 8px;text-align:left}img{max-width:48%;margin:.3rem}</style></head>
<body><h1>{{ title }}: task diversity by {{ s.by }}</h1>
<p><a href="index.html">back to the gallery</a></p>
<p>{{ s.tasks }} tasks, embedding {{ s.embedding }}: mean pairwise cosine distance
<b id="overall">{{ s.mean_pairwise_distance }}</b>; all {{ s.pooled[-1].contributors }} groups pooled
{{ s.pooled[-1].mean }}, one group {{ s.pooled[0].mean }} (95% interval {{ s.pooled[0].lo }}..{{ s.pooled[0].hi }}).</p>
<table id="groups"><tr><th>{{ s.by }}</th><th>tasks</th><th>diversity</th></tr>
{% for g, n in s.groups.items() %}<tr><td>{{ g }}</td><td>{{ n }}</td><td>{{ s.per_group[g] if s.per_group[g] is not none else "-" }}</td></tr>
{% endfor %}</table>
<p>{% for key, f in structural %}{{ key }}: entropy {{ "%.2f"|format(f.entropy_bits) }} bits, coverage {{ "%.0f"|format(f.coverage * 100) }}%<br>{% endfor %}</p>
<p>least covered: {% for key, vals in s.suggest.items() %}{{ key }}: {{ vals|join(", ") }}; {% endfor %}</p>
<div>{% for name, file in s.plots.items() %}<img src="diversity/{{ file }}" alt="{{ name }} plot">{% endfor %}</div>
</body></html>
""", autoescape=True)


def _oracle_rate(directory: Path) -> dict | None:
    """The ``solvable`` gate's details from ``validation.json`` (None when it did not run)."""
    import json

    try:
        gates = json.loads((directory / "validation.json").read_text()).get("gates", [])
    except (OSError, ValueError, AttributeError):
        return None
    found = [g for g in gates if isinstance(g, dict) and g.get("gate") == "solvable"]
    details = found[0].get("details") if found else None
    return details if isinstance(details, dict) and "successes" in details else None


def _waivers(library: Path) -> dict[str, str]:
    """Entry name -> why its ``solvable`` gate is waived, from the library's manifest if any."""
    from rpg.library.build import ManifestError, load_manifest

    try:
        manifest = load_manifest(library / "manifest.yaml")
    except ManifestError:
        return {}
    return {e.name: e.waive["solvable"] for e in manifest.entries if "solvable" in e.waive}


def _card(directory: Path, site: Path, card_id: str, title: str, kind: str, lineage: str = "",
          waived: str | None = None) -> dict:
    schema, doc = load_artifact(directory)
    images = {}
    for key in ("initial", "goal"):
        src = directory / f"{key}.png"
        if src.is_file() and not src.is_symlink():  # a gallery never publishes what a link points at
            dst = site / "img" / f"{card_id}-{key}.png"
            write_file(dst, read_bytes(src, 64 * 1024**2))
            images[key] = f"img/{dst.name}"
        else:
            images[key] = None
    prov = doc.get("provenance", {})
    return {"id": card_id, "title": title, "kind": kind, "instruction": schema.instruction,
            "summary": schema.goal_summary, "images": images, "gates": prov.get("gates", {}),
            "repairs": [r["operator"] for r in prov.get("repairs", [])], "lineage": lineage,
            "oracle": _oracle_rate(directory), "waived": waived, "hash": doc.get("content_hash"), "evals": []}


def library_entries(library: Path) -> list[tuple[str, Path, dict | None]]:
    """Every task artifact and family version directly under ``library``, in library order
    (directories by name, a family's versions as its history lists them):
    ``(entry name, version directory, history record or None for a plain task)``."""
    out = []
    for d in sorted(p for p in Path(library).iterdir() if p.is_dir() and not p.name.startswith(".")):
        if (d / "family.yaml").is_file():
            hist = yamlio.load((d / "family.yaml").read_text())
            out += [(d.name, d / f"v{v['version_id']}", v) for v in hist["versions"]]
        elif (d / "task.yaml").is_file():
            out.append((d.name, d, None))
    return out


def collect_cards(library: Path, site: Path) -> list[dict]:
    """Cards for every task artifact and family version directly under ``library``."""
    cards = []
    waivers = _waivers(Path(library))
    for name, d, v in library_entries(library):
        if v is not None:
            ref = "none" if v["reference"] is None else f"v{v['reference']}"
            parent = "none" if v["parent"] is None else f"v{v['parent']}"
            lineage = (f"{v['intent']}; reference {ref}; parent {parent}; lineage {v['lineage_hash'][:12]}"
                       + (f"; edit: {v['description']}" if v["version_id"] else ""))
            cards.append(_card(d, site, f"{name}-v{v['version_id']}", f"{name} v{v['version_id']}", "family_version",
                               lineage, waivers.get(name)))
        else:
            try:
                cards.append(_card(d, site, name, name, "task", waived=waivers.get(name)))
            except ArtifactError:
                continue
    return cards


def _add_runs(cards: list[dict], runs: list[Path], site: Path) -> list[dict]:
    """Write each ``rpg eval`` run's page (``site/eval-<i>.html``) and put its success rate
    on every card whose task content hash it evaluated; the runs' header lines."""
    from rpg.eval.report import task_rates, write_eval_report
    from rpg.eval.stats import rate

    out = []
    for i, run in enumerate(runs):
        page = f"eval-{i}"
        write_eval_report(run, site, name=page)
        cfg = json.loads((Path(run) / "run.json").read_text())
        label = f"{cfg['policy']} ({cfg['embodiment'].replace('_', ' ')})"
        rates = task_rates(run)
        for c in cards:
            if c["hash"] in rates:
                k, n = rates[c["hash"]]
                r = rate(k, n)
                c["evals"].append({"page": page, "label": label, "k": k, "n": n, "mean": r["mean"],
                                   "lo": r["wilson95"][0], "hi": r["wilson95"][1]})
        out.append({"page": page, "label": label, "episodes": len(cfg["seeds"])})
    return out


def write_report(library: str | Path, site: str | Path, title: str | None = None, diversity: str | None = None,
                 embedding: str = "wordllama", runs: list[str | Path] = ()) -> Path:
    """Write ``site/index.html`` (and ``site/img/``); return the page's path.

    With ``diversity`` (a grouping: ``author``, ``family`` or ``tag:KEY``) also write
    ``site/diversity.html`` and its plots under ``site/diversity/`` (:func:`rpg.diversity.analyze`).
    With ``runs`` (``rpg eval`` run directories) also write each run's evaluation page
    (``site/eval-<i>.html``) and show its success rate, with the Wilson 95% interval, on the
    card of every task it evaluated (matched by content hash).  Every run's files and video
    paths are checked (:func:`rpg.eval.report.check_run`) before anything is written.

    Raises:
        ValueError: ``library`` is not a directory, or a run directory holds no finished run.
        PeerError: a run's file or video path is a symbolic link or leaves the run directory
            (nothing is written).
    """
    library, site = Path(library), Path(site)
    if not library.is_dir():
        raise ValueError(f"{library} is not a directory")
    if site.exists() and not site.is_dir():
        raise ValueError(f"{site} is a file; -o needs a directory for the site")
    from rpg.eval.report import check_run, is_run_dir

    for run in runs:
        if not is_run_dir(Path(run)):
            raise ValueError(f"--eval {run} holds no finished rpg eval run (run.json and summary.json)")
        check_run(run)  # every video path of every run, before anything is written
    (site / "img").mkdir(parents=True, exist_ok=True)
    cards = collect_cards(library, site)
    run_lines = _add_runs(cards, [Path(r) for r in runs], site)
    title = title or f"rpg task library: {library.resolve().name}"
    if diversity:
        from rpg.diversity import analyze

        summary = analyze(library, by=diversity, embedding=embedding, out_dir=site / "diversity")
        structural = [(k.replace("_", " "), summary["structural"][k]) for k in ("goal_kinds", "predicate_types", "asset_classes")]
        (site / "diversity.html").write_text(DIVERSITY_PAGE.render(title=title, s=summary, structural=structural))
    page = site / "index.html"
    page.write_text(PAGE.render(title=title, cards=cards, diversity=diversity, runs=run_lines))
    return page
