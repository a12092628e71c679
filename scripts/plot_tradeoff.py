#!/usr/bin/python3
"""Plot of gloss-cli tradeoff's CSV: error (RMSE against the reference, log scale) against the
median render time, one marker style per knob, every point labelled with its setting, and the
Pareto front (no other point is both faster and more accurate) drawn as a step line.

Several CSVs are drawn together: the raster path's rows (`quality raster PATH` in an editor
script, editor/gl/raster/raster_tradeoff.h) measure against the same reference as the CPU rows
and are drawn as hollow markers of their own, with the cpu 1-spp row they carry.

Usage: plot_tradeoff.py CSV [CSV ...] OUT.png [--title TEXT] [--base spp=4,pow=exact,...]
Run with Debian's /usr/bin/python3 (python3-matplotlib). Writes OUT.png as given (gloss-cli
passes a temporary name and renames it into place).
"""
import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")  # no display; must precede pyplot
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import ticker  # noqa: E402

KNOB_STYLE = {  # marker, colour (colour-blind-safe Okabe-Ito palette)
    "spp": ("o", "#0072B2"),
    "adaptive": ("h", "#A08600"),  # the palette's yellow, darkened to read on white
    "tessellation": ("s", "#E69F00"),
    "pow": ("^", "#009E73"),
    "precision": ("D", "#CC79A7"),
    "shading": ("v", "#D55E00"),
    "resolution": ("P", "#56B4E9"),
    "shadows": ("X", "#000000"),
    # Texture maps: how they are filtered, and at what fraction of their size.
    "map_filter": ("H", "#882255"),
    "map_resolution": ("p", "#44AA99"),
    # The raster (GLSL) path's rows: hollow markers, colours outside the palette above.
    "cpu": ("p", "#444444"),
    "raster-shading": ("<", "#7B3294"),
    "raster-shadow-map": (">", "#1B7837"),
    "raster-bias": ("d", "#B2182B"),
    "raster-tessellation": ("8", "#8C510A"),
}
RASTER_LABEL = {"raster-shading": "gl", "raster-shadow-map": "gl map", "raster-bias": "gl bias",
                "raster-tessellation": "gl tess"}


def read_rows(paths):
    rows = []
    for path in paths:
        with open(path, newline="") as f:
            rows += list(csv.DictReader(f))
    for r in rows:
        r["time_ms"] = float(r["time_ms"])
        r["rmse"] = float(r["rmse"])
    return rows


def pareto_front(points):
    """Points (time, error) that no other point beats on both, sorted by time. A slower point
    joins only if its error is at least 1 % below the front's so far: smaller differences (float
    against double, fast pow) are far below what the 256-spp reference resolves."""
    front = []
    for p in sorted(points, key=lambda p: (p[0], p[1])):
        if not front or p[1] < 0.99 * front[-1][1]:
            front.append(p)
    return front


def label_text(knob, setting):
    """Settings that do not name their knob get it in front ("pow fast", "tess 8")."""
    if knob in ("spp", "resolution"):
        return setting
    if knob in RASTER_LABEL:
        return RASTER_LABEL[knob] + " " + setting
    short = {"tessellation": "tess", "map_filter": "filter", "map_resolution": "maps"}
    return short.get(knob, knob) + " " + setting


