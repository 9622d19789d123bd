"""Pictures of planar scenes: a :class:`~rbdsolve.render.drawing.sketch.Sketch` drawn to scale with
matplotlib, and a modes question's mode shapes side by side.

matplotlib is imported here only, lazily, through its object-oriented API on the Agg
canvas (never pyplot, never a GUI), so the CLI's other commands never load it.
``save_figures`` is what the answer key calls: the scene, then one picture per modes
question, each with its caption; nothing for a scene that cannot be drawn.
"""

from __future__ import annotations

import functools
import math
import textwrap
from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

from rbdsolve.errors import InputError, RbdError
from rbdsolve.model.build import Model
from rbdsolve.render.files import replacing
from rbdsolve.render.drawing.sketch import Circle, Dot, Ground, Polygon, Segment, Sketch, sketch
from rbdsolve.problem.schema import Question, QuestionKind
from rbdsolve.form.printers import unicode_name

SUFFIXES = (".png", ".svg")
COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf")
MARGIN = 0.18  # of the scene's size, around it
ARROW = 0.16  # the gravity arrow's length, of the scene's size
PANELS_PER_ROW = 3
ASPECTS = (0.5, 1.4)  # the range of a panel's height/width
PANEL = 4.2  # inches: the width of one scene panel
DPI = 150


@dataclass(frozen=True)
class Figure:
    """A picture written to ``path``, and the caption that goes under it."""

    path: Path
    caption: str


def save_figures(model: Model, folder: Path, stem: str, suffix: str = ".png") -> tuple[Figure, ...]:
    """The scene (``stem`` + suffix) and each modes question's mode shapes (``stem-modes``,
    then ``stem-modes-2``, …) in ``folder``; an empty tuple when the scene cannot be
    drawn, and no mode picture for a modes question the numeric route cannot answer."""
    folder = Path(folder)
    try:
        figures = [save_scene(model, folder / f"{stem}{suffix}")]
    except RbdError:  # not planar, velocities only, …: the key goes without a picture
        return ()
    for n, question in enumerate(modes_questions(model), 1):
        name = f"{stem}-modes{suffix}" if n == 1 else f"{stem}-modes-{n}{suffix}"
        try:
            figures.append(save_modes(model, question, folder / name))
        except RbdError:
            continue
    return tuple(figures)


def modes_questions(model: Model) -> list[Question]:
    return [q for q in model.problem.questions if q.kind is QuestionKind.MODES]


def literal_text(draw):
    """Run ``draw`` with matplotlib's mathtext off: titles and names come from the
    problem file, and a '$' there is a dollar, not the start of a formula to parse."""

    @functools.wraps(draw)
    def drawn(*args, **kwargs):
        import matplotlib

        with matplotlib.rc_context({"text.parse_math": False}):
            return draw(*args, **kwargs)

    return drawn


@literal_text
def save_scene(model: Model, path: Path, at: Mapping[str, float] | None = None) -> Figure:
    """The scene at ``at`` (default: the questions' configuration) written to ``path``;
    NotDrawable (an InputError) for a scene that is not planar."""
    check_suffix(path)
    drawing = sketch(model, at)
    view = View.of([drawing])
    fig = _new_figure(*view.figure_size(1, 1))
    ax = fig.add_subplot()
    draw_sketch(ax, drawing, labels=True)
    view.apply(ax)
    _legend(ax, drawing)
    ax.set_title(configuration_text(drawing), fontsize=10)
    _suptitle(fig, model.problem.title)
    _notes(fig, drawing.notes)
    save(fig, path)
    at_text = configuration_text(drawing)
    return Figure(Path(path), _caption(model, "the scene to scale" + (f" at {at_text}" if at_text else ""),
                                       drawing.notes))


@literal_text
def save_modes(model: Model, question: Question, path: Path) -> Figure:
    """One panel per mode: the equilibrium faint, q₀ + a·u_k over it, titled with ω_k."""
    from rbdsolve.render.drawing.mode_shapes import mode_shapes

    check_suffix(path)
    shapes = mode_shapes(model, question)
    n = len(shapes.modes)
    cols = min(n, PANELS_PER_ROW)
    rows = math.ceil(n / cols)
    view = View.of([shapes.equilibrium, *(m.sketch for m in shapes.modes)])
    fig = _new_figure(*view.figure_size(rows, cols))
    for k, mode in enumerate(shapes.modes):
        ax = fig.add_subplot(rows, cols, k + 1)
        draw_sketch(ax, shapes.equilibrium, labels=False, faint=True)
        draw_sketch(ax, mode.sketch, labels=True)
        view.apply(ax)
        ax.set_title(f"{mode.title()}\n{mode.shape_text()}, a = {mode.amplitude:.2g}", fontsize=10)
    about = configuration_text(shapes.equilibrium)
    _suptitle(fig, f"{model.problem.title}: mode shapes about {about}")
    _notes(fig, shapes.notes)
    save(fig, path)
    text = f"the mode shapes about {about}, each drawn at q₀ + a·u (the equilibrium faint)"
    return Figure(Path(path), _caption(model, text, shapes.notes))


