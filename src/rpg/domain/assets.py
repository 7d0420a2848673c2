"""Task assets: coloured cubes, semantic (letter/number) cubes and goal patches.

Each asset is a small immutable description that knows how to add itself to a
``mujoco.MjSpec`` (``Asset.attach``).  Cubes are free bodies; goal patches are mocap
bodies with a thin, non-colliding box, so their pose is part of the episode state without
affecting the physics.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import TYPE_CHECKING, ClassVar

from rpg.domain import constants as C
from rpg.domain.glyphs import FACES, canonical_label, cube_texture, label_type
from rpg.domain.palette import DEFAULT_SEMANTIC_COLOR, PALETTE, canonical_color, rgba
from rpg.errors import BadInput

if TYPE_CHECKING:  # mujoco is imported where a scene is built, not when a schema is read
    import mujoco

CUBE_GEOM_GROUP = 0
"""Geom group of cubes and the table: seen by rays and cameras."""

PATCH_GEOM_GROUP = 2
"""Geom group of goal patches: rendered (groups 0-2 are shown by default), ignored by visibility rays."""


def _mj():
    import mujoco

    return mujoco


def _contact_params(geom: mujoco.MjsGeom) -> None:
    geom.solref = list(C.CONTACT_SOLREF)
    geom.solimp = list(C.CONTACT_SOLIMP)
    geom.friction = list(C.CUBE_FRICTION)


@dataclass(frozen=True)
class Asset:
    """Base of all assets.  Subclasses set ``kind`` and implement ``_add_geoms``.

    Attributes:
        name: unique object name in the task (letters, digits, underscores).
    """

    name: str
    kind: ClassVar[str] = "asset"
    movable: ClassVar[bool] = True

    def __post_init__(self) -> None:
        if not self.name or not self.name.replace("_", "").isalnum():
            raise ValueError(
                f"invalid object name {self.name!r}: use letters, digits and underscores"
            )

    @property
    def extents(self) -> tuple[float, float, float]:
        """Full extents (x, y, z) of the asset, m."""
        raise NotImplementedError

    def describe(self) -> str:
        """Short human description, e.g. ``"red cube"``."""
        raise NotImplementedError

    def to_dict(self) -> dict:
        """Plain-data form: ``{"kind": kind, <field>: value, ...}`` (:func:`asset_from_dict` rebuilds it)."""
        return {"kind": self.kind, **{f.name: (dict(v) if isinstance(v := getattr(self, f.name), dict) else v)
                                      for f in fields(self)}}

    def attach(self, spec: mujoco.MjSpec) -> mujoco.MjsBody:
        """Add the asset's body to ``spec`` (template method: body, joint, geoms)."""
        body = spec.worldbody.add_body(name=self.name, pos=[0.0, 0.0, C.TABLE_TOP_Z + 0.1])
        if self.movable:
            body.add_freejoint(name=f"{self.name}_joint")
        else:
            body.mocap = True
        self._add_geoms(spec, body)
        return body

    def _add_geoms(self, spec: mujoco.MjSpec, body: mujoco.MjsBody) -> None:
        raise NotImplementedError


@dataclass(frozen=True)
class _Cube(Asset):
    size: float = C.CUBE_EDGE

    @property
    def extents(self) -> tuple[float, float, float]:
        return (self.size, self.size, self.size)

    def _cube_geom(self, body: mujoco.MjsBody, **kwargs) -> mujoco.MjsGeom:
        half = self.size / 2
        geom = body.add_geom(
            name=self.name,
            type=_mj().mjtGeom.mjGEOM_BOX,
            size=[half, half, half],
            mass=C.CUBE_MASS,
            group=CUBE_GEOM_GROUP,
            **kwargs,
        )
        _contact_params(geom)
        return geom


@dataclass(frozen=True)
class ColoredCube(_Cube):
    """A plain cube of one palette colour.

    Attributes:
        name: unique object name.
        color: palette colour name (see :mod:`rpg.domain.palette`).
        size: edge length, m (default :data:`~rpg.domain.constants.CUBE_EDGE`).
    """

    color: str = "red"
    kind: ClassVar[str] = "colored_cube"

    def __post_init__(self) -> None:
        super().__post_init__()
        object.__setattr__(self, "color", canonical_color(self.color))

    @property
    def label(self) -> None:
        return None

    def face_labels(self) -> dict[str, str | None]:
        return dict.fromkeys(FACES)

    def describe(self) -> str:
        return f"{self.color} cube"

    def _add_geoms(self, spec: mujoco.MjSpec, body: mujoco.MjsBody) -> None:
        self._cube_geom(body, rgba=rgba(self.color))


