#!/usr/bin/python3
"""Checks scripts/plot_figure.py: reverse segments found from the poses' headings, scale-bar
lengths, the unknown cells' legend entry only where the picture has some, and a figure with a
forward and a reverse piece, a vehicle, markers and a free goal heading drawn to a PNG. Usage: plot_figure_test.py SOURCE_DIR WORK_DIR"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(sys.argv[1], "scripts"))
import plot_figure  # noqa: E402


def main():
    work = sys.argv[2]
    os.makedirs(work, exist_ok=True)
    # forwards along +x, then backwards (heading still +x, motion -x): a three-point turn's piece
    fwd = [(x * 0.5, 0.0, 0.0) for x in range(10)]
    back = [(4.5 - x * 0.5, 0.1 * x, 0.0) for x in range(1, 6)]
    rev = plot_figure.reversed_steps(fwd + back)
    assert rev == [False] * 9 + [True] * 5, rev
    assert plot_figure.reversed_steps([(0, 0, math.pi), (-1, 0, math.pi)]) == [False]
    for span, bar in ((73, 10), (100, 20), (4.9, 0.5), (1000, 200), (260, 50)):
        assert abs(plot_figure.nice_length(span) - bar) < 1e-9, (span, plot_figure.nice_length(span))
    import matplotlib.pyplot as plt
    import numpy as np
    # the legend names unknown cells only where the picture has some (grey 190)
    grey = np.full((2, 2, 3), 255, np.uint8)
    assert not plot_figure.has_unknown_cells(grey)
    grey[1, 0] = 190
    assert plot_figure.has_unknown_cells(grey)
    assert plot_figure.has_unknown_cells(grey.astype(np.float32) / 255.0)
    assert not plot_figure.has_unknown_cells(np.full((2, 2, 4), 0.5, np.float32))
    img = os.path.join(work, "map.png")
    plt.imsave(img, [[1.0, 1.0], [1.0, 0.0]], cmap="gray")
    spec = {"title": "test", "image": img, "extent": [-2, 8, -3, 3],
            "vehicle": {"length": 1.0, "width": 0.5, "rear_overhang": 0.2},
            "start": [0, 0, 0], "goal": [2, 0.5, None],
            "paths": [{"label": "path", "colour": "tab:blue", "points": [list(p) for p in fwd + back], "outline": True}],
            "markers": [{"label": "obstacle", "colour": "tab:orange", "points": [[1, 1]]}],
            "tint": {"label": "explored", "colour": "#aac8ff"}}
    with open(os.path.join(work, "fig.json"), "w") as f:
        json.dump(spec, f)
    out = os.path.join(work, "fig.png")
    sys.argv = ["plot_figure.py", os.path.join(work, "fig.json"), out]
    plot_figure.main()
    with open(out, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    print("plot_figure: reverse segments, scale bars and a figure OK")


if __name__ == "__main__":
    main()
