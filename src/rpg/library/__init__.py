"""Task libraries: manifests, parallel (re)generation with a reproducibility check, reports."""

from rpg.library.build import (
    Entry,
    Manifest,
    ManifestError,
    build_entry,
    build_library,
    load_manifest,
)

__all__ = ["Entry", "Manifest", "ManifestError", "build_entry", "build_library", "load_manifest"]
