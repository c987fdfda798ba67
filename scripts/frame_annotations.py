"""What scripts/render_frames.py draws around the scene (VTK's Python bindings, python3-vtk9):
the colour bar with its title, units, ticks and the data's largest value, the picture's title,
the time stamp, and the axes in metres. Everything here is placed in pixels from the picture's
size, in its own strips beside the scene, so that no text can overlap another or the scene.

The colour range ends at a round number at or above the data's largest value: the next of
1, 1.2, 1.5, 1.8, 2, 2.5, 3, 3.5, 4, 5, 6, 7, 8, 10 times a power of ten, so the bar's top is
at most 25 % above the largest value (1.25 = 2.5/2 = 5/4 = 10/8, the widest steps of that list)
and every tick is a round number.
"""

import math

import numpy as np

from vtkmodules.vtkCommonCore import vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor2D, vtkPolyDataMapper2D, vtkTextActor

# Round tops of a colour range, as multiples of a power of ten, each with its tick step.
ROUND_TOPS = ((1.0, 0.2), (1.2, 0.2), (1.5, 0.3), (1.8, 0.3), (2.0, 0.5), (2.5, 0.5), (3.0, 0.5),
              (3.5, 0.5), (4.0, 1.0), (5.0, 1.0), (6.0, 1.0), (7.0, 1.0), (8.0, 2.0), (10.0, 2.0))
ABOVE_RANGE = (0.55, 0.0, 0.55)  # data above a range given by hand: dark magenta
CHAR = 0.6  # the width of a character of Arial against the font size, at most (digits: 0.556)


def round_top(largest):
    """The colour range's top for data up to `largest` > 0, and its tick step."""
    if not largest > 0.0:
        return 1.0, 0.2
    power = 10.0 ** math.floor(math.log10(largest))
    for top, step in ROUND_TOPS:
        if largest <= top * power * (1.0 + 1e-12):
            return top * power, step * power
    return 10.0 * power, 2.0 * power


def ticks(low, high, step=None):
    """Round ticks from low to high: `step` if given, else 4 to 7 intervals of a round step."""
    span = high - low
    if step is None:
        power = 10.0 ** math.floor(math.log10(span / 4.0)) if span > 0 else 1.0
        step = next((m * power for m in (1.0, 2.0, 2.5, 5.0, 10.0) if span / (m * power) <= 7.0),
                    10.0 * power)
    count = int(math.floor(span / step + 1e-9))
    return [low + k * step for k in range(count + 1)], step


def tick_label(value, step):
    """A tick's text with as many decimals as the step needs (0.25 needs 2, 50 none)."""
    if value == 0.0:
        return "0"
    if abs(value) >= 1e5 or abs(value) < 1e-3:
        return f"{value:.3g}"
    decimals = 0
    while decimals < 6 and abs(step * 10**decimals - round(step * 10**decimals)) > 1e-6:
        decimals += 1
    return f"{value:.{decimals}f}"


def text(message, size, x, y, bold=False, align="left", valign="bottom"):
    """A text actor at pixel (x, y) of the window, black, upright, Arial."""
    actor = vtkTextActor()
    actor.SetInput(message)
    style = actor.GetTextProperty()
    style.SetFontFamilyToArial()
    style.SetFontSize(int(size))
    style.SetColor(0.0, 0.0, 0.0)
    style.SetBold(bold)
    style.ItalicOff()
    style.ShadowOff()
    style.SetLineSpacing(1.1)
    {"left": style.SetJustificationToLeft, "right": style.SetJustificationToRight,
     "centre": style.SetJustificationToCentered}[align]()
    {"bottom": style.SetVerticalJustificationToBottom, "top": style.SetVerticalJustificationToTop,
     "centre": style.SetVerticalJustificationToCentered}[valign]()
    actor.SetPosition(x, y)
    return actor


def polygons_2d(corners, colours):
    """A 2D actor in window pixels: with colours (RGB in 0..1, one each), filled polygons of the
    corner lists; without (None), black polylines through them."""
    points, cells = vtkPoints(), vtkCellArray()
    rgb = vtkUnsignedCharArray()
    rgb.SetNumberOfComponents(3)
    for k, polygon in enumerate(corners):
        ids = [points.InsertNextPoint(x, y, 0.0) for x, y in polygon]
        cells.InsertNextCell(len(ids), ids)
        if colours is not None:
            rgb.InsertNextTuple3(*[round(255 * c) for c in colours[k]])
    poly = vtkPolyData()
    poly.SetPoints(points)
    if colours is None:
        poly.SetLines(cells)
    else:
        poly.SetPolys(cells)
        poly.GetCellData().SetScalars(rgb)
    mapper = vtkPolyDataMapper2D()
    mapper.SetInputData(poly)
    actor = vtkActor2D()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.0, 0.0, 0.0)
    actor.GetProperty().SetLineWidth(1.0)
    return actor


