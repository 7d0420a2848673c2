"""YAML reading for artifacts, histories and manifests: PyYAML's safe loader, through
libyaml's C parser when PyYAML was built with it (the same documents, ~10x faster to
parse; task.yaml files are re-read at every steering step and batch entry).  Writing
stays with :func:`yaml.safe_dump`, whose output the content hashes are taken over."""

from __future__ import annotations

from typing import Any

import yaml

SafeLoader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def load(text: str) -> Any:
    """Parse one YAML document with the safe loader.

    Raises:
        yaml.YAMLError: malformed YAML.
    """
    return yaml.load(text, Loader=SafeLoader)  # noqa: S506 - a safe loader (C or Python)
