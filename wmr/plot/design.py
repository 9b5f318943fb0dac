r"""Drawing the design study: worst-case :math:`\kappa(\mathbf J)` over the design space, and along the motions.

The numbers come from :func:`wmr.analysis.design.landscape` and
:func:`wmr.analysis.motion_kappa.motion_map`; these functions only draw them.
"""

from __future__ import annotations

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import LogNorm
from matplotlib.path import Path

from .marks import label
from .style import PALETTE, ROLE, new_figure, panel_title, style

__all__ = ["draw_landscape", "draw_motion_maps", "picture_bundle", "show_figure"]

_KAPPA_LEVELS = (1.05, 1.25, 1.5, 2.0, 3.0, 5.0, 10.0)


def _kappa_image(ax, x, y, K, vmax):
    """A log-scaled map of kappa (inf at the top of the scale) and its contours (labelled by :func:`_label_contours`)."""
    shown = np.where(np.isfinite(K), K, vmax)
    im = ax.pcolormesh(x, y, np.clip(shown, 1.0, vmax), norm=LogNorm(1.0, vmax), shading="auto", cmap="cividis")
    levels = [v for v in _KAPPA_LEVELS if np.nanmin(shown) < v < vmax]
    ax.set_aspect("equal")
    return im, (ax.contour(x, y, shown, levels=levels, colors="white", linewidths=0.5) if levels else None)


def _obstacles(ax, r):
    """The lines and markers (small squares) of ``ax`` and its legend's box, in display coordinates."""
    legend = ax.get_legend()
    boxes = [legend.get_window_extent(r)] if legend is not None else []
    paths = []
    for line in ax.get_lines():
        xy = line.get_transform().transform(np.asarray(line.get_xydata(), dtype=float))
        if line.get_linestyle() not in ("None", "none", "", " ") and len(xy) >= 2:
            paths.append(Path(xy))
        if line.get_marker() not in (None, "None", "none", "", " "):
            h = line.get_markersize() * ax.figure.dpi / 144.0  # half the marker's size, in pixels
            paths += [Path(p + [[-h, -h], [h, h]]) for p in xy]
    return paths, boxes


def _label_contours(fig, contours):
    """Label each contour once, where the label covers no line, marker, legend or other label and stays inside its axes.

    The figure is laid out first, so each candidate label's box is where it will be shown; the chosen points are
    labelled by :meth:`~matplotlib.axes.Axes.clabel`, which breaks the contour there.
    """
    canvas = fig.canvas if hasattr(fig.canvas, "get_renderer") else FigureCanvasAgg(fig)
    canvas.draw()
    r = canvas.get_renderer()
    for cs in contours:
        if cs is None:
            continue
        ax, chosen = cs.axes, []
        paths, boxes = _obstacles(ax, r)
        frame = ax.get_window_extent(r)
        for level, segs in zip(cs.levels, cs.allsegs):
            found = None
            for seg in sorted(segs, key=len, reverse=True):
                d = ax.transData.transform(seg)
                for i in range(2, len(seg) - 2, max(1, len(seg) // 12)):
                    dx, dy = d[i + 2] - d[i - 2]
                    angle = float(np.degrees(np.arctan2(dy, dx)))
                    angle = angle - 180 if angle > 90 else angle + 180 if angle < -90 else angle
                    t = ax.text(*seg[i], f"{level:g}", fontsize=6.5, ha="center", va="center", rotation=angle)
                    bb = t.get_window_extent(r)
                    t.remove()
                    inside = frame.contains(bb.x0, bb.y0) and frame.contains(bb.x1, bb.y1)
                    if inside and not any(p.intersects_bbox(bb, filled=False) for p in paths):
                        if not any(bb.overlaps(b) for b in boxes):
                            found = (float(seg[i][0]), float(seg[i][1]))
                            boxes.append(bb)
                            break
                if found:
                    break
            if found:
                chosen.append(found)
        if chosen:
            ax.clabel(cs, fontsize=6.5, fmt="%g", manual=chosen)


def _colorbar(fig, im, ax, label, vmax):
    """A colour bar for a kappa map, with plain tick labels."""
    cb = fig.colorbar(im, ax=ax, label=label, shrink=0.9)
    ticks = [t for t in (1, 1.25, 1.5, 2, 3, 5, 10) if t <= vmax]
    cb.set_ticks(ticks, labels=[f"{t:g}" for t in ticks])
    cb.minorticks_off()
    return cb


def draw_landscape(data, fig=None):
    r"""Two panels: :math:`\bar\kappa` against :math:`d/r`, and over wheel 2's position at :math:`d = r`.

    Parameters
    ----------
    data : wmr.analysis.design.Landscape
    fig : matplotlib.figure.Figure, optional
        Draw into this figure.

    Returns
    -------
    matplotlib.figure.Figure
    """
    with style():
        fig, (a, b) = new_figure(1, 2, width=7.2, height=3.2, fig=fig, drawing=False)
        a.loglog(data.ratios, data.kappa_paper, color=PALETTE["blue"], label="equilateral, C at the centroid")
        a.loglog(
            data.ratios,
            data.kappa_moved,
            color=PALETTE["vermillion"],
            ls="--",
            label=f"wheel 2 moved to ({data.moved[0]:g}, {data.moved[1]:g})",
        )
        a.axvline(1.0, color=PALETTE["grey"], lw=0.6, ls=":")
        a.set_xticks([0.25, 0.5, 1, 2, 4], ["1/4", "1/2", "1", "2", "4"])
        a.set_yticks([1, 1.5, 2, 3, 4], ["1", "1.5", "2", "3", "4"])
        a.minorticks_off()
        a.set_xlabel(r"offset ratio $d/r$")
        a.set_ylabel(r"worst-case $\kappa(\mathbf{J})$")
        a.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), frameon=False)  # below: inside, it covers data
        panel_title(a, "a", r"the offset sets $\kappa(\mathbf{J}_2)$")
        vmax = float(min(np.nanmax(data.kappa_map[np.isfinite(data.kappa_map)]), 10.0))
        im, contours = _kappa_image(b, data.x, data.y, data.kappa_map, vmax)
        m = data.mounts
        b.plot(*np.vstack([m, m[:1]]).T, color=PALETTE["light"], lw=0.8, ls=":")
        b.plot(m[[0, 2], 0], m[[0, 2], 1], "o", color=ROLE["point"], ms=4, mfc="white")
        b.plot(*m[1], "*", color=PALETTE["yellow"], ms=9, mec="black", mew=0.5)
        b.plot(0, 0, "+", color="white", ms=7)
        for k, p in enumerate(m, 1):
            label(b, p, f"$P_{k}$", offset=(5, 4), color="white", fontsize=8, halo=False)
        b.set_xlabel("$x_2$")
        b.set_ylabel("$y_2$")
        _colorbar(fig, im, b, r"worst-case $\kappa(\mathbf{J})$", vmax)
        panel_title(b, "b", r"wheel 2 anywhere, $d = r$")
        _label_contours(fig, [contours])
    return fig


