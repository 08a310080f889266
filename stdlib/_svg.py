"""A :class:`~mech.stdlib._scene.Scene` as an SVG file, written directly: coordinates rounded to
0.1 px, each marker group one ``<path>`` (dots are zero-length round-capped segments)."""
from __future__ import annotations

from html import escape  # xml.sax.saxutils would import urllib, http and ssl (25 ms)

from mech.stdlib._scene import Lines, Markers, Scene, Text


def _n(v: float) -> str:
    """A coordinate rounded to 0.1 without a trailing ``.0``."""
    s = f"{v:.1f}"
    s = s[:-2] if s.endswith(".0") else s
    return "0" if s == "-0" else s


def _marker(shape: str, x: float, y: float, h: float) -> str:
    """The path data of one marker of half size ``h`` at ``(x, y)``."""
    if shape == "dot":
        return f"M{_n(x)} {_n(y)}h0"
    if shape == "x":
        return f"M{_n(x - h)} {_n(y - h)}L{_n(x + h)} {_n(y + h)}M{_n(x - h)} {_n(y + h)}L{_n(x + h)} {_n(y - h)}"
    if shape == "circle":
        return f"M{_n(x - h)} {_n(y)}a{_n(h)} {_n(h)} 0 1 0 {_n(2 * h)} 0a{_n(h)} {_n(h)} 0 1 0 {_n(-2 * h)} 0z"
    if shape == "triangle":
        return f"M{_n(x)} {_n(y - h)}L{_n(x + h)} {_n(y + h)}L{_n(x - h)} {_n(y + h)}z"
    if shape == "square":
        return f"M{_n(x - h)} {_n(y - h)}h{_n(2 * h)}v{_n(2 * h)}h{_n(-2 * h)}z"
    raise ValueError(f"unknown marker shape {shape!r}")


def _cls(cls: str) -> str:
    return f' class="{cls}"' if cls else ""


def _element(item: Lines | Markers | Text) -> str:
    if isinstance(item, Lines):
        close = "Z" if item.fill else ""
        d = "".join("M" + "L".join(f"{_n(x)} {_n(y)}" for x, y in line) + close for line in item.lines if line)
        style = f'fill="{item.fill or "none"}" stroke="{item.colour}" stroke-width="{_n(item.width)}"'
        if item.dash:
            style += ' stroke-dasharray="6 4"'
        if item.round:
            style += ' stroke-linecap="round" stroke-linejoin="round"'
        return f'<path{_cls(item.cls)} d="{d}" {style}/>'
    if isinstance(item, Markers):
        h = item.size / 2
        d = "".join(_marker(item.shape, x, y, h) for x, y in item.points)
        if item.shape == "dot":
            style = f'fill="none" stroke="{item.colour}" stroke-width="{_n(item.size)}" stroke-linecap="round"'
        else:
            style = f'fill="{item.fill or "none"}" stroke="{item.colour}" stroke-width="{_n(item.width)}"'
        return f'<path{_cls(item.cls)} d="{d}" {style}/>'
    turn = f' transform="rotate({-item.rotate} {_n(item.x)} {_n(item.y)})"' if item.rotate else ""
    return (f'<text{_cls(item.cls)} x="{_n(item.x)}" y="{_n(item.y)}" font-size="{_n(item.size)}" '
            f'text-anchor="{item.anchor}"{turn}>{escape(item.text, quote=False)}</text>')


def to_svg(scene: Scene, title: str = "") -> str:
    """The SVG document of ``scene`` (``title``: the document's title element)."""
    w, h = scene.width, scene.height
    head = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" '
            f'font-family="DejaVu Sans, Verdana, sans-serif">')
    parts = [head]
    if title:
        parts.append(f"<title>{escape(title, quote=False)}</title>")
    parts.append(f'<rect width="{w}" height="{h}" fill="white"/>')
    parts += [_element(item) for item in scene.items]
    parts.append("</svg>\n")
    return "\n".join(parts)


def write_svg(scene: Scene, path: str, title: str = "") -> None:
    with open(path, "w", encoding="utf-8") as f:
        f.write(to_svg(scene, title))

