"""Task diversity of a library (paper: Results, "diversity grows with contributors"; appendix
on diversity measures): embeddings of task instructions, pairwise cosine distance, pooling
over contributors, cumulative curves per contributor, and structural diversity computed from
the schemas themselves.

Python API::

    from rpg.diversity import analyze
    summary = analyze("library", by="author", embedding="wordllama", out_dir="diversity")
"""

from rpg.diversity.analysis import analyze, collect
from rpg.diversity.measures import (
    cumulative_diversity,
    mean_pairwise_distance,
    pooled_diversity,
    structural_diversity,
    suggestions,
)

__all__ = ["analyze", "collect", "cumulative_diversity", "mean_pairwise_distance", "pooled_diversity",
           "structural_diversity", "suggestions"]