class Layout:
    """Pixel strips of a picture W x H: the title and the time stamp on top, the colour bar on
    the right, as wide as its longest text (`bar_text`, its lines); the scene
    gets the rest (its viewport, in 0..1)."""

    def __init__(self, width, height, bar_text):
        self.width, self.height = width, height
        # Text readable where the picture is shown at its own size or down to half of it.
        self.font = max(13, min(26, round(0.032 * min(width, height))))
        self.small = round(0.9 * self.font)
        self.margin = round(0.6 * self.font)
        self.top_strip = round(2.4 * self.font + 2 * self.margin)
        self.bottom_strip = self.margin
        self.bar_width = max(12, round(1.1 * self.font))
        widest = max(len(line) for line in bar_text)
        self.bar_column = round(max(self.bar_width + 0.45 * self.font + 6 * CHAR * self.small,
                                    widest * CHAR * self.small) + 2 * self.margin)

    def scene_viewport(self):
        return (0.0, self.bottom_strip / self.height,
                1.0 - self.bar_column / self.width, 1.0 - self.top_strip / self.height)


def title_actors(layout, title, stamp):
    """The title at the top left and the time stamp under it, in the top strip."""
    top = layout.height - layout.margin
    return [text(title, layout.font, layout.margin, top, bold=True, valign="top"),
            text(stamp, layout.font, layout.margin, top - round(1.25 * layout.font), valign="top")]


def bar_caption(caption, largest, step):
    """The colour bar's caption lines: the quantity, its unit and the data's largest value."""
    return caption.split("\n") + [f"largest {largest:.3g}"]


def colour_bar(layout, lookup, low, high, step, caption, above):
    """The colour bar in its column: `caption` (bar_caption's lines) above it, round ticks
    beside it, and a swatch in the above-range colour when the data go past `high` (a range
    given by hand)."""
    f, m = layout.font, layout.margin
    x0 = layout.width - layout.bar_column + m
    x1 = x0 + layout.bar_width
    y_top = layout.height - layout.top_strip - round(1.25 * len(caption) * layout.small) - m
    # A bar of at most 60 % of the picture's height, hanging under its caption.
    y_bottom = max(layout.bottom_strip + round(0.5 * f), y_top - round(0.6 * layout.height))
    swatch = layout.small if above else 0
    y_high = y_top - swatch - (round(0.3 * f) if above else 0)
    segments = 96
    quads, colours = [], []
    for k in range(segments):
        ya = y_bottom + (y_high - y_bottom) * k / segments
        yb = y_bottom + (y_high - y_bottom) * (k + 1) / segments
        quads.append([(x0, ya), (x1, ya), (x1, yb), (x0, yb)])
        value = low + (high - low) * (k + 0.5) / segments
        colour = [0.0, 0.0, 0.0]
        lookup.GetColor(value, colour)
        colours.append(colour)
    outline = [(x0, y_bottom), (x1, y_bottom), (x1, y_high), (x0, y_high), (x0, y_bottom)]
    actors = [polygons_2d(quads, colours), polygons_2d([outline], None)]
    values, _ = ticks(low, high, step)
    for value in values:
        y = y_bottom + (y_high - y_bottom) * (value - low) / (high - low)
        actors.append(polygons_2d([[(x1, y), (x1 + round(0.3 * f), y)]], None))
        actors.append(text(tick_label(value, step), layout.small, x1 + round(0.45 * f), y,
                           valign="centre"))
    if above:
        quad = [(x0, y_top - swatch), (x1, y_top - swatch), (x1, y_top), (x0, y_top)]
        actors.append(polygons_2d([quad], [ABOVE_RANGE]))
        actors.append(polygons_2d([quad + quad[:1]], None))
        actors.append(text("above", layout.small, x1 + round(0.45 * f), y_top - swatch / 2,
                           valign="centre"))
    actors.append(text("\n".join(caption), layout.small, x0,
                       layout.height - layout.top_strip - m, valign="top"))
    return actors


def text_box(label, size, x, y, align, valign):
    """The pixel box (x0, y0, x1, y1) a text of that size anchored at (x, y) covers, at most."""
    lines = label.split("\n")
    width = max(len(line) for line in lines) * CHAR * size
    height = len(lines) * 1.2 * size
    x0 = {"left": x, "right": x - width, "centre": x - width / 2}[align]
    y0 = {"bottom": y, "top": y - height, "centre": y - height / 2}[valign]
    return (x0, y0, x0 + width, y0 + height)


def overlaps(box, boxes):
    return any(box[0] < b[2] and b[0] < box[2] and box[1] < b[3] and b[1] < box[3]
               for b in boxes)