def check_suffix(path: Path) -> None:
    if Path(path).suffix.lower() not in SUFFIXES:
        raise InputError(f"{path}: a picture is written as .png or .svg, found '{Path(path).suffix or 'no suffix'}'")


def save(fig, path: Path) -> None:
    """PNG or SVG by the suffix; an unwritable place is an InputError."""
    check_suffix(path)
    metadata = {"Date": None} if Path(path).suffix.lower() == ".svg" else {}  # the same scene, the same file
    with replacing(path) as temporary:  # an interrupted run leaves the old picture or none
        fig.savefig(temporary, dpi=DPI, metadata=metadata, format=Path(path).suffix.lower()[1:])


def configuration_text(drawing: Sketch) -> str:
    """θ = 0, φ = 0.3: the coordinates as a caption says them."""
    return ", ".join(f"{unicode_name(n)} = {_number(v)}" for n, v in drawing.configuration)


def _number(x: float) -> str:
    return f"{x:.4g}" if abs(x) > 1e-12 else "0"


def _caption(model: Model, what: str, notes: tuple[str, ...]) -> str:
    text = f"{model.problem.title}: {what}"
    return text + (f" ({'; '.join(notes)})" if notes else "") + "."


def _new_figure(width: float, height: float):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure as MplFigure

    fig = MplFigure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def _colour(drawing: Sketch, body: str) -> str:
    return COLOURS[drawing.bodies.index(body) % len(COLOURS)]


def draw_sketch(ax, drawing: Sketch, labels: bool, faint: bool = False) -> None:
    """Bodies by shape, springs, and (with ``labels``) the named points."""
    alpha = 0.22 if faint else 1.0
    for shape in drawing.shapes:
        _draw_shape(ax, shape, _colour(drawing, shape.body), alpha)
    for ground in drawing.grounds:
        _draw_ground(ax, ground, alpha)
    for link in drawing.links:
        (x0, y0), (x1, y1) = link.start, link.end
        ax.plot([x0, x1], [y0, y1], color="0.45", lw=1.3, alpha=alpha, zorder=1)
    for spring in drawing.springs:
        xs, ys = zip(*spring.vertices)
        ax.plot(xs, ys, color="0.35", lw=1.2, alpha=alpha, zorder=2)
    for pivot in drawing.pivots:  # the support on the side away from the scene's middle (a ceiling above a pendulum)
        _draw_pivot(ax, pivot, 0.04 * drawing.size(), alpha, 1.0 if pivot[1] >= _centre(drawing)[1] else -1.0)
    for strike in drawing.strikes:
        _draw_strike(ax, strike, alpha)
    if labels:
        _points(ax, drawing)
        ax.plot(0, 0, "+", color="0.55", ms=9, mew=1, zorder=1)  # the scene's origin


def _draw_strike(ax, strike, alpha: float) -> None:
    """An impact's particle as a small dark ball at the point it strikes, its velocity
    just before as an arrow pointing at it, labelled with its speed."""
    from matplotlib import patches

    ax.add_patch(patches.Circle(strike.ball, strike.radius, facecolor="0.25", edgecolor="0.1", lw=0.8,
                                alpha=alpha, zorder=6))
    ax.annotate("", strike.head, xytext=strike.tail, zorder=6,
                arrowprops={"arrowstyle": "-|>", "color": "#d62728", "lw": 1.8, "alpha": alpha})
    middle = ((strike.tail[0] + strike.head[0]) / 2, (strike.tail[1] + strike.head[1]) / 2)
    ax.annotate(strike.label, middle, xytext=(0, 7), textcoords="offset points", ha="center", va="bottom",
                fontsize=12, style="italic", color="#d62728", alpha=alpha, zorder=7)