def place_labels(fig, ax, labels):
    """Labels each point beside it; labels that overlap are pushed up, one above the other, and
    a label moved away from its point is joined to it by a thin line."""
    texts = [ax.annotate(text, (x, y), textcoords="offset points", xytext=(5, 4), fontsize=7,
                         color=colour) for x, y, text, colour in labels]
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    points_per_pixel = 72.0 / fig.dpi
    for _ in range(200):
        moved = False
        boxes = [t.get_window_extent(renderer) for t in texts]
        for i in range(len(texts)):
            for j in range(len(texts)):
                if i == j or not boxes[i].overlaps(boxes[j]) or boxes[i].y0 < boxes[j].y0:
                    continue
                if boxes[i].y0 == boxes[j].y0 and i < j:
                    continue
                # i sits on or above j: lift i clear of j.
                lift = (boxes[j].y1 - boxes[i].y0 + 1.0) * points_per_pixel
                ox, oy = texts[i].xyann
                texts[i].xyann = (ox, oy + lift)
                boxes[i] = texts[i].get_window_extent(renderer)
                moved = True
        if not moved:
            break
    for t, (x, y, text, colour) in zip(texts, labels):
        ox, oy = t.xyann
        if oy > 10:
            t.remove()
            ax.annotate(text, (x, y), textcoords="offset points", xytext=(ox, oy), fontsize=7,
                        color=colour, arrowprops=dict(arrowstyle="-", color=colour, lw=0.5,
                                                      alpha=0.7, shrinkA=0, shrinkB=3))


