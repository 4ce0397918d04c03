"""The propagation graph of report.html: a layered layout (grandalf) drawn as SVG.

Each row is a label in a column by its depth (a root slip in the first column, what
inherits it to the right); grandalf's Sugiyama layout orders each column to reduce crossings
and gives every edge that skips a column a slot of its own there. An edge runs horizontally
through each column band, at its endpoint's or its slot's height, and bends only in the gaps
between columns, so no edge crosses a label (tests/output/html/test_html_report.py checks it).
"""

from __future__ import annotations

import html
from collections.abc import Callable, Sequence
from dataclasses import dataclass

__all__ = ["Box", "layered_graph"]

CHAR_W, LABEL_H, SLOT_H, GAP = 7.0, 16.0, 22.0, 70.0


@dataclass(frozen=True)
class Box:
    """A label's rectangle: left, top, width, height."""

    x: float
    y: float
    w: float
    h: float


@dataclass
class _View:  # what grandalf reads and writes for a vertex
    w: float
    h: float
    xy: tuple[float, float] = (0.0, 0.0)


def _layout(nodes: Sequence[str], edges: Sequence[tuple[str, str]]) -> tuple[dict, dict, dict]:
    """Each node's (rank, order position), each edge's per-rank positions, per component."""
    from grandalf.graphs import Edge, Graph, Vertex  # type: ignore[import-untyped]
    from grandalf.layouts import SugiyamaLayout  # type: ignore[import-untyped]

    vertices = {n: Vertex(n) for n in nodes}
    for v in vertices.values():
        v.view = _View(SLOT_H, 10.0)
    graph = Graph(list(vertices.values()), [Edge(vertices[a], vertices[b]) for a, b in edges])
    rank: dict[str, int] = {}
    place: dict[str, float] = {}
    routes: dict[tuple[str, str], dict[int, float]] = {}
    offset = 0.0
    for component in graph.C:
        sugiyama = SugiyamaLayout(component)
        sugiyama.init_all()
        sugiyama.draw()
        low = min(v.view.xy[0] for v in component.sV)
        for v in component.sV:
            rank[v.data] = sugiyama.grx[v].rank
            place[v.data] = offset + v.view.xy[0] - low
        for e in component.sE:
            ctrl = sugiyama.ctrls.get(e, {})
            routes[(e.v[0].data, e.v[1].data)] = {
                r: offset + d.view.xy[0] - low for r, d in ctrl.items()
            }
        offset = max(place.values()) + 2 * SLOT_H
    return rank, place, routes


def layered_graph(
    nodes: Sequence[str],
    edges: Sequence[tuple[str, str]],
    href: Callable[[str], str],
    is_root: Callable[[str], bool],
) -> tuple[str, dict[str, Box], list[list[tuple[float, float]]]]:
    """The SVG, each label's box and each edge's polyline (for the geometry test)."""
    rank, place, routes = _layout(nodes, edges)
    columns = max(rank.values()) + 1
    width = [max(CHAR_W * len(n) for n in nodes if rank[n] == c) + 8 for c in range(columns)]
    left = [10 + sum(width[:c]) + GAP * c for c in range(columns)]
    boxes = {n: Box(left[rank[n]], 10 + place[n], CHAR_W * len(n) + 8, LABEL_H) for n in nodes}
    lines = [_route(boxes[a], boxes[b], rank[a], rank[b], routes.get((a, b), {}), left, width)
             for a, b in edges]  # fmt: skip
    svg = _svg(nodes, boxes, lines, href, is_root, left[-1] + width[-1] + 10)
    return svg, boxes, lines


def _route(
    a: Box, b: Box, ra: int, rb: int, slots: dict[int, float], left: list[float], width: list[float]
) -> list[tuple[float, float]]:
    """From a's right edge to b's left edge, straight across every column between them."""
    mid = LABEL_H / 2
    points = [(a.x + a.w, a.y + mid), (left[ra] + width[ra], a.y + mid)]
    for r in range(ra + 1, rb):
        y = 10 + slots.get(r, a.y - 10) + mid
        points += [(left[r], y), (left[r] + width[r], y)]
    return [*points, (left[rb], b.y + mid), (b.x, b.y + mid)]


def _svg(nodes, boxes, lines, href, is_root, width) -> str:
    height = max(b.y + b.h for b in boxes.values()) + 10
    paths = "".join(
        '<polyline fill="none" stroke="#888" marker-end="url(#arrow)" points="'
        + " ".join(f"{x:.1f},{y:.1f}" for x, y in line)
        + '"/>'
        for line in lines
    )
    labels = "".join(
        f'<a href="{html.escape(href(n))}"><rect class="label" x="{b.x:.1f}" y="{b.y:.1f}" '
        f'width="{b.w:.1f}" height="{b.h:.1f}" fill="#fff"/><text x="{b.x + 4:.1f}" '
        f'y="{b.y + 12:.1f}" font-size="12" fill="{"#b00" if is_root(n) else "#333"}">'
        f"{html.escape(n)}</text></a>"
        for n, b in boxes.items()
    )
    return (
        f'<svg class="graph" xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" '
        f'height="{height:.0f}" viewBox="0 0 {width:.0f} {height:.0f}" role="img" '
        'aria-label="propagation of slips"><defs><marker id="arrow" viewBox="0 0 10 10" '
        'refX="10" refY="5" markerWidth="6" markerHeight="6" orient="auto">'
        f'<path d="M0,0L10,5L0,10z" fill="#888"/></marker></defs>{paths}{labels}</svg>'
    )
