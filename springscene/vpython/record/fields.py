"""What a recording keeps of each kind of object, canvas, light and graph.

Each kind has its fields: the VPython attribute name a reader sees, the private field the
object keeps it in, and its type: ``"v"`` a vector (three numbers), ``"f"`` a number,
``"b"`` a boolean (numbers and booleans are compared as one row of floats a frame), or
``"j"`` any other JSON value (a string, a colour that may be unset) compared as Python
values. The attribute names and their meaning are docs/recording.md's.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Field", "Schema", "schema_of", "POINT_KINDS"]

POINT_KINDS = ("curve", "points")        # objects whose points are recorded as a list


@dataclass(frozen=True)
class Field:
    name: str          # the VPython attribute, as a reader sees it
    store: str         # the object's field it is read from
    type: str          # "v", "f", "b" or "j"


def _fields(spec: str) -> tuple[Field, ...]:
    """``"pos:_pos:v opacity:_opacity:f"`` as Fields."""
    out = []
    for item in spec.split():
        name, store, kind = item.split(":")
        out.append(Field(name, store, kind))
    return tuple(out)


_SOLID = ("pos:_pos:v axis:_axis:v up:_up:v size:_size:v color:_color:v "
          "opacity:_opacity:f shininess:_shininess:f emissive:_emissive:b visible:_visible:b "
          "texture:texture:j")
_KINDS = {
    "solid": _fields(_SOLID),
    "arrow": _fields(_SOLID + " shaftwidth:_shaftwidth:f headwidth:_headwidth:f "
                              "headlength:_headlength:f round:_round:b"),
    "helix": _fields(_SOLID + " coils:_coils:f thickness:thickness:f ccw:_ccw:b"),
    "curve": _fields("origin:_origin:v axis:_axis:v up:_up:v size:_size:v color:_color:v "
                     "radius:_radius:f opacity:_opacity:f shininess:_shininess:f "
                     "emissive:_emissive:b visible:_visible:b retain:_retain:f"),
    "points": _fields("origin:_origin:v color:_color:v radius:_radius:f opacity:_opacity:f "
                      "shininess:_shininess:f emissive:_emissive:b visible:_visible:b "
                      "retain:_retain:f size_units:_size_units:j"),
    "label": _fields("pos:_pos:v xoffset:_xoffset:f yoffset:_yoffset:f height:_height:f "
                     "opacity:_opacity:f box:_box:b border:_border:f line:_line:b "
                     "linewidth:_linewidth:f space:_space:f pixel_pos:_pixel_pos:b "
                     "visible:_visible:b text:_text:j font:_font:j align:_align:j "
                     "color:_color:v background:_background:v linecolor:_linecolor:v"),
}


@dataclass(frozen=True)
class Schema:
    """The fields of one kind, split into the numeric row and the other values."""

    numeric: tuple[Field, ...]
    other: tuple[Field, ...]
    columns: tuple[slice, ...]           # each numeric field's columns in the row

    @property
    def width(self) -> int:
        return self.columns[-1].stop if self.columns else 0


def _schema(fields: tuple[Field, ...]) -> Schema:
    numeric = tuple(f for f in fields if f.type != "j")
    columns, at = [], 0
    for f in numeric:
        n = 3 if f.type == "v" else 1
        columns.append(slice(at, at + n))
        at += n
    return Schema(numeric, tuple(f for f in fields if f.type == "j"), tuple(columns))


_SCHEMAS = {name: _schema(fields) for name, fields in _KINDS.items()}


def schema_of(kind: str) -> Schema:
    """The fields recorded of an object of ``kind`` (a solid's for any kind not listed)."""
    return _SCHEMAS.get(kind, _SCHEMAS["solid"])
