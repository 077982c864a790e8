"""`gecent plot`: a backplot of a tape (read by LinuxCNC's rs274) or of a CL file, drawn
with matplotlib in one plane: rapid moves dashed, feed moves solid, arcs as arcs, and
optionally the CL path under the tape's (docs/verify.md#plot).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from math import atan2, degrees
from pathlib import Path
from typing import Any

from gecent.core.errors import InputError
from gecent.core.output.files import write_atomically
from gecent.core.verify.clpath import PLANE_AXES, ClPath
from gecent.core.verify.rs274 import TapeMove

TAPE_SUFFIXES = frozenset({".ngc", ".nc", ".tap", ".tape", ".gcode", ".cnc"})
AXIS_NAMES = "XYZ"
RAPID_STYLE: dict[str, Any] = {"color": "#d62728", "linestyle": (0, (4, 3)), "linewidth": 0.6}
FEED_STYLE: dict[str, Any] = {"color": "#1f3d99", "linestyle": "-", "linewidth": 0.7}
CL_STYLE: dict[str, Any] = {"color": "#999999", "linestyle": "-", "linewidth": 2.2, "alpha": 0.45}


@dataclass(frozen=True, slots=True)
class Segment:
    """One move in the plot's plane: a line, or an arc (centre, radius, start and end
    angles in degrees, counterclockwise from start to end)."""

    start: tuple[float, float]
    end: tuple[float, float]
    rapid: bool
    arc: tuple[tuple[float, float], float, float, float] | None = None


def is_tape(path: str) -> bool:
    return Path(path).suffix.lower() in TAPE_SUFFIXES


def _arc(
    start: tuple[float, float], end: tuple[float, float], centre: tuple[float, float], ccw: bool
) -> tuple[tuple[float, float], float, float, float]:
    radius = ((start[0] - centre[0]) ** 2 + (start[1] - centre[1]) ** 2) ** 0.5
    a = degrees(atan2(start[1] - centre[1], start[0] - centre[0]))
    b = degrees(atan2(end[1] - centre[1], end[0] - centre[0]))
    if not ccw:
        a, b = b, a
    if b <= a + 1e-9:
        b += 360.0
    return centre, radius, a, b


def tape_segments(moves: Iterable[TapeMove], plane: str) -> list[Segment]:
    first, second = PLANE_AXES[plane]
    at = (0.0, 0.0, 0.0)
    segments = []
    for move in moves:
        start = (at[first], at[second])
        end = (move.end[first], move.end[second])
        arc = None
        if move.kind == "arc" and move.centre is not None and move.plane == plane:
            centre = (move.centre[first], move.centre[second])
            arc = _arc(start, end, centre, move.rotation > 0)
        segments.append(Segment(start, end, move.kind == "rapid", arc))
        at = move.end
    return segments


def cl_segments(path: ClPath, plane: str) -> list[Segment]:
    first, second = PLANE_AXES[plane]
    segments = []
    at: tuple[float, float] | None = None
    for target in path.targets:
        end = (target.point[first], target.point[second])
        if at is not None:
            arc = None
            spec = target.arc
            if spec is not None and spec.plane == plane:
                centre = (spec.centre[first], spec.centre[second])
                arc = _arc(at, end, centre, spec.counterclockwise)
            segments.append(Segment(at, end, target.kind == "rapid", arc))
        at = end
    return segments


def render(
    segments: list[Segment],
    output: str,
    *,
    plane: str,
    title: str,
    overlay: list[Segment] | None = None,
    unit: str = "mm",
) -> None:
    """Draw and write the plot (PNG or SVG by the file's suffix), atomically."""
    suffix = Path(output).suffix.lower()
    if suffix not in (".png", ".svg"):
        raise InputError(f"plot output must end in .png or .svg, found {output!r}", None)
    import io

    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D
    from matplotlib.patches import Arc

    figure, axes = pyplot.subplots(figsize=(10, 8))
    try:
        for group, styles in ((overlay or [], (CL_STYLE, CL_STYLE)), (segments, None)):
            lines: dict[bool, list[tuple[tuple[float, float], tuple[float, float]]]] = {
                True: [],
                False: [],
            }
            for segment in group:
                style = styles[0] if styles else RAPID_STYLE if segment.rapid else FEED_STYLE
                if segment.arc is not None:
                    (cx, cy), radius, a, b = segment.arc
                    axes.add_patch(
                        Arc((cx, cy), 2 * radius, 2 * radius, theta1=a, theta2=b, **style)
                    )
                else:
                    lines[segment.rapid].append((segment.start, segment.end))
            for rapid, pairs in lines.items():
                if pairs:
                    style = styles[0] if styles else RAPID_STYLE if rapid else FEED_STYLE
                    axes.add_collection(LineCollection(pairs, **style))
        points = [p for s in [*segments, *(overlay or [])] for p in (s.start, s.end)]
        if points:
            xs, ys = [p[0] for p in points], [p[1] for p in points]
            pad = 0.03 * max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
            axes.set_xlim(min(xs) - pad, max(xs) + pad)
            axes.set_ylim(min(ys) - pad, max(ys) + pad)
        axes.set_aspect("equal")
        first, second = PLANE_AXES[plane]
        axes.set_xlabel(f"{AXIS_NAMES[first]} ({unit})")
        axes.set_ylabel(f"{AXIS_NAMES[second]} ({unit})")
        axes.set_title(title)
        legend = [Line2D([], [], **FEED_STYLE), Line2D([], [], **RAPID_STYLE)]
        names = ["feed", "rapid"]
        if overlay:
            legend.append(Line2D([], [], **CL_STYLE))
            names.append("CL path")
        axes.legend(legend, names, loc="upper right")
        axes.grid(True, linewidth=0.3)
        buffer = io.BytesIO()
        figure.savefig(buffer, format=suffix[1:], dpi=120, bbox_inches="tight")
    finally:
        pyplot.close(figure)
    write_atomically(output, buffer.getvalue())