def draw_raster_knob(ax, knob, knob_rows, marker, colour, floor, raster_base, drawn, labels,
                     points):
    """One raster knob: hollow markers; ordered settings joined (shadow map sizes; tessellation
    levels per shading frequency); the raster base drawn once."""
    series = {}
    for r in knob_rows:
        if knob == "raster-tessellation":
            series.setdefault(r["setting"].split(" ")[0], []).append(r)
        elif knob == "raster-shadow-map" and r["setting"] != "off":
            series.setdefault("maps", []).append(r)
    for s in series.values():
        ax.plot([r["time_ms"] for r in s], [max(r["rmse"], floor) for r in s], color=colour,
                linewidth=0.8, alpha=0.5, zorder=2,
                linestyle="--" if s[0]["setting"].startswith("vertex") else "-")
    own = []
    for r in knob_rows:
        key = (r["time_ms"], r["rmse"])
        if key in raster_base:
            if key in drawn:
                continue
            drawn.add(key)
            text = raster_base[key]
        else:
            text = label_text(knob, r["setting"])
        own.append((r["time_ms"], max(r["rmse"], floor), text))
    ax.scatter([x for x, _, _ in own], [y for _, y, _ in own], marker=marker, s=52,
               facecolors="white", edgecolors=colour, linewidths=1.4, label=knob, zorder=3)
    for x, y, text in own:
        labels.append((x, y, text, colour))
        points.append((x, y))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("csv", nargs="+")
    parser.add_argument("out")
    parser.add_argument("--title", default="gloss tradeoff")
    parser.add_argument("--base", default="",
                        help="the base rows as knob=setting,... (drawn once, as a star)")
    args = parser.parse_args()
    rows = read_rows(args.csv)
    if not rows:
        sys.exit("no rows in " + args.csv)

    # An exact match (rmse 0) cannot sit on a log axis: it is drawn at a floor below the smallest
    # non-zero error and labelled "= ref".
    nonzero = [r["rmse"] for r in rows if r["rmse"] > 0]
    floor = (min(nonzero) / 4) if nonzero else 1e-6

    # The rows of every knob at its base setting render the same image (the same error); their
    # times differ only by when they were taken. They are drawn once, as a star at their median
    # time.
    base_names = set(args.base.split(",")) if args.base else set()
    base_rows = [r for r in rows if r["knob"] + "=" + r["setting"] in base_names]
    base_point = None
    if base_rows:
        times = sorted(r["time_ms"] for r in base_rows)
        base_point = (times[len(times) // 2], max(base_rows[0]["rmse"], floor))

    fig, ax = plt.subplots(figsize=(10, 6), dpi=100)
    points = []
    labels = []  # (x, y, text, colour), placed once every point is known
    # Raster rows of one measured configuration (the raster base: per pixel, the default map and
    # bias, the finest teapot; per vertex at the finest teapot) have the same time and error:
    # each is drawn once, the base (named by three knobs or more) as "gl base".
    groups = {}
    for r in rows:
        if r["knob"].startswith("raster-"):
            groups.setdefault((r["time_ms"], r["rmse"]), []).append(r)
    raster_base = {key: ("gl base" if len({r["knob"] for r in g}) >= 3 else
                         label_text(g[0]["knob"], g[0]["setting"]))
                   for key, g in groups.items() if len(g) > 1}
    drawn = set()
    for knob, (marker, colour) in KNOB_STYLE.items():
        knob_rows = [r for r in rows if r["knob"] == knob]
        if not knob_rows:
            continue
        if knob.startswith("raster-"):
            draw_raster_knob(ax, knob, knob_rows, marker, colour, floor, raster_base, drawn,
                             labels, points)
            continue
        xs = [r["time_ms"] for r in knob_rows]
        ys = [max(r["rmse"], floor) for r in knob_rows]
        own = [(r, x, y) for r, x, y in zip(knob_rows, xs, ys) if r not in base_rows]
        ordered = ("spp", "tessellation", "resolution", "map_resolution")
        if knob in ordered and base_point is not None:
            # The joining line passes through the star, not through this knob's own base timing.
            xs = [base_point[0] if r in base_rows else x for r, x in zip(knob_rows, xs)]
        if knob in ordered:  # ordered settings: join them
            ax.plot(xs, ys, color=colour, linewidth=0.8, alpha=0.5, zorder=2)
        ax.scatter([x for _, x, _ in own], [y for _, _, y in own], marker=marker, color=colour,
                   s=46, label=knob, zorder=3, edgecolors="white", linewidths=0.6)
        for r, x, y in own:
            labels.append((x, y, label_text(knob, r["setting"]) +
                           (" = ref" if r["rmse"] == 0 else ""), colour))
            points.append((x, y))
    if base_point is not None:
        bx, by = base_point
        parts = [r["knob"] + " " + r["setting"] for r in base_rows]
        lines = [", ".join(parts[i:i + 3]) for i in range(0, len(parts), 3)]
        # Under the knobs' markers, which can sit on it when a knob changes little.
        ax.scatter([bx], [by], marker="*", s=200, color="#444444", alpha=0.8, zorder=2.5,
                   label="base:\n" + ",\n".join(lines))
        ax.annotate("base", (bx, by), textcoords="offset points", xytext=(7, -11), fontsize=8,
                    color="#444444")
        points.append((bx, by))


    front = pareto_front(points)
    fx = [p[0] for p in front]
    fy = [p[1] for p in front]
    ax.step(fx, fy, where="post", color="#777777", linewidth=1.4, linestyle="--", zorder=1,
            label="Pareto front")
    ax.scatter(fx, fy, s=150, facecolors="none", edgecolors="#777777", linewidths=1.2, zorder=4)

    ax.set_xscale("log")
    ax.set_yscale("log")
    # Plain milliseconds at 1-2-5 steps read better than powers of ten on a short time range.
    ax.xaxis.set_major_locator(ticker.LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    ax.xaxis.set_major_formatter(ticker.FuncFormatter(lambda v, _: "%g" % v))
    ax.xaxis.set_minor_formatter(ticker.NullFormatter())
    if any(r["knob"].startswith("raster-") for r in rows):
        ax.set_xlabel("median time of one render (ms, log scale; CPU: BVH build included, "
                      "raster: one frame)")
    else:
        ax.set_xlabel("median time of one render, BVH build included (ms, log scale)")
    ax.set_ylabel("RMSE of the total image against the reference (log scale)")
    ax.set_title(args.title, fontsize=10)
    ax.text(0.01, 0.01, "better: down and to the left", transform=ax.transAxes, fontsize=8,
            color="#555555", ha="left", va="bottom")
    ax.grid(True, which="major", alpha=0.35)
    ax.grid(True, which="minor", alpha=0.12)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    lo_y = min(fy) / 2
    hi_y = max(p[1] for p in points) * 2
    if math.isfinite(lo_y) and math.isfinite(hi_y) and lo_y > 0:
        ax.set_ylim(lo_y, hi_y)
    fig.tight_layout()
    place_labels(fig, ax, labels)  # after the layout: it measures the labels on the canvas
    fig.savefig(args.out, format="png")


if __name__ == "__main__":
    main()
