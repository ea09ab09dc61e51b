"""render.py: the README's pictures of a fabrication package, drawn from
Facet's own files by readers that are not Facet's.

    render.py xlsx SCHEDULE.xlsx OUT.png   the panels sheet's first rows, as
                                           openpyxl reads them
    render.py dxf  PATTERNS.dxf  OUT.png   the first sheet of flat patterns
                                           (its frame the first on layer
                                           SHEETS), drawn by ezdxf's renderer

Both draw with matplotlib (Debian: python3-openpyxl, python3-ezdxf,
python3-matplotlib); the output is a PNG, its metadata stripped so that
the same input draws the same bytes."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROWS = 16      # panel rows shown of the schedule, from the first SP one
# The schedule's columns shown, by the start of their header; the workbook
# has more (centroid, normal, corners, fits).
SHOWN = ("id", "surface", "column i", "row j", "type as classed",
         "type as built", "class", "area", "deviation", "SP bending",
         "worst gap", "worst kink", "mould family", "cost")


def cell_text(value):
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:,.3f}" if abs(value) < 1e6 else f"{value:,.0f}"
    return str(value)


def render_xlsx(path, out):
    import openpyxl
    book = openpyxl.load_workbook(path, read_only=True)
    sheet = book["panels"]
    rows = list(sheet.iter_rows(values_only=True))
    names = rows[0]
    keep = [k for k, name in enumerate(names)
            if name and any(name.startswith(s) for s in SHOWN)]
    built = names.index("type as built")
    first = next((r for r in range(1, len(rows)) if rows[r][built] == "SP"),
                 1)
    first = max(1, first - ROWS // 2)
    header = [names[k] for k in keep]
    body = [[cell_text(rows[r][k]) for k in keep]
            for r in range(first, min(first + ROWS, len(rows)))]
    fig = plt.figure(figsize=(15, 0.205 * (len(body) + 1)))
    ax = fig.add_axes([0, 0, 1, 1])
    ax.axis("off")
    table = ax.table(cellText=body, colLabels=header, loc="upper left",
                     cellLoc="right", colLoc="center")
    table.auto_set_font_size(False)
    table.set_fontsize(8)
    table.auto_set_column_width(list(range(len(header))))
    for (r, _), cell in table.get_celld().items():
        if r == 0:
            cell.set_facecolor("#dde3ea")
            cell.set_text_props(weight="bold")
    fig.savefig(out, dpi=110, bbox_inches="tight", pad_inches=0.05,
                metadata={"Software": None})


def first_point(entity):
    if entity.dxftype() == "POLYLINE":
        for vertex in entity.vertices:
            return vertex.dxf.location
        return None
    return entity.dxf.insert


def render_dxf(path, out):
    import logging

    import ezdxf
    from ezdxf.addons.drawing import Frontend, RenderContext
    from ezdxf.addons.drawing.matplotlib import MatplotlibBackend
    # The DXF names no font file; matplotlib's default stands in, and
    # says so once per text.
    logging.getLogger("matplotlib.font_manager").setLevel(logging.ERROR)
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    frame = next(e for e in msp
                 if e.dxftype() == "POLYLINE" and e.dxf.layer == "SHEETS")
    xs = [v.dxf.location[0] for v in frame.vertices]
    ys = [v.dxf.location[1] for v in frame.vertices]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    # The labels of a sheet sit just outside its frame.
    pad = 0.08 * (y1 - y0)

    def on_first_sheet(entity):
        if entity.dxf.layer.startswith("OUTLINE_3D"):
            return False
        p = first_point(entity)
        return (p is not None and x0 <= p[0] <= x1 and
                y0 - pad <= p[1] <= y1 + pad)

    fig = plt.figure(figsize=(12, 12 * (y1 - y0 + 2 * pad) / (x1 - x0)))
    ax = fig.add_axes([0, 0, 1, 1])
    ctx = RenderContext(doc)
    ctx.set_current_layout(msp)
    Frontend(ctx, MatplotlibBackend(ax)).draw_layout(
        msp, finalize=True, filter_func=on_first_sheet)
    ax.set_xlim(x0 - pad, x1 + pad)
    ax.set_ylim(y0 - pad, y1 + pad)
    fig.savefig(out, dpi=110, facecolor="white", bbox_inches="tight",
                pad_inches=0.05, metadata={"Software": None})


def main(argv):
    if len(argv) != 4 or argv[1] not in ("xlsx", "dxf"):
        sys.exit("usage: render.py xlsx|dxf IN OUT.png")
    (render_xlsx if argv[1] == "xlsx" else render_dxf)(argv[2], argv[3])


if __name__ == "__main__":
    main(sys.argv)