def peak_marker(scene, point, label, layout, taken):
    """A ring round the place of the largest value (drawn over the scene, even where the
    shell hides it) and its value beside it, on the first side where it covers no label
    already placed (`taken`, pixel boxes)."""
    x, y = display_point(scene, point)
    r = 0.55 * layout.font
    ring = [(x + r * math.cos(a), y + r * math.sin(a))
            for a in np.linspace(0.0, 2.0 * math.pi, 25)]
    sides = [(1.2 * r, 0.8 * r, "left", "bottom"), (-1.2 * r, 0.8 * r, "right", "bottom"),
             (1.2 * r, -0.8 * r, "left", "top"), (-1.2 * r, -0.8 * r, "right", "top")]
    for dx, dy, align, valign in sides:
        box = text_box(label, layout.small, x + dx, y + dy, align, valign)
        if not overlaps(box, taken):
            break
    taken.append(box)
    note = text(label, layout.small, x + dx, y + dy, align=align, valign=valign)
    note.GetTextProperty().SetBackgroundColor(1.0, 1.0, 1.0)
    note.GetTextProperty().SetBackgroundOpacity(0.85)
    return [polygons_2d([ring], None), note]


def axis_edge(scene, bounds, axis, up):
    """The box edge along `axis` to label, in window pixels (two points): for a horizontal
    axis the edge lowest on the screen, for the vertical one the edge farthest left."""
    other = [k for k in range(3) if k != axis]
    best = None
    for a in (0, 1):
        for b in (0, 1):
            ends = []
            for end in (0, 1):
                point = [0.0, 0.0, 0.0]
                point[axis] = bounds[2 * axis + end]
                point[other[0]] = bounds[2 * other[0] + a]
                point[other[1]] = bounds[2 * other[1] + b]
                ends.append(display_point(scene, point))
            middle = [(ends[0][i] + ends[1][i]) / 2 for i in (0, 1)]
            key = middle[0] if axis == up else middle[1]
            if best is None or key < best[0]:
                best = (key, ends)
    return best[1]


def display_point(scene, point):
    scene.SetWorldPoint(point[0], point[1], point[2], 1.0)
    scene.WorldToDisplay()
    x, y, _ = scene.GetDisplayPoint()
    return x, y


def metre_axes(scene, bounds, layout, up, taken):
    """Axes in metres along three edges of the scene's bounding box, drawn over the scene
    (the camera must be placed): the edge, round ticks at least four characters apart, their
    values and the axis name with its unit, each label set off outwards from the box. A label
    that would cover one already placed (`taken`, pixel boxes, which the labels join) is left
    out: where two axes meet at a corner, the first one's value stays."""
    f = layout.font
    centre = display_point(scene, [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)])
    actors = []
    for axis in range(3):
        low, high = bounds[2 * axis], bounds[2 * axis + 1]
        (xa, ya), (xb, yb) = axis_edge(scene, bounds, axis, "xyz".index(up))
        length = math.hypot(xb - xa, yb - ya)
        if high - low <= 0.0 or length < 2 * f:
            continue
        # Outwards: perpendicular to the edge on screen, away from the box's centre.
        nx, ny = -(yb - ya) / length, (xb - xa) / length
        if nx * ((xa + xb) / 2 - centre[0]) + ny * ((ya + yb) / 2 - centre[1]) < 0:
            nx, ny = -nx, -ny
        actors.append(polygons_2d([[(xa, ya), (xb, yb)]], None))
        # Labels of up to four characters, a gap of about as much between them.
        values = metre_ticks(low, high, max(2, min(6, int(length / (4.0 * f)) + 1)))
        align = "left" if nx > 0.5 else "right" if nx < -0.5 else "centre"
        valign = "bottom" if ny > 0.5 else "top" if ny < -0.5 else "centre"
        for value, label in values:
            s = (value - low) / (high - low)
            x, y = xa + s * (xb - xa), ya + s * (yb - ya)
            actors.append(polygons_2d([[(x, y), (x + 0.35 * f * nx, y + 0.35 * f * ny)]], None))
            actors += placed(label, round(0.8 * f), x + 0.55 * f * nx, y + 0.55 * f * ny,
                             align, valign, taken)
        actors += placed(f"{'xyz'[axis]} (m)", round(0.85 * f), (xa + xb) / 2 + 2.2 * f * nx,
                         (ya + yb) / 2 + 2.2 * f * ny, align, valign, taken)
    return actors


def placed(label, size, x, y, align, valign, taken):
    """The label as a text actor, or nothing where it would cover a label in `taken`."""
    box = text_box(label, size, x, y, align, valign)
    if overlaps(box, taken):
        return []
    taken.append(box)
    return [text(label, size, x, y, align=align, valign=valign)]


def metre_ticks(low, high, most):
    """Round values inside [low, high], at most `most` of them and at least two, with their
    labels: the finest round step (1, 2, 2.5, 5 times a power of ten) that gives no more
    than `most`; the two ends where no round step puts two values inside."""
    span = high - low
    power = 10.0 ** math.floor(math.log10(span)) / 100.0
    for step in (m * power * 10**k for k in range(5) for m in (1.0, 2.0, 2.5, 5.0)):
        first = math.ceil(low / step - 1e-9) * step
        count = int(math.floor((high - first) / step + 1e-9)) + 1
        values = [first + k * step for k in range(count)]
        if len(values) <= most:
            break
    if len(values) < 2:
        return [(v, f"{v:.2g}") for v in (low, high)]
    return [(v, tick_label(0.0 if abs(v) < 1e-9 * step else v, step)) for v in values]