def _draw_pivot(ax, at: tuple[float, float], size: float, alpha: float, side: float) -> None:
    """A fixed support as a textbook draws it: a hinge (an open circle) on a small
    triangle whose base is hatched, on ``side`` (+1 above the hinge, −1 below)."""
    from matplotlib import patches

    x, y = at
    base = y + side * 1.6 * size
    ax.add_patch(patches.Polygon([(x, y), (x - size, base), (x + size, base)], closed=True,
                                 facecolor="0.85", edgecolor="0.25", lw=1.2, alpha=alpha, zorder=1))
    ax.plot([x - 1.5 * size, x + 1.5 * size], [base, base], color="0.25", lw=1.2, alpha=alpha, zorder=1)
    for k in range(6):
        x0 = x - 1.5 * size + k * 0.6 * size
        ax.plot([x0, x0 - 0.5 * size], [base, base + side * 0.5 * size], color="0.5", lw=0.8, alpha=alpha, zorder=1)
    ax.plot(x, y, "o", ms=6, mfc="white", mec="0.15", mew=1.3, alpha=alpha, zorder=8)


def _draw_ground(ax, g: Ground, alpha: float) -> None:
    """A floor or incline hatched on the side away from the body; a track or drum as its
    circle; a string as a thin line."""
    from matplotlib import patches

    if g.centre is not None:
        ax.add_patch(patches.Circle(g.centre, g.radius, facecolor="none", edgecolor="0.3", lw=2,
                                    hatch=None if g.inside else "///", alpha=alpha, zorder=1))
        return
    (x0, y0), (x1, y1) = g.start, g.end
    if g.string:
        ax.plot([x0, x1], [y0, y1], color="0.2", lw=1.2, alpha=alpha, zorder=1)
        return
    ax.plot([x0, x1], [y0, y1], color="0.3", lw=2, alpha=alpha, zorder=1)
    length = math.hypot(x1 - x0, y1 - y0)
    tick = 0.04 * length
    for k in range(1, 24):  # hatching on the far side of the body
        x, y = x0 + (x1 - x0) * k / 24, y0 + (y1 - y0) * k / 24
        ax.plot([x, x - tick * (g.normal[0] + (x1 - x0) / length)], [y, y - tick * (g.normal[1] + (y1 - y0) / length)],
                color="0.5", lw=0.8, alpha=alpha, zorder=1)


def _draw_shape(ax, shape, colour: str, alpha: float) -> None:
    from matplotlib import patches

    if isinstance(shape, Segment):
        (x0, y0), (x1, y1) = shape.start, shape.end
        ax.plot([x0, x1], [y0, y1], color=colour, lw=5, solid_capstyle="round", alpha=alpha, zorder=3)
    elif isinstance(shape, Dot):
        ax.plot(*shape.at, "o", color=colour, ms=11, alpha=alpha, zorder=4)
    elif isinstance(shape, Circle):
        ax.add_patch(patches.Circle(shape.centre, shape.radius, zorder=3 if shape.hole else 2,
                                    **_fill(shape, colour, alpha)))
    elif len(shape.vertices) < 3:  # a flat shape seen edge-on
        xs, ys = zip(*shape.vertices)
        ax.plot(xs, ys, color=colour, lw=4, alpha=alpha, zorder=3)
    else:
        ax.add_patch(patches.Polygon(shape.vertices, closed=True, zorder=3 if shape.hole else 2,
                                     **_fill(shape, colour, alpha)))


def _fill(shape: Circle | Polygon, colour: str, alpha: float) -> dict:
    """Solids tinted, thin shapes outlined, holes white with a dashed rim."""
    if shape.hole:
        return {"facecolor": "white", "edgecolor": colour, "ls": "--", "lw": 1.5, "alpha": alpha}
    face = colour if shape.filled else "none"
    return {"facecolor": face, "edgecolor": colour, "lw": 2.5, "alpha": alpha * (0.45 if shape.filled else 1.0)}


def _points(ax, drawing: Sketch) -> None:
    """Each place once, with every name of the points there (O, G₁), offset so it does
    not sit on the dot; a white box keeps a label readable over a body."""
    tolerance = 1e-9 * drawing.size()
    places: list[tuple[tuple[float, float], list[str]]] = []
    for p in drawing.points:
        same = next((names for at, names in places if math.dist(at, p.at) <= tolerance), None)
        if same is None:
            places.append((p.at, [unicode_name(p.name)]))
        else:
            same.append(unicode_name(p.name))
    centre = _centre(drawing)
    for at, names in places:
        ax.plot(*at, "o", color="black", ms=3.5, zorder=6)
        dx, dy = at[0] - centre[0], at[1] - centre[1]
        right = dx >= -1e-9 * drawing.size()  # labels lean away from the scene's middle
        ax.annotate(", ".join(names), at, xytext=(7 if right else -7, 6 if dy >= 0 else -6),
                    textcoords="offset points", ha="left" if right else "right",
                    va="bottom" if dy >= 0 else "top", fontsize=12, zorder=7,
                    bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.75})