def draw_motion_maps(maps, titles, fig=None):
    r""":math:`\kappa(\mathbf J)` of the rotation about each point, one panel per robot (same colour scale).

    Parameters
    ----------
    maps : sequence of wmr.analysis.motion_kappa.MotionMap
    titles : sequence of str
        One per map.
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    maps, titles = list(maps), list(titles)
    with style():
        fig, axes = new_figure(1, len(maps), width=3.6 * len(maps), height=3.4, fig=fig, drawing=False)
        vmax = 10.0
        contours = []
        for k, (ax, mm, title) in enumerate(zip(axes, maps, titles)):
            im, cs = _kappa_image(ax, mm.x, mm.y, mm.kappa, vmax)
            contours.append(cs)
            ax.plot(*mm.mounts.T, "s", color="white", mec="black", ms=5, mew=0.6)
            ax.plot(0, 0, "+", color="white", ms=7)
            if mm.circle is not None:
                c, R = mm.circle
                t = np.linspace(0, 2 * np.pi, 200)
                ax.plot(
                    c[0] + R * np.cos(t),
                    c[1] + R * np.sin(t),
                    color=PALETTE["vermillion"],
                    lw=1.0,
                    label=r"$\kappa = \infty$",
                )
                ax.legend(loc="lower right", frameon=True, framealpha=0.9)
            ax.plot(*mm.argmin, "*", color=PALETTE["yellow"], ms=9, mec="black", mew=0.5)
            ax.set_xlabel("$U_x$")
            ax.set_ylabel("$U_y$" if k == 0 else "")
            panel_title(ax, "abcdef"[k], title)
        _colorbar(fig, im, axes, r"$\kappa(\mathbf{J})$ of the rotation about $U$", vmax)
        _label_contours(fig, contours)
    return fig


def picture_bundle(data, alt, width=None):
    """The MIME bundle that shows a PNG with alt text (JupyterLab's PNG renderer drops it; ``text/html`` keeps it).

    Parameters
    ----------
    data : bytes
        A PNG.
    alt : str
        What the picture shows, in plain words (no Markdown or LaTeX); not empty.
    width : int, optional
        Display width in pixels (the picture shrinks to fit a narrower notebook).

    Returns
    -------
    dict
        ``text/html`` (an ``<img alt=...>``), ``image/png`` and ``text/plain`` (the alt text), for
        ``IPython.display.display(bundle, raw=True)``.

    Examples
    --------
    >>> sorted(picture_bundle(b"png bytes", "a robot seen from above"))
    ['image/png', 'text/html', 'text/plain']
    """
    import base64
    import html

    from ..errors import InputValueError

    if not isinstance(alt, str) or not alt.strip():
        raise InputValueError(f"alt must be a non-empty description of the picture, got {alt!r}")
    b64 = base64.b64encode(data).decode("ascii")
    size = f' width="{int(width)}"' if width else ""
    tag = f'<img src="data:image/png;base64,{b64}" alt="{html.escape(alt.strip())}"{size} style="max-width:100%">'
    return {"text/html": tag, "image/png": b64, "text/plain": alt.strip()}


def show_figure(fig, caption, width=None, dpi=150, colours=None, alt=None):
    """Display a figure in a notebook as a PNG, with its caption (Markdown) below.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    caption : str
    width : int, optional
        Display width in pixels (default 110 per inch of the figure).
    dpi : int, optional
    colours : int, optional
        Reduce the PNG to a palette of this many colours (a third of the bytes for line charts).
    alt : str, optional
        What the figure shows, in words (:func:`picture_bundle`).

    Returns
    -------
    None
    """
    import io

    from IPython.display import Image, Markdown, display

    buf = io.BytesIO()
    with style():
        fig.savefig(buf, format="png", dpi=dpi)
    png = buf.getvalue()
    if colours:
        from PIL import Image as Picture

        small = io.BytesIO()
        picture = Picture.open(io.BytesIO(png)).convert("RGB").quantize(colors=int(colours))
        picture.save(small, format="PNG", optimize=True)
        png = small.getvalue()
    shown = width or round(fig.get_figwidth() * 110)
    if alt is None:
        display(Image(png, width=shown), Markdown(caption))
    else:
        display(picture_bundle(png, alt, shown), raw=True, metadata={"image/png": {"width": shown}})
        display(Markdown(caption))
