"""YAML reading and writing for artifacts, histories and manifests.

Reading uses PyYAML's safe loader, through libyaml's C parser when PyYAML was built with it
(the same documents, ~10x faster to parse; task.yaml files are re-read at every steering
step and batch entry).  Anchors and aliases are refused: rpg never writes them, and a
kilobyte of nested aliases expands to gigabytes (an "alias bomb").  Writing goes through
:func:`dump` (:func:`yaml.safe_dump` that never emits aliases), whose output the content
hashes are taken over.
"""

from __future__ import annotations

from typing import Any

import yaml

from rpg.errors import BadInput

SafeLoader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


class AliasRefused(BadInput, yaml.YAMLError):
    """A YAML document uses an anchor or an alias (which rpg's files never contain) or
    nests deeper than :data:`MAX_DEPTH`."""


class _NoAliasDumper(yaml.SafeDumper):
    def ignore_aliases(self, data: Any) -> bool:
        return True


MAX_DEPTH = 64
"""Deepest nesting of lists and mappings accepted (rpg's own files nest fewer than 10 levels)."""


def load(text: str) -> Any:
    """Parse one YAML document with the safe loader, refusing anchors, aliases and nesting
    deeper than :data:`MAX_DEPTH` (checked first on libyaml's event stream, which is
    iterative: a deeply nested document never reaches the recursive composer).

    Raises:
        AliasRefused: the document has an anchor or alias, or nests too deep.
        yaml.YAMLError: malformed YAML.
    """
    depth = 0
    for event in yaml.parse(text, Loader=SafeLoader):
        if isinstance(event, yaml.AliasEvent) or getattr(event, "anchor", None):
            mark = getattr(event, "start_mark", None)
            where = f" (line {mark.line + 1})" if mark else ""
            raise AliasRefused(f"YAML anchors and aliases are not allowed{where}")
        if isinstance(event, yaml.CollectionStartEvent):
            depth += 1
            if depth > MAX_DEPTH:
                raise AliasRefused(f"YAML nested deeper than {MAX_DEPTH} levels is not allowed")
        elif isinstance(event, yaml.CollectionEndEvent):
            depth -= 1
    return yaml.load(text, Loader=SafeLoader)  # noqa: S506 - a safe loader (C or Python)


def dump(doc: Any, width: int = 100) -> str:
    """``doc`` as block YAML in insertion order, UTF-8 kept, never with anchors or aliases."""
    return yaml.dump(doc, Dumper=_NoAliasDumper, sort_keys=False, allow_unicode=True, width=width)