def _centre(drawing: Sketch) -> tuple[float, float]:
    x0, y0, x1, y1 = drawing.bounds()
    return (x0 + x1) / 2, (y0 + y1) / 2


@dataclass(frozen=True)
class View:
    """The data limits shared by a figure's panels: every drawing with a margin, and
    room on the right for the gravity arrow (in data coordinates, so its direction is
    true whatever the panel's shape)."""

    x0: float
    y0: float
    x1: float
    y1: float
    gravity: tuple[float, float] | None
    arrow_at: tuple[float, float]
    arrow_length: float

    @staticmethod
    def of(drawings: list[Sketch]) -> View:
        boxes = [d.bounds() for d in drawings]
        x0, y0 = min(b[0] for b in boxes), min(b[1] for b in boxes)
        x1, y1 = max(b[2] for b in boxes), max(b[3] for b in boxes)
        size = max(x1 - x0, y1 - y0) or 1.0
        pad, length = MARGIN * size, ARROW * size
        gravity = drawings[0].gravity
        arrow_at = (x1 + pad, (y0 + y1) / 2)
        if gravity is not None:
            x1 = arrow_at[0] + abs(gravity[0]) * length / 2 + 0.35 * length  # the arrow and its label
        x0, y0, x1, y1 = _within_aspect(x0 - pad, y0 - pad, x1 + pad, y1 + pad)
        return View(x0, y0, x1, y1, gravity, arrow_at, length)

    def figure_size(self, rows: int, cols: int) -> tuple[float, float]:
        """Inches: panels about PANEL wide, as tall as the scene's shape asks (within
        limits), plus room for the titles and the notes."""
        aspect = min(max((self.y1 - self.y0) / (self.x1 - self.x0), 0.45), 1.6)
        return PANEL * cols + 0.6, PANEL * aspect * rows + 0.75 * rows + 0.7

    def apply(self, ax) -> None:
        ax.set_xlim(self.x0, self.x1)
        ax.set_ylim(self.y0, self.y1)
        ax.set_aspect("equal", adjustable="box")
        ax.grid(True, color="0.92", lw=0.6)
        ax.tick_params(labelsize=9, colors="0.4")
        for side in ax.spines.values():
            side.set_color("0.8")
        if self.gravity is not None:
            _gravity_arrow(ax, self.gravity, *self.arrow_at, self.arrow_length)


def _within_aspect(x0: float, y0: float, x1: float, y1: float) -> tuple[float, float, float, float]:
    """Widen the shorter side, about its middle, so height/width stays within ASPECTS: a
    hanging pendulum gets a panel of a readable shape, not a sliver."""
    low, high = ASPECTS
    width, height = x1 - x0, y1 - y0
    if height > high * width:
        grow = (height / high - width) / 2
        return x0 - grow, y0, x1 + grow, y1
    if height < low * width:
        grow = (low * width - height) / 2
        return x0, y0 - grow, x1, y1 + grow
    return x0, y0, x1, y1


def _gravity_arrow(ax, g: tuple[float, float], x: float, y: float, length: float) -> None:
    """An arrow along g centred at (x, y), labelled g."""
    half = length / 2
    start = (x - g[0] * half, y - g[1] * half)
    end = (x + g[0] * half, y + g[1] * half)
    ax.annotate("", end, xytext=start, arrowprops={"arrowstyle": "-|>", "color": "0.3", "lw": 1.6,
                                                   "mutation_scale": 14}, zorder=5)
    ax.annotate("g", (x, y), xytext=(6, 0), textcoords="offset points", fontsize=11, style="italic",
                color="0.3", va="center")


def _legend(ax, drawing: Sketch) -> None:
    from matplotlib.lines import Line2D

    if not drawing.bodies:
        return
    dots = {s.body for s in drawing.shapes if isinstance(s, Dot)}
    handles = [Line2D([], [], color=_colour(drawing, b), label=b.replace("_", " "),
                      **({"marker": "o", "ls": "none", "ms": 9} if b in dots else {"lw": 5}))
               for b in drawing.bodies]
    ax.legend(handles=handles, fontsize=9, loc="best", framealpha=0.85)


def _suptitle(fig, text: str) -> None:
    """Wrapped to the figure's width: a one-panel figure is narrower than a long title."""
    fig.suptitle(textwrap.fill(text, int(fig.get_figwidth() * 8)), fontsize=12)


def _notes(fig, notes: tuple[str, ...]) -> None:
    if notes:
        fig.supxlabel("; ".join(notes), fontsize=9, style="italic", color="0.3")  # constrained layout makes room
