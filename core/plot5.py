"""`gecent plot` on a five-axis machine by data (docs/five-axis.md): a 3-D picture of the
tool tip's path in the part, with the tool axis drawn every N points as a short line from
the tip towards the holder. A tape is read by rs274 and carried back to the part through
the machine's kinematics (as `gecent verify` does); a CL file is drawn as it is written.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from itertools import pairwise
from pathlib import Path
from typing import Any

from gecent.core.errors import InputError
from gecent.core.output.files import write_atomically
from gecent.core.verify.fiveaxis import FiveAxisKinematics
from gecent.core.verify.fiveaxis_cl import Pose
from gecent.core.verify.rs274 import TapeMove

Point = tuple[float, float, float]
RAPID_STYLE: dict[str, Any] = {"color": "#d62728", "linestyle": (0, (4, 3)), "linewidth": 0.6}
FEED_STYLE: dict[str, Any] = {"color": "#1f3d99", "linestyle": "-", "linewidth": 0.8}
CL_STYLE: dict[str, Any] = {"color": "#999999", "linestyle": "-", "linewidth": 2.2, "alpha": 0.45}
AXIS_STYLE: dict[str, Any] = {"color": "#2ca02c", "linewidth": 0.7}


@dataclass(frozen=True, slots=True)
class PathPoint:
    """A point of the tool's path in the part: its tip and axis, and whether the move that
    reaches it is a rapid one."""

    tip: Point
    axis: Point
    rapid: bool


def tape_path(moves: Iterable[TapeMove], kinematics: FiveAxisKinematics) -> list[PathPoint]:
    found = []
    for move in moves:
        tip, axis = kinematics.pose(move.end, kinematics.angles(move), move.tool)
        found.append(PathPoint(tip, axis, move.kind == "rapid"))
    return found


def cl_path(poses: Iterable[Pose]) -> list[PathPoint]:
    return [PathPoint(p.tip, p.axis, p.kind == "rapid") for p in poses]


def render_five_axis(
    path: list[PathPoint],
    output: str,
    *,
    title: str,
    overlay: list[PathPoint] | None = None,
    every: int = 10,
    axis_length: float = 10.0,
    unit: str = "mm",
) -> None:
    """Draw the path in 3-D with the tool axis every ``every`` points; PNG or SVG."""
    suffix = Path(output).suffix.lower()
    if suffix not in (".png", ".svg"):
        raise InputError(f"plot output must end in .png or .svg, found {output!r}", None)
    if every < 1:
        raise InputError(f"--axis-every must be 1 or more, found {every}", None)
    import io

    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot
    from matplotlib.lines import Line2D
    from mpl_toolkits.mplot3d.art3d import Line3DCollection  # type: ignore[import-untyped]

    figure = pyplot.figure(figsize=(10, 8))
    axes = figure.add_subplot(projection="3d")
    try:
        if overlay:
            pairs = [(a.tip, b.tip) for a, b in pairwise(overlay)]
            axes.add_collection3d(Line3DCollection(pairs, **CL_STYLE))
        for rapid in (True, False):
            pairs = [(a.tip, b.tip) for a, b in pairwise(path) if b.rapid == rapid]
            if pairs:
                style = RAPID_STYLE if rapid else FEED_STYLE
                axes.add_collection3d(Line3DCollection(pairs, **style))
        sticks = [
            (p.tip, tuple(p.tip[a] + axis_length * p.axis[a] for a in range(3)))
            for index, p in enumerate(path)
            if index % every == 0 and not p.rapid
        ]
        if sticks:
            axes.add_collection3d(Line3DCollection(sticks, **AXIS_STYLE))
        points = [p.tip for p in [*path, *(overlay or [])]] + [s[1] for s in sticks]
        if points:
            low = [min(p[a] for p in points) for a in range(3)]
            high = [max(p[a] for p in points) for a in range(3)]
            span = max(max(h - lo for h, lo in zip(high, low, strict=True)), 1.0) / 2
            for a, setter in enumerate((axes.set_xlim, axes.set_ylim, axes.set_zlim)):
                middle = (high[a] + low[a]) / 2
                setter(middle - span, middle + span)
        axes.set_xlabel(f"X ({unit})")
        axes.set_ylabel(f"Y ({unit})")
        axes.set_zlabel(f"Z ({unit})")
        axes.set_title(title)
        legend = [Line2D([], [], **FEED_STYLE), Line2D([], [], **RAPID_STYLE)]
        names = ["feed (tool tip)", "rapid"]
        legend.append(Line2D([], [], **AXIS_STYLE))
        names.append(f"tool axis, every {every} points")
        if overlay:
            legend.append(Line2D([], [], **CL_STYLE))
            names.append("CL path")
        axes.legend(legend, names, loc="upper right")
        buffer = io.BytesIO()
        figure.savefig(buffer, format=suffix[1:], dpi=120, bbox_inches="tight")
    finally:
        pyplot.close(figure)
    write_atomically(output, buffer.getvalue())
