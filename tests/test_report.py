"""rpg report: the gallery loads in headless Chromium with every card and image present."""

import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from conftest import CHROMIUM_FLAGS

ROOT = Path(__file__).resolve().parents[1]
@pytest.mark.slow
def test_gallery_has_every_card_and_image(chromium, tmp_path):
    site, run = tmp_path / "site", tmp_path / "run"
    proc = subprocess.run([sys.executable, "-m", "rpg.cli", "eval", "split=train", "--library", str(ROOT / "library" / "manifest.yaml"),
                           "--policy", "oracle", "-n", "2", "--embodiment", "floating_gripper", "-o", str(run)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    proc = subprocess.run([sys.executable, "-m", "rpg.cli", "report", str(ROOT / "library"), "-o", str(site),
                           "--diversity", "family", "--eval", str(run)], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    lib = ROOT / "library"
    expected = {d.name for d in lib.iterdir() if (d / "task.yaml").is_file()}
    for fam in (d for d in lib.iterdir() if (d / "family.yaml").is_file()):
        expected |= {f"{fam.name}-v{v['version_id']}" for v in yaml.safe_load((fam / "family.yaml").read_text())["versions"]}
    dom = subprocess.run([chromium, *CHROMIUM_FLAGS, f"--user-data-dir={tmp_path / 'profile'}", "--virtual-time-budget=10000",
                          "--dump-dom", (site / "index.html").as_uri()], capture_output=True, text=True, timeout=120).stdout
    cards = set(re.findall(r'<section class="card" id="([^"]+)"', dom))
    assert cards == expected
    m = re.search(r'<body data-images-loaded="(\d+)" data-images="(\d+)"', dom)
    assert m, dom[:500]
    assert int(m.group(1)) == int(m.group(2)) == 2 * len(expected)
    assert dom.count("class=\"pass\"") >= 8 * len(expected)
    # every card says what the oracle did: its successes over the episodes run (the gate stops once
    # SOLVABLE_MIN_SUCCESS succeeded, so 3/3 as well as 5/5), or why the solvable gate was waived
    rates = re.findall(r"oracle \(solvable gate\): (\d)/([3-5]) episodes with the floating gripper", dom)
    waived = dom.count("solvable gate waived: the oracle cannot build the 3x3x3 cube")  # stack_and_modify v0, v1
    assert len(rates) + waived == len(expected) and waived == 2
    assert all(3 <= int(k) <= int(n) for k, n in rates)
    # the evaluation run: its page is linked, and each evaluated task's card shows its rate
    train = [e["name"] for e in yaml.safe_load((lib / "manifest.yaml").read_text())["entries"] if e.get("split") == "train"]
    evals = {}
    for section in dom.split('<section class="card" id="')[1:]:
        m = re.search(r'data-run="eval-0">oracle \(floating gripper\): (\d/\d) episodes', section.split("</section>")[0])
        if m:
            evals[section.split('"')[0]] = m.group(1)
    assert len(train) == 10 and sorted(evals) == sorted(train) and set(evals.values()) <= {"2/2", "1/2", "0/2"}
    assert 'href="eval-0.html"' in dom and (site / "eval-0.html").is_file() and (site / "eval-0" / "success.png").is_file()
    page = subprocess.run([chromium, *CHROMIUM_FLAGS, f"--user-data-dir={tmp_path / 'profile2'}", "--virtual-time-budget=10000",
                           "--dump-dom", (site / "diversity.html").as_uri()], capture_output=True, text=True, timeout=120).stdout
    assert 'id="diversity-link"' in dom and 'id="overall"' in page
    assert len(re.findall(r"<tr><td>", page)) == len({c.split("-v")[0] for c in cards})
    assert {p.name for p in (site / "diversity").iterdir()} >= {"summary.json", "pooled.png", "cumulative.png", "tsne.png"}
