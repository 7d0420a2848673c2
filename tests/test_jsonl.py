"""rpg.jsonl: the kill-safe JSON-lines logs of rpg eval and rpg demos."""

from rpg.jsonl import append_jsonl, cut_torn_line, read_complete, read_jsonl, rewrite_jsonl


def test_a_torn_last_line_is_not_read_and_is_cut_before_appending(tmp_path):
    log = tmp_path / "episodes.jsonl"
    append_jsonl(log, {"seed": 0})
    append_jsonl(log, {"seed": 1})
    whole = log.stat().st_size
    with open(log, "a") as fh:
        fh.write('{"seed": 2, "succ')  # killed mid-write
    records, good = read_complete(log)
    assert [r["seed"] for r in records] == [0, 1] and good == whole
    assert cut_torn_line(log) == records and log.stat().st_size == whole
    append_jsonl(log, {"seed": 2})
    assert [r["seed"] for r in read_jsonl(log)] == [0, 1, 2]


def test_blank_lines_are_skipped_and_a_missing_file_is_empty(tmp_path):
    log = tmp_path / "a.jsonl"
    assert read_complete(log) == ([], 0) and cut_torn_line(log) == []
    log.write_text('{"a": 1}\n\n{"a": 2}\n')
    assert read_jsonl(log) == [{"a": 1}, {"a": 2}]
    rewrite_jsonl(log, [{"a": 3}])
    assert read_jsonl(log) == [{"a": 3}] and not list(tmp_path.glob(".*tmp*"))