@dataclass(frozen=True)
class SemanticCube(_Cube):
    """A cube with a glyph (letter, digit or operator) on its faces.

    Attributes:
        name: unique object name.
        label: the cube's label: a letter A-Z, a digit 0-9, or one of ``+ - = x``.
        faces: optional per-face labels (local face ``"+x"``...``"-z"`` -> label or None);
            faces not given carry ``label``.  Default: ``label`` on all six faces.
        color: body colour (palette name), default white; glyphs are black.
        size: edge length, m.

    Raises:
        UnknownLabelError: a label is not a letter, digit or operator.
    """

    label: str = "A"
    faces: dict[str, str | None] = field(default_factory=dict, hash=False, compare=True)
    color: str = DEFAULT_SEMANTIC_COLOR
    kind: ClassVar[str] = "semantic_cube"

    def __post_init__(self) -> None:
        super().__post_init__()
        object.__setattr__(self, "label", canonical_label(self.label))
        object.__setattr__(self, "color", canonical_color(self.color))
        unknown = set(self.faces) - set(FACES)
        if unknown:
            raise ValueError(f"unknown face(s) {sorted(unknown)}; faces are {', '.join(FACES)}")
        object.__setattr__(
            self,
            "faces",
            {f: (None if v is None else canonical_label(v)) for f, v in sorted(self.faces.items())},
        )

    @property
    def label_type(self) -> str:
        """``"letter"``, ``"digit"`` or ``"operator"``."""
        return label_type(self.label)

    def face_labels(self) -> dict[str, str | None]:
        """Label of every local face (None for a blank face)."""
        return {f: self.faces.get(f, self.label) for f in FACES}

    def describe(self) -> str:
        return f"{self.label_type} cube {self.label!r}"

    def _add_geoms(self, spec: mujoco.MjSpec, body: mujoco.MjsBody) -> None:
        background = tuple(int(round(255 * c)) for c in PALETTE[self.color])
        tex = spec.add_texture(
            name=f"{self.name}_tex",
            type=_mj().mjtTexture.mjTEXTURE_CUBE,
            width=C.GLYPH_TEXTURE_PX,
            height=6 * C.GLYPH_TEXTURE_PX,
            nchannel=3,
        )
        tex.data = cube_texture(self.face_labels(), background)
        mat = spec.add_material(name=f"{self.name}_mat")
        mat.textures[_mj().mjtTextureRole.mjTEXROLE_RGB] = tex.name
        self._cube_geom(body, material=mat.name)


@dataclass(frozen=True)
class GoalPatch(Asset):
    """A thin coloured patch on the table: visual only, never colliding.

    Attributes:
        name: unique object name.
        color: palette colour name.
        shape: ``"square"`` (:data:`~rpg.domain.constants.PATCH_SIZE`) or ``"long"``
            (:data:`~rpg.domain.constants.LONG_PATCH_SIZE`, long along y).
    """

    color: str = "gray"
    shape: str = "square"
    kind: ClassVar[str] = "goal_patch"
    movable: ClassVar[bool] = False

    def __post_init__(self) -> None:
        super().__post_init__()
        object.__setattr__(self, "color", canonical_color(self.color))
        if self.shape not in ("square", "long"):
            raise ValueError(f"unknown patch shape {self.shape!r}; use 'square' or 'long'")

    @property
    def label(self) -> None:
        return None

    @property
    def extents(self) -> tuple[float, float, float]:
        sx, sy = C.LONG_PATCH_SIZE if self.shape == "long" else C.PATCH_SIZE
        return (sx, sy, C.PATCH_THICKNESS)

    def describe(self) -> str:
        return f"{self.color} {'long ' if self.shape == 'long' else ''}goal patch"

    def _add_geoms(self, spec: mujoco.MjSpec, body: mujoco.MjsBody) -> None:
        sx, sy, sz = self.extents
        body.add_geom(
            name=self.name,
            type=_mj().mjtGeom.mjGEOM_BOX,
            size=[sx / 2, sy / 2, sz / 2],
            rgba=rgba(self.color, 0.9),
            contype=0,
            conaffinity=0,
            group=PATCH_GEOM_GROUP,
        )


ASSET_KINDS: dict[str, type[Asset]] = {
    cls.kind: cls for cls in (ColoredCube, SemanticCube, GoalPatch)
}
"""Asset kind name -> class."""


def asset_from_dict(doc: dict) -> Asset:
    """Rebuild an asset from its :meth:`Asset.to_dict` form with the domain's own classes.

    Raises:
        ValueError: not a mapping, an unknown kind or field, or a field the class refuses
            (a name that is not a slug, an unknown colour or label, a size outside
            :data:`~rpg.domain.constants.CUBE_EDGE_RANGE`).
    """
    if not isinstance(doc, dict):
        raise ValueError("an asset must be a mapping with a 'kind' key")
    cls = ASSET_KINDS.get(doc.get("kind"))
    if cls is None:
        raise ValueError(f"unknown asset kind {doc.get('kind')!r}; known: {', '.join(sorted(ASSET_KINDS))}")
    names = {f.name for f in fields(cls)}
    unknown = sorted(set(doc) - names - {"kind"})
    if unknown:
        raise ValueError(f"asset kind {cls.kind!r} has no field {unknown[0]!r}")
    try:
        asset = cls(**{k: v for k, v in doc.items() if k != "kind"})
    except (TypeError, BadInput) as exc:
        raise ValueError(f"bad {cls.kind} {doc.get('name')!r}: {exc}") from None
    size = getattr(asset, "size", None)
    if size is not None and not (isinstance(size, int | float) and C.CUBE_EDGE_RANGE[0] <= size <= C.CUBE_EDGE_RANGE[1]):
        raise ValueError(f"cube {asset.name!r} has edge {size!r} m; edges are within {C.CUBE_EDGE_RANGE} m")
    return asset
